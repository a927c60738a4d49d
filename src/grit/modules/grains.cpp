// The grains module: set-up from the case, the DEM step, plane impacts, outputs.
#include "grit/modules/grains.hpp"

#include <fmt/format.h>

#include <cmath>
#include <numbers>

#include "grit/core/error.hpp"
#include "grit/dem/grain_fill.hpp"
#include "grit/domain/particle_id.hpp"
#include "grit/io/vtu_writer.hpp"
#include "grit/parallel/parallel.hpp"
#include "grit/sim/geometry.hpp"

namespace grit::modules {

using core::to_vec;

template <int Dim>
double impact_angle(const core::Vec<Dim>& v, const core::Vec<Dim>& n) {
    const double speed = core::norm(v), length = core::norm(n);
    if (!(speed > 0.0) || !(length > 0.0)) return 90.0;
    return std::asin(std::min(1.0, std::abs(core::dot(v, n)) / (speed * length))) * 180.0 / std::numbers::pi;
}

template double impact_angle<2>(const core::Vec<2>&, const core::Vec<2>&);
template double impact_angle<3>(const core::Vec<3>&, const core::Vec<3>&);

template <int Dim>
GrainsModule<Dim>::GrainsModule(sim::State<Dim>& state, const sim::RunSetup<Dim>& setup)
    : state_(state), setup_(setup) {
    const auto& spec = setup.spec;
    dem::DemParameters<Dim> p;
    p.contact_law = spec.dem.contact_law;
    p.gravity = to_vec<Dim>(spec.gravity);
    p.skin = spec.dem.skin;
    p.domain = setup.periodic_box;  // domain.periodic: the same box as the SPH particles'
    p.grain_pairs = spec.dem.grain_grain_contact;
    state.grains = std::make_unique<dem::DemSystem<Dim>>(p, spec.grain_materials);
    auto& system = *state.grains;
    system.grains().fields().template add<std::int32_t>("contact_targets", 0, false);

    if (static_cast<int>(spec.grain_walls.size()) + (spec.symmetry_plane ? 1 : 0) > max_grain_planes)
        throw core::InputError(fmt::format("key 'grain_wall': at most {} plane walls", max_grain_planes));
    for (const auto& w : spec.grain_walls) {
        system.add_wall({to_vec<Dim>(w.point), to_vec<Dim>(w.normal), w.material});
        wall_names_.push_back(w.name);
    }
    if (spec.symmetry_plane) {  // a grain meets its mirror twin at x = 0 (modules/symmetry_plane)
        system.grains().fields().template add<std::int32_t>(dem::straddling_field, -1, false);
        core::Vec<Dim> normal = core::Vec<Dim>::zero();
        normal[0] = 1.0;
        const std::int32_t material = spec.abrasive.enabled ? spec.abrasive.material : 0;
        system.add_wall({core::Vec<Dim>::zero(), normal, material, true});
        wall_names_.push_back("symmetry_plane");
    }
    bool any_fixed = false;
    for (const auto& b : spec.grains) any_fixed |= b.fixed;
    if (any_fixed) system.grains().fields().template add<std::int32_t>("fixed", 0, true);
    for (std::size_t block = 0; block < spec.grains.size(); ++block) {
        const auto& b = spec.grains[block];
        std::vector<dem::GrainSeed<Dim>> seeds;
        if (b.arrangement == "single") {
            std::mt19937_64 rng(b.seed);
            seeds.push_back({to_vec<Dim>(b.position), dem::draw_diameter(b.size, rng)});
        } else if (b.arrangement == "lattice") {
            seeds = dem::lattice_fill<Dim>(to_vec<Dim>(b.min), to_vec<Dim>(b.max), b.spacing, b.size, b.seed, b.jitter);
        } else {
            seeds = dem::random_fill<Dim>(to_vec<Dim>(b.min), to_vec<Dim>(b.max), static_cast<std::size_t>(b.count),
                                          b.size, b.seed);
            if (seeds.size() < static_cast<std::size_t>(b.count))
                throw core::InputError(fmt::format("{}: only {} of count = {} grains fit in the box without overlap",
                                                   b.key, seeds.size(), b.count));
        }
        if (seeds.empty()) throw core::InputError(fmt::format("{}: the arrangement holds no grain", b.key));
        for (std::size_t serial = 0; serial < seeds.size(); ++serial) {
            const auto& s = seeds[serial];
            for (int k = 0; k < Dim; ++k)
                if (!setup.periodic_box.periodic[k] &&
                    (s.position[k] < spec.domain_min[static_cast<std::size_t>(k)] ||
                     s.position[k] > spec.domain_max[static_cast<std::size_t>(k)]))
                    throw core::InputError(fmt::format(
                        "{}: a grain at ({}) lies outside the domain (domain.min/domain.max); enlarge the domain",
                        b.key, fmt::join(std::vector<double>(s.position.c, s.position.c + Dim), ", ")));
            // The seed's index in its block's fill is its serial.
            const auto id = domain::make_particle_id({domain::IdKind::grain_block, static_cast<std::int32_t>(block)},
                                                     static_cast<std::int64_t>(serial));
            const Index i = system.add_grain(id, s.position, 0.5 * s.diameter, b.material, to_vec<Dim>(b.velocity));
            if (b.fixed) system.grains().fields().template get<std::int32_t>("fixed")[i] = 1;
        }
    }
}

template <int Dim>
void GrainsModule<Dim>::install(sim::Pipeline& pipeline) {
    const auto& spec = setup_.spec;
    if (spec.remove_leaving || !spec.outlets.empty())
        pipeline.add(sim::Hook::boundaries, "grain_exit", [this] { remove_leaving(); });
    pipeline.add(sim::Hook::grain_motion, "grain_drift", [this] { move(); });
    pipeline.add(sim::Hook::grain_neighbors, "grain_neighbors", [this] { state_.grains->update_neighbors(); });
    pipeline.add(sim::Hook::grain_force, "grain_forces", [this] { contact_forces(); });
    if (!state_.grains->walls().empty())
        pipeline.add(sim::Hook::grain_force, "grain_plane_contacts", [this] { log_plane_contacts(); });
}

template <int Dim>
void GrainsModule<Dim>::remove_leaving() {
    // Grains leave through the outlets, as the water does, and (domain.on_exit = "remove") through the
    // domain's faces; their mass is booked as grain mass out.
    const auto& spec = setup_.spec;
    auto& system = *state_.grains;
    const auto& grains = system.grains();
    const auto* x = grains.position();
    const auto& periodic = system.parameters().domain.periodic;
    std::vector<Index> keep;
    keep.reserve(static_cast<std::size_t>(grains.size()));
    for (Index g = 0; g < grains.size(); ++g) {
        bool out = false;
        for (const auto& o : spec.outlets) out = out || sim::inside<Dim>(x[g], o.min, o.max);
        if (spec.remove_leaving)
            for (int k = 0; k < Dim; ++k)
                out = out || (!periodic[k] && (x[g][k] < spec.domain_min[static_cast<std::size_t>(k)] ||
                                               x[g][k] > spec.domain_max[static_cast<std::size_t>(k)]));
        if (out) {
            grain_mass_out_ += grains.mass()[g];
            grain_collisions_out_ += grains.collisions()[g];
            ++grains_out_;
        } else {
            keep.push_back(g);
        }
    }
    if (static_cast<Index>(keep.size()) < grains.size()) system.gather(keep);
}

template <int Dim>
void GrainsModule<Dim>::prime() {
    state_.grains->compute_forces(0.0, state_.clock.time);
}

template <int Dim>
void GrainsModule<Dim>::move() {
    auto& system = *state_.grains;
    const double dt = state_.clock.dt;
    if (state_.clock.step != 0) system.kick(dt);  // the step before's second half, with its whole forces
    system.drift(dt, state_.clock.time);
}

template <int Dim>
void GrainsModule<Dim>::contact_forces() {
    state_.grains->compute_contact_forces(state_.clock.dt, state_.clock.time + state_.clock.dt);
}

template <int Dim>
void GrainsModule<Dim>::log_plane_contacts() {
    auto& system = *state_.grains;
    const double time = state_.clock.time, dt = state_.clock.dt;
    // First contacts with the plane walls, at the new positions.
    auto& grains = system.grains();
    std::int32_t* mask = grains.fields().template get<std::int32_t>("contact_targets").data();
    const auto& walls = system.walls();
    const auto* x = grains.position();
    const auto* v = grains.velocity();
    const double* r = grains.radius();
    const auto& fields = std::as_const(grains).fields();
    const std::int32_t* straddling =
        fields.has(dem::straddling_field) ? fields.template get<std::int32_t>(dem::straddling_field).data() : nullptr;
    for (Index g = 0; g < grains.size(); ++g) {
        for (std::size_t w = 0; w < walls.size(); ++w) {
            const std::int32_t bit = 1 << w;
            const bool touching = core::dot(x[g] - walls[w].point, walls[w].normal) < r[g] &&
                                  !(walls[w].frictionless && straddling && straddling[g] > 0);
            if (touching && !(mask[g] & bit)) {
                if (walls[w].frictionless)  // a symmetry plane: the grain meets its mirror twin, a collision
                    ++grains.collisions()[g];
                else
                    state_.impacts.add({time + dt, grains.id()[g], wall_names_[w], core::norm(v[g]),
                                        impact_angle<Dim>(v[g], walls[w].normal), core::to_array3(x[g]),
                                        grains.collisions()[g]});
            }
            mask[g] = touching ? (mask[g] | bit) : (mask[g] & ~bit);
        }
    }
}

template <int Dim>
double GrainsModule<Dim>::stable_time_step() const {
    return state_.grains->stable_time_step();
}

template <int Dim>
std::string GrainsModule<Dim>::check_health() const {
    const auto& spec = setup_.spec;
    const auto& grains = state_.grains->grains();
    const auto* x = grains.position();
    const auto* v = grains.velocity();
    const auto& periodic = state_.grains->parameters().domain.periodic;
    const Index bad = parallel::first_index(grains.size(), [&](Index i) {
        if (!core::all_finite(x[i]) || !core::all_finite(v[i])) return true;
        if (spec.remove_leaving) return false;  // a grain that has left is removed at the next step's start
        for (int k = 0; k < Dim; ++k)
            if (!periodic[k] && (x[i][k] < spec.domain_min[static_cast<std::size_t>(k)] ||
                                 x[i][k] > spec.domain_max[static_cast<std::size_t>(k)]))
                return true;
        return false;
    });
    if (bad < 0) return {};
    const std::string what = !core::all_finite(x[bad]) ? "position is not finite"
                             : !core::all_finite(v[bad]) ? "velocity is not finite"
                                                         : "escaped the domain (domain.min/domain.max)";
    return fmt::format("grain {} ({}) at ({:.6g}): {}", grains.id()[bad], domain::describe_id(grains.id()[bad]),
                       fmt::join(std::vector<double>(x[bad].c, x[bad].c + Dim), ", "), what);
}

template <int Dim>
void GrainsModule<Dim>::output_values(std::vector<sim::OutputValue>& out) const {
    out.push_back(sim::OutputValue::count("grains", static_cast<double>(state_.grains->grains().size()), domain::Combine::sum));
    out.push_back(sim::OutputValue::real("grain_kinetic_energy", state_.grains->kinetic_energy(), domain::Combine::sum));
    if (setup_.spec.remove_leaving || !setup_.spec.outlets.empty()) {
        out.push_back(sim::OutputValue::count("grains_out", static_cast<double>(grains_out_), domain::Combine::sum));
        out.push_back(sim::OutputValue::real("grain_mass_out", grain_mass_out_, domain::Combine::sum).summary_only());
    }
    out.push_back(sim::OutputValue::count("impacts", static_cast<double>(state_.impacts.total()), domain::Combine::sum).summary_only());
    // Grain-grain collisions begun, each grain's counted (two free grains meeting count two), those of
    // the grains that have left included: the deflections Fig. 14 credits with an AWJ crater's widening.
    const auto& grains = state_.grains->grains();
    std::int64_t collisions = grain_collisions_out_;
    for (Index g = 0; g < grains.size(); ++g) collisions += grains.collisions()[g];
    out.push_back(sim::OutputValue::count("grain_collisions", static_cast<double>(collisions), domain::Combine::sum));
}

template <int Dim>
void GrainsModule<Dim>::open_output(const sim::OutputPlace& place, bool restart) {
    namespace fs = std::filesystem;
    fs::create_directories(place.dir / "grains");
    // A fresh run clears the old snapshots; a restart keeps those its checkpoint lists (load() removes
    // the ones written after it).
    if (!restart)
        for (const auto& e : fs::directory_iterator(place.dir / "grains"))
            if (e.path().extension() == ".vtu") fs::remove(e.path());
    pvd_ = std::make_unique<io::PvdWriter>(place.dir / (place.name + "_grains.pvd"));
    if (restart) pvd_->restore(restored_pvd_);
    state_.impacts.open(place.dir / "impacts.csv", Dim, restart ? static_cast<long>(state_.impacts.total()) : -1);
}

template <int Dim>
void GrainsModule<Dim>::write_output(const sim::OutputPlace& place) {
    if (place.snapshots) {
        const auto file = fmt::format("grains/{}_grains_{:06}.vtu", place.name, snapshot_index_++);
        io::PointCloud cloud = state_.grains->grains().snapshot();
        io::NameList names{"material_names", {}};
        for (const auto& m : setup_.spec.grain_materials) names.values.push_back(m.name);
        cloud.names.push_back(std::move(names));
        io::write_vtu(place.dir / file, cloud);
        pvd_->add(state_.clock.time, file);
    }
    state_.impacts.flush();
}

template <int Dim>
void GrainsModule<Dim>::save(io::Hdf5Group& group) const {
    group.write("snapshot_index", static_cast<std::int64_t>(snapshot_index_));
    group.write("grains_out", grains_out_);
    group.write("grain_mass_out", grain_mass_out_);
    group.write("grain_collisions_out", grain_collisions_out_);
    io::save_pvd_entries(group, "pvd", pvd_ ? pvd_->entries() : restored_pvd_);
}

template <int Dim>
void GrainsModule<Dim>::load(const io::Hdf5Group& group) {
    snapshot_index_ = static_cast<long>(group.read_int("snapshot_index"));
    grains_out_ = group.read_int("grains_out");
    grain_mass_out_ = group.read_double("grain_mass_out");
    grain_collisions_out_ = group.read_int("grain_collisions_out");
    restored_pvd_ = io::load_pvd_entries(group, "pvd");
}

template class GrainsModule<2>;
template class GrainsModule<3>;

}  // namespace grit::modules
