// The solid SPH module: fields, pressure, sums, material update and erosion.
#include "grit/modules/sph_solid.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "grit/analysis/fragments.hpp"
#include "grit/material/solid_model.hpp"
#include "grit/parallel/parallel.hpp"
#include "grit/sph/correction_matrix.hpp"
#include "grit/sph/pressure.hpp"

namespace grit::modules {

namespace {
/// rho / rho0 below which fractured rock counts as loose rubble (removed).
constexpr double rubble_dilation = 0.9;
}  // namespace

template <int Dim>
SolidModule<Dim>::SolidModule(sim::State<Dim>& state, const sim::RunSetup<Dim>& setup, const SphModule<Dim>& sph)
    : state_(state), setup_(setup), sph_(sph) {
    particles::FieldRegistry& f = state.particles.fields();
    f.add<core::SymTensor3>("deviatoric_stress", core::SymTensor3::zero(), true);
    f.add<double>("plastic_strain", 0.0, true);
    f.add<double>("damage", 0.0, true);
    f.add<double>("von_mises", 0.0, true);
    f.add<double>("temperature", 0.0, true);
    f.add<double>("specific_energy", 0.0, false);
    for (const auto& m : setup.spec.materials) {
        const auto* jh2 = std::get_if<material::JH2>(&m.solid_model);
        brittle_.push_back(jh2 != nullptr);
        rubble_density_.push_back(jh2 ? rubble_dilation * jh2->reference_density : 0.0);
    }
    // Written only where a JH-2 material can give it a value.
    const bool any_brittle = std::find(brittle_.begin(), brittle_.end(), true) != brittle_.end();
    f.add<double>("bulking_pressure", 0.0, any_brittle);
    f.add<std::int32_t>("fixed", 0, true);  // clamped particles (set by the open-boundaries module)

    // Snapshots show the solid state on solids only, and the bulking pressure (eq. 41) on JH-2 solids only.
    constexpr auto solid = static_cast<std::int32_t>(Phase::solid);
    const auto on_solids = [](std::int32_t phase, std::int32_t) { return phase == solid; };
    for (const char* name : {"deviatoric_stress", "plastic_strain", "damage", "von_mises", "temperature"})
        f.base(name).set_output_scope(on_solids);
    f.base("bulking_pressure").set_output_scope([brittle = brittle_](std::int32_t phase, std::int32_t m) {
        return phase == solid && brittle[static_cast<std::size_t>(m)];
    });
    std::vector<double> damage_length;
    for (const auto& m : setup.spec.materials) {
        const auto* jc = std::get_if<material::JohnsonCook>(&m.solid_model);
        const bool nonlocal = m.phase == Phase::solid && jc && jc->nonlocal_damage();
        damage_length.push_back(nonlocal ? jc->damage_length : 0.0);
    }
    nonlocal_damage_ = sph::NonlocalDamage<Dim>(std::move(damage_length), setup.periodic_box);
    parameters_.gravity = core::to_vec<Dim>(setup.spec.gravity);
    parameters_.artificial_stress = setup.spec.artificial_stress;
    parameters_.spacing = setup.spacing;
    parameters_.materials = sph.pair_coefficients();
    parameters_.periodic_box = setup.periodic_box;
}

template <int Dim>
void SolidModule<Dim>::initialise() {
    auto& ps = state_.particles;
    auto& temperature = ps.fields().template get<double>("temperature");
    for (Index i = 0; i < ps.size(); ++i)
        if (ps.phase()[i] == static_cast<std::int32_t>(Phase::solid))
            temperature[i] = setup_.spec.materials[static_cast<std::size_t>(ps.material()[i])].solid.room_temperature;
}

template <int Dim>
void SolidModule<Dim>::install(sim::Pipeline& pipeline) {
    using sim::Hook;
    auto& ps = state_.particles;
    pipeline.add(Hook::pressure, "solid_pressure", [this] { update_pressure(); }, true);
    pipeline.add(Hook::force, "sph_solid", [this, &ps] {
        sph::compute_solid_rates(ps, state_.neighbors.list(), setup_.kernel, parameters_, sph_.workspace(), workspace_);
        workspace_generation_ = ps.generation();
    }, true);
    pipeline.add(Hook::end_step, "solid_stress", [this] { update_stress(); });
    pipeline.add(Hook::end_step, "erosion", [this] { remove_failed(); });
}

template <int Dim>
void SolidModule<Dim>::update_pressure() {
    auto& ps = state_.particles;
    sph::update_pressure(ps, setup_.spec.materials, Phase::solid,
                         ps.fields().template get<double>("specific_energy").data());
    // JH-2 (eqs. 40-41): the polynomial EOS value plus the bulking increment in compression, and tension
    // limited to -T (1 - D).
    const auto& f = ps.fields();
    const double* damage = f.template get<double>("damage").data();
    const double* bulking = f.template get<double>("bulking_pressure").data();
    const double* rho = ps.density();
    double* p = ps.pressure();
    const std::int32_t* ph = ps.phase();
    const std::int32_t* mat = ps.material();
    const auto solid = static_cast<std::int32_t>(Phase::solid);
    const auto& materials = setup_.spec.materials;
    for (std::size_t m = 0; m < materials.size(); ++m) {
        const auto* jh2 = std::get_if<material::JH2>(&materials[m].solid_model);
        if (!jh2 || materials[m].phase != Phase::solid) continue;
        const auto id = static_cast<std::int32_t>(m);
        const double rho0 = jh2->reference_density, tension = jh2->strength.tensile_pressure();
        parallel::for_each(ps.size(), [&](Index i) {
            if (ph[i] != solid || mat[i] != id) return;
            p[i] = material::jh2_pressure(p[i], rho[i] / rho0 - 1.0, bulking[i], damage[i], tension);
        });
    }
}

template <int Dim>
void SolidModule<Dim>::update_stress() {
    // Material update of every solid particle (first seed paper Fig. 6): Jaumann rate, radial return,
    // plastic strain, damage, temperature; and the specific internal energy. One loop per material,
    // dispatched once on its constitutive model. Reads the strain rate and spin of this step's solid
    // sums: scratch outside the registry, valid while the particle set is unchanged since.
    auto& ps = state_.particles;
    if (workspace_generation_ != ps.generation())
        throw std::logic_error("solid workspace read after the particle set changed");
    auto& f = ps.fields();
    core::SymTensor3* tau = f.template get<core::SymTensor3>("deviatoric_stress").data();
    double* eps_p = f.template get<double>("plastic_strain").data();
    double* damage = f.template get<double>("damage").data();
    double* vm = f.template get<double>("von_mises").data();
    double* temperature = f.template get<double>("temperature").data();
    double* energy = f.template get<double>("specific_energy").data();
    double* bulking = f.template get<double>("bulking_pressure").data();
    const double* p = ps.pressure();
    const double* rho = ps.density();
    const std::int32_t* ph = ps.phase();
    const std::int32_t* mat = ps.material();
    const core::SymTensor3* rate = workspace_.strain_rate.data();
    const material::Spin* spin = workspace_.spin.data();
    const double* de = workspace_.energy_rate.data();
    const core::SymTensor3* correction = workspace_.correction.data();
    const double dt = state_.clock.dt;
    failure_von_mises_.assign(static_cast<std::size_t>(ps.size()), std::numeric_limits<double>::quiet_NaN());
    double* failure_vm = failure_von_mises_.data();
    damage_increment_.resize(static_cast<std::size_t>(ps.size()));
    double* increment = damage_increment_.data();
    const auto solid = static_cast<std::int32_t>(Phase::solid);
    const auto& materials = setup_.spec.materials;
    for (std::size_t m = 0; m < materials.size(); ++m) {
        const auto& material = materials[m];
        if (material.phase != Phase::solid) continue;
        const auto id = static_cast<std::int32_t>(m);
        std::visit(
            [&](const auto& model) {
                parallel::for_each_dynamic(ps.size(), [&](Index i) {
                    if (ph[i] != solid || mat[i] != id) return;
                    material::SolidPointState s{tau[i], eps_p[i], 0.0, damage[i], temperature[i], bulking[i]};
                    const double damage_before = damage[i], vm_before = vm[i];
                    // On the surface eq. (35) takes at most the triaxiality a surface can carry.
                    const bool at_surface = sph::at_solid_surface<Dim>(correction[i]);
                    s = material::update_solid_point(model, material.solid, s, rate[i], spin[i], p[i], rho[i], dt,
                                                     at_surface);
                    if (s.damage >= 1.0 && damage_before < 1.0) failure_vm[i] = vm_before;
                    increment[i] = s.damage_increment;
                    tau[i] = s.deviatoric_stress;
                    eps_p[i] = s.plastic_strain;
                    damage[i] = s.damage;
                    temperature[i] = s.temperature;
                    bulking[i] = s.bulking_pressure;
                    vm[i] = s.deviatoric_stress.von_mises();
                    energy[i] += de[i] * dt;
                });
            },
            material.solid_model);
    }
    if (!nonlocal_damage_.active()) return;
    // Non-local damage (sph/nonlocal_damage.hpp): the Johnson-Cook materials with a damage length
    // accumulate the average of their particles' increments; a particle that fails now fails with the
    // stress it has after this step's return (its failure zeroes it).
    averaged_increment_.resize(static_cast<std::size_t>(ps.size()));  // written for the averaging particles
    nonlocal_damage_.average(ps, increment, averaged_increment_.data());
    const double* averaged = averaged_increment_.data();
    parallel::for_each(ps.size(), [&](Index i) {
        if (ph[i] != solid || !nonlocal_damage_.averages(mat[i]) || ps.is_image(i)) return;
        material::SolidPointState s{tau[i], eps_p[i], 0.0, damage[i], temperature[i], bulking[i]};
        if (s.damage >= 1.0) return;
        material::accumulate_ductile_damage(s, averaged[i]);
        if (s.damage >= 1.0) failure_vm[i] = vm[i];
        damage[i] = s.damage;
        tau[i] = s.deviatoric_stress;
        vm[i] = s.deviatoric_stress.von_mises();
    });
}

template <int Dim>
void SolidModule<Dim>::remove_failed() {
    // Ductile (eq. 36): a particle with D >= 1 is removed and its mass booked as eroded.
    // Brittle (JH-2): a fractured particle keeps pressure and its fractured strength, so it stays while
    // it belongs to the specimen; it is removed once it is part of a fragment made of fractured rock
    // only: a cluster of solid particles linked within 1.5 spacings (nearest and diagonal neighbours)
    // that holds no intact (D < 1) particle. Rubble resting on the specimen stays until carried off;
    // fractured rock that has dilated by more than 10 % (rho < 0.9 rho0) has come apart from its
    // neighbours (it holds no tension) and goes too: carried in the water, such particles ran away.
    auto& ps = state_.particles;
    const double* rho = ps.density();
    const double* damage = ps.fields().template get<double>("damage").data();
    const std::int32_t* ph = ps.phase();
    const std::int32_t* mat = ps.material();
    const auto solid = static_cast<std::int32_t>(Phase::solid);
    const Index n = ps.size();
    std::vector<std::uint8_t> gone(static_cast<std::size_t>(n), 0);
    bool fractured_rock = false;
    parallel::for_each(n, [&](Index i) {
        // A symmetry plane's image goes with its source.
        if (ph[i] != solid || damage[i] < 1.0 || ps.is_image(i)) return;
        const auto k = static_cast<std::size_t>(mat[i]);
        gone[static_cast<std::size_t>(i)] = brittle_[k] && rho[i] >= rubble_density_[k] ? 2 : 1;
    });
    for (Index i = 0; i < n && !fractured_rock; ++i) fractured_rock = gone[static_cast<std::size_t>(i)] == 2;
    if (fractured_rock) {
        // Fragments as exchangeable labels (analysis/fragments): the clusters of fractured rock, and those a
        // member anchors to intact rock; a fractured particle goes when its fragment is not anchored.
        const double link = 1.5 * setup_.spacing;
        const auto& box = setup_.periodic_box;  // links across a periodic face by the nearest image
        const auto labels = analysis::fragment_labels(ps, damage, link, n, nullptr, box);
        const auto anchored = analysis::anchored_fragments(ps, damage, labels, state_.neighbors.list(), link, n, box);
        for (Index i = 0; i < n; ++i)
            if (gone[static_cast<std::size_t>(i)] == 2)
                gone[static_cast<std::size_t>(i)] =
                    std::binary_search(anchored.begin(), anchored.end(), labels[static_cast<std::size_t>(i)]) ? 0 : 1;
    }
    const Index failed = parallel::sum(n, Index{0}, [&](Index i) { return Index{gone[static_cast<std::size_t>(i)]}; });
    if (failed == 0) return;
    const double* m = ps.mass();
    std::vector<Index> keep;
    keep.reserve(static_cast<std::size_t>(n - failed));
    for (Index i = 0; i < n; ++i) {
        const auto g = static_cast<std::size_t>(i);
        if (!gone[g]) {
            keep.push_back(i);
            continue;
        }
        state_.ledger.eroded += m[i];
        const auto k = static_cast<std::size_t>(mat[i]);
        const bool brittle = brittle_[k];
        analysis::ErosionRecord r =
            analysis::erosion_record(ps, i, state_.clock.time, setup_.spec.materials[k].reference_density());
        r.cause = !brittle ? "failed" : rho[i] < rubble_density_[k] ? "rubble" : "fragment";
        // A ductile failure zeroes the stress: the record keeps the von Mises stress it failed at.
        const double vm_before = g < failure_von_mises_.size() ? failure_von_mises_[g] : r.von_mises;
        if (!brittle && !std::isnan(vm_before)) {
            r.von_mises = vm_before;
            r.triaxiality = vm_before > 0.0 ? -r.pressure / vm_before : std::numeric_limits<double>::quiet_NaN();
        }
        // The correction of this step's sums, while the particle set is the one they were made for.
        r.surface = workspace_generation_ == ps.generation() ? sph::at_solid_surface<Dim>(workspace_.correction[g]) : -1;
        state_.erosion.add(r);
    }
    ps.remove(keep);
}

template <int Dim>
void SolidModule<Dim>::output_values(std::vector<sim::OutputValue>& out) const {
    const auto& ps = state_.particles;
    const auto& f = ps.fields();
    const double* eps_p = f.template get<double>("plastic_strain").data();
    const double* e = f.template get<double>("specific_energy").data();
    const double* m = ps.mass();
    const std::int32_t* ph = ps.phase();
    const auto solid = static_cast<std::int32_t>(Phase::solid);
    const double max_eps = parallel::max(ps.size(), 0.0, [&](Index i) { return ph[i] == solid ? eps_p[i] : 0.0; });
    const double internal = parallel::sum(ps.size(), 0.0, [&](Index i) {
        return ph[i] == solid && !ps.is_image(i) ? m[i] * e[i] : 0.0;
    });
    out.push_back(sim::OutputValue::real("eroded_mass", state_.ledger.eroded, domain::Combine::sum));
    // When the solid first lost mass (failure or an outlet): the end of Fig. 13's Stage One [s].
    out.push_back(sim::OutputValue::real("first_removal_time", state_.erosion.first_time(), domain::Combine::min).summary_only());
    out.push_back(sim::OutputValue::real("max_plastic_strain", max_eps, domain::Combine::max));
    out.push_back(sim::OutputValue::real("internal_energy", internal, domain::Combine::sum));  // sum of m e over solids [J]
}

template <int Dim>
void SolidModule<Dim>::open_output(const sim::OutputPlace& place, bool restart) {
    std::vector<std::string> names;
    for (const auto& m : setup_.spec.materials) names.push_back(m.name);
    state_.erosion.open(place.dir / "eroded.csv", Dim, std::move(names),
                        restart ? static_cast<long>(state_.erosion.total()) : -1);
}

template <int Dim>
void SolidModule<Dim>::write_output(const sim::OutputPlace& /*place*/) {
    state_.erosion.flush();
}

template <int Dim>
void SolidModule<Dim>::flush_logs() {
    state_.erosion.flush();
}

template <int Dim>
void SolidModule<Dim>::save(io::Hdf5Group& group) const {
    group.write("eroded_particles", static_cast<std::int64_t>(state_.erosion.total()));
    group.write("first_removal_time", state_.erosion.first_time());
}

template <int Dim>
void SolidModule<Dim>::load(const io::Hdf5Group& group) {
    // A checkpoint from before the erosion log has no count: its eroded.csv, if any, is started again.
    // One from before the first removal's time has none: it stays unknown (NaN) if something had gone.
    state_.erosion.restore(group.has_attribute("eroded_particles")
                               ? static_cast<std::size_t>(group.read_int("eroded_particles"))
                               : 0,
                           group.has_attribute("first_removal_time") ? group.read_double("first_removal_time")
                                                                     : std::numeric_limits<double>::quiet_NaN());
}

template class SolidModule<2>;
template class SolidModule<3>;

}  // namespace grit::modules
