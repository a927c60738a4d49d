// Open boundaries: inlets, outlets, domain exits, clamps.
#include "grit/modules/open_boundaries.hpp"

#include <fmt/format.h>

#include <cmath>

#include "grit/core/error.hpp"
#include "grit/parallel/parallel.hpp"
#include "grit/sim/geometry.hpp"

namespace grit::modules {

template <int Dim>
OpenBoundariesModule<Dim>::OpenBoundariesModule(sim::State<Dim>& state, const sim::RunSetup<Dim>& setup)
    : state_(state), setup_(setup) {
    for (const auto& in : setup.spec.inlets) {
        const auto& m = setup.spec.materials[static_cast<std::size_t>(in.material)];
        inlets_.emplace_back(in, static_cast<std::int32_t>(inlets_.size()), setup.spacing, m.reference_density(),
                             m.reference_density() * std::pow(setup.spacing, Dim));
    }
}

template <int Dim>
void OpenBoundariesModule<Dim>::initialise() {
    const auto& spec = setup_.spec;
    if (spec.clamps.empty()) return;
    auto& ps = state_.particles;
    if (!ps.fields().has("fixed"))
        throw core::InputError(fmt::format("{}: a clamp holds solid particles, and the case has no solid",
                                           spec.clamps.front().key));
    auto& fixed = ps.fields().template get<std::int32_t>("fixed");
    const auto* x = ps.position();
    for (Index i = 0; i < ps.size(); ++i) {
        if (ps.phase()[i] != static_cast<std::int32_t>(Phase::solid)) continue;
        for (const auto& c : spec.clamps)
            if (sim::inside<Dim>(x[i], c.min, c.max)) {
                fixed[i] = 1;
                ps.velocity()[i] = core::to_vec<Dim>(c.velocity);
                ps.velocity_half()[i] = core::to_vec<Dim>(c.velocity);
            }
    }
    for (const auto& c : spec.clamps) {
        bool any = false;
        for (Index i = 0; i < ps.size() && !any; ++i)
            any = fixed[i] && ps.phase()[i] == static_cast<std::int32_t>(Phase::solid) && sim::inside<Dim>(x[i], c.min, c.max);
        if (!any) throw core::InputError(fmt::format("{}: the clamp box holds no solid particle", c.key));
    }
}

template <int Dim>
void OpenBoundariesModule<Dim>::install(sim::Pipeline& pipeline) {
    pipeline.add(sim::Hook::boundaries, "boundaries", [this] { apply(); });
}

template <int Dim>
void OpenBoundariesModule<Dim>::apply() {
    // Outlets and (with domain.on_exit = "remove") the domain's faces remove fluid and loose solid
    // particles (debris). Fluid mass is booked as mass out, solid mass as eroded mass.
    const auto& spec = setup_.spec;
    auto& ps = state_.particles;
    if (!spec.outlets.empty() || spec.remove_leaving) {
        const auto* x = ps.position();
        const double* m = ps.mass();
        const std::int32_t* ph = ps.phase();
        const std::int32_t* fixed = ps.fields().has("fixed") ? ps.fields().template get<std::int32_t>("fixed").data() : nullptr;
        const auto fluid = static_cast<std::int32_t>(Phase::fluid), solid = static_cast<std::int32_t>(Phase::solid);
        const Index n = ps.size();
        std::vector<std::uint8_t> gone(static_cast<std::size_t>(n), 0);
        parallel::for_each(n, [&](Index i) {
            if (ph[i] != fluid && (ph[i] != solid || (fixed && fixed[i]))) return;
            if (ps.is_image(i)) return;  // goes with its source (modules/symmetry_plane)
            bool out = spec.remove_leaving && !sim::inside<Dim>(x[i], spec.domain_min, spec.domain_max);
            for (const auto& o : spec.outlets) out = out || sim::inside<Dim>(x[i], o.min, o.max);
            gone[static_cast<std::size_t>(i)] = out;
        });
        const Index removed = parallel::sum(n, Index{0}, [&](Index i) { return Index{gone[static_cast<std::size_t>(i)]}; });
        if (removed > 0) {
            std::vector<Index> keep;
            keep.reserve(static_cast<std::size_t>(n - removed));
            for (Index i = 0; i < n; ++i) {
                if (!gone[static_cast<std::size_t>(i)]) {
                    keep.push_back(i);
                } else if (ph[i] == solid) {  // torn off before it failed: eroded all the same
                    state_.ledger.eroded += m[i];
                    const auto& material = spec.materials[static_cast<std::size_t>(ps.material()[i])];
                    analysis::ErosionRecord r =
                        analysis::erosion_record(ps, i, state_.clock.time, material.reference_density());
                    r.cause = "outlet";
                    state_.erosion.add(r);
                } else {
                    state_.ledger.out += m[i];
                }
            }
            ps.remove(keep);
        }
    }
    for (auto& inlet : inlets_) state_.ledger.in += inlet.emit(ps, state_.clock.time, state_.clock.dt);
}

template <int Dim>
void OpenBoundariesModule<Dim>::save(io::Hdf5Group& group) const {
    std::vector<double> travelled;
    std::vector<std::int64_t> layers;
    for (const auto& in : inlets_) {
        travelled.push_back(in.travelled());
        layers.push_back(in.layers());
    }
    group.write("inlet_travelled", travelled.data(), travelled.size(), 1);
    group.write("inlet_layers", layers.data(), layers.size(), 1);
}

template <int Dim>
void OpenBoundariesModule<Dim>::load(const io::Hdf5Group& group) {
    std::size_t rows = 0;
    const auto travelled = group.read_doubles("inlet_travelled", 1, rows);
    if (rows != inlets_.size()) throw io::Hdf5Error(group.path() + ": the checkpoint has another number of inlets");
    const auto layers = group.read_int64("inlet_layers", 1, rows);
    if (rows != inlets_.size()) throw io::Hdf5Error(group.path() + ": the checkpoint has another number of inlets");
    for (std::size_t k = 0; k < rows; ++k) {
        inlets_[k].set_travelled(travelled[k]);
        inlets_[k].set_layers(layers[k]);
    }
}

template class OpenBoundariesModule<2>;
template class OpenBoundariesModule<3>;

}  // namespace grit::modules
