// DemSystem: neighbour updates with history carry-over, the force stage and the velocity-Verlet step.
#include "grit/dem/dem_system.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <variant>

#include "grit/core/error.hpp"
#include "grit/dem/grain_integrator.hpp"
#include "grit/dem/grain_loop.hpp"
#include "grit/parallel/parallel.hpp"

namespace grit::dem {

template <int Dim>
DemSystem<Dim>::DemSystem(DemParameters<Dim> parameters, std::vector<GrainMaterial> materials)
    : parameters_(std::move(parameters)), materials_(std::move(materials)),
      law_(make_contact_law(parameters_.contact_law)) {
    if (materials_.empty()) throw core::InputError("a grain system needs at least one material");
    for (const auto& m : materials_)
        if (!(m.density > 0.0) || !(m.youngs_modulus > 0.0) || !(m.restitution > 0.0 && m.restitution <= 1.0) ||
            !(m.friction >= 0.0) || !(m.poisson_ratio >= 0.0 && m.poisson_ratio < 0.5))
            throw core::InputError("grain material '" + m.name +
                                   "': needs density > 0 [kg/m^3], youngs_modulus > 0 [Pa], 0 <= poisson_ratio "
                                   "< 0.5, friction >= 0 and 0 < restitution <= 1");
    pair_table_.count = static_cast<std::int32_t>(materials_.size());
    for (const auto& a : materials_)
        for (const auto& b : materials_) pair_table_.table.push_back(pair_material(a, b));
    parameters_.domain.finalise();
}

template <int Dim>
Index DemSystem<Dim>::add_grain(domain::ParticleId id, const Vec& x, double radius, std::int32_t material,
                                const Vec& v) {
    if (material < 0 || material >= static_cast<std::int32_t>(materials_.size()))
        throw core::InputError("grain material index " + std::to_string(material) + " out of range");
    if (!(radius > 0.0)) throw core::InputError("grain radius must be > 0 [m], got " + std::to_string(radius));
    lists_dirty_ = true;
    forces_ready_ = false;
    return grains_.add(id, x, radius, materials_[static_cast<std::size_t>(material)], material, v);
}

template <int Dim>
Index DemSystem<Dim>::add_grain(const Vec& x, double radius, std::int32_t material, const Vec& v) {
    return add_grain(grains_.take_hand_built_id(), x, radius, material, v);
}

template <int Dim>
Index DemSystem<Dim>::inject_grain(domain::ParticleId id, const Vec& x, double radius, std::int32_t material,
                                   const Vec& v) {
    const bool ready = forces_ready_;
    const Index i = add_grain(id, x, radius, material, v);
    grains_.force()[i] = parameters_.gravity * grains_.mass()[i];
    forces_ready_ = ready;
    return i;
}

template <int Dim>
void DemSystem<Dim>::add_wall(const PlaneWall<Dim>& wall) {
    const double len = core::norm(wall.normal);
    if (!(len > 0.0)) throw core::InputError("plane wall: the normal must be a non-zero vector");
    if (wall.material < 0 || wall.material >= static_cast<std::int32_t>(materials_.size()))
        throw core::InputError("plane wall: material index " + std::to_string(wall.material) + " out of range");
    PlaneWall<Dim> w = wall;
    w.normal *= 1.0 / len;
    grains_.fields().template add<Vec>("wall_history_" + std::to_string(walls_.size()), Vec::zero(), false);
    walls_.push_back(w);
    forces_ready_ = false;
}

template <int Dim>
void DemSystem<Dim>::add_mesh(MeshWall wall) {
    if constexpr (Dim != 3) {
        throw core::InputError("mesh walls need a 3D case (simulation.dimension = 3)");
    } else {
        if (wall.material < 0 || wall.material >= static_cast<std::int32_t>(materials_.size()))
            throw core::InputError("mesh wall '" + wall.name + "': material index " + std::to_string(wall.material) +
                                   " out of range");
        if (!meshes_) meshes_ = std::make_unique<MeshWalls>();
        meshes_->add(std::move(wall), grains_);
        forces_ready_ = false;
    }
}

template <int Dim>
void DemSystem<Dim>::gather(const std::vector<Index>& source) {
    if (!history_saved_) history_.save(grains_.id(), grains_.size(), pairs_);
    history_saved_ = true;
    grains_.gather(source);  // forces and torques travel with their grains and stay valid
    lists_dirty_ = true;
}

template <int Dim>
double DemSystem<Dim>::skin() const {
    if (parameters_.skin >= 0.0) return parameters_.skin;
    const double rmax = max_over_grains(grains_.size(), 0.0, [&](Index i) { return grains_.radius()[i]; });
    return 0.4 * rmax;
}

template <int Dim>
void DemSystem<Dim>::rebuild_neighbors() {
    const Index n = grains_.size();
    if (!history_saved_) history_.save(grains_.id(), n, pairs_);
    history_saved_ = false;
    // Wrap into the periodic box, then sort grains by cell so neighbours are close in memory.
    Vec* x = grains_.position();
    const GrainDomain<Dim>& domain = parameters_.domain;
    for_each_grain(n, [&](Index i) { x[i] = domain.wrap(x[i]); });
    skin_ = skin();
    if (n == 0) {  // no grains yet (a feed brings them): empty lists, no grid
        list_ = GrainNeighborList<Dim>();
        cut_pairs();
        scratch_.reset(0);
        lists_dirty_ = false;
        ++counters_.rebuilds;
        return;
    }
    const double rmax = max_over_grains(n, 0.0, [&](Index i) { return grains_.radius()[i]; });
    const double cell = 2.0 * rmax + skin_;
    const auto grid = GrainNeighborList<Dim>::make_grid(domain, x, n, cell);
    std::vector<Index> cell_start;
    neighbors::sort_by_cell(grid, x, n, order_, cell_start);
    grains_.gather(order_);
    list_.build(grid, cell_start, domain, std::as_const(grains_).position(), std::as_const(grains_).radius(), n,
                skin_);
    cut_pairs();
    history_.restore(grains_.id(), pairs_);
    scratch_.reset(pairs_.upper_size());
    lists_dirty_ = false;
    ++counters_.rebuilds;
}

template <int Dim>
void DemSystem<Dim>::cut_pairs() {
    pairs_.update(list_.offsets(), list_.indices(), list_.grain_count(), list_.version());
    blocks_.assign(list_.slab_starts());
    images_.assign(parameters_.domain, pairs_, list_.reference_positions());
}

template <int Dim>
void DemSystem<Dim>::update_neighbors() {
    const Index n = grains_.size();
    // The drift's measure when it was taken against these lists, else a pass of its own.
    const double moved2 = drift2_;
    drift2_ = -1.0;
    if (lists_dirty_ || list_.grain_count() != n) {
        rebuild_neighbors();
    } else if (moved2 >= 0.0 ? list_.stale(moved2, n) : list_.stale(std::as_const(grains_).position(), n)) {
        rebuild_neighbors();
    }
}

template <int Dim>
void DemSystem<Dim>::drift(double dt, double time) {
    // Forces of a state no step has computed yet (new grains or walls): dt = 0 leaves the histories as
    // they are, so a repeated evaluation does not count their increment twice.
    if (!forces_ready_) compute_forces(0.0, time);
    const Index n = grains_.size();
    // The skin check rides on the drift's pass; fresh lists are due anyway when they are dirty.
    const bool check = !lists_dirty_ && list_.grain_count() == n;
    const Vec* reference = check ? list_.reference_positions() : nullptr;
    double d2 = 0.0;
    if (parameters_.grain_pairs) {
        // The pair pass's sums cleared in the same pass, while each grain's lines are loaded (a pass of
        // its own cost 7 % of a settling step); a rebuild reorders the grains and unsets the flag.
        prepare_pair_sums(grains_, scratch_);
        d2 = kick_drift_grains(grains_, 0.5 * dt, dt, reference, PairSumsClearing<Dim>(grains_, scratch_));
        scratch_.sums_cleared = true;
    } else {
        d2 = kick_drift_grains(grains_, 0.5 * dt, dt, reference);
    }
    drift2_ = check ? d2 : -1.0;
}

template <int Dim>
void DemSystem<Dim>::force_stage(double dt, double half_kick, double time) {
    std::vector<Vec*> wall_history;
    for (std::size_t s = 0; s < walls_.size(); ++s)
        wall_history.push_back(grains_.fields().template get<Vec>("wall_history_" + std::to_string(s)).data());
    std::visit(
        [&](const auto& law) {
            // Sized before the completion takes the counts' data().
            if (parameters_.grain_pairs) prepare_pair_sums(grains_, scratch_);
            const GrainCompletion<Dim, std::decay_t<decltype(law)>> complete(
                grains_, parameters_.gravity, walls_, wall_history, pair_table_, law, dt, half_kick,
                parameters_.grain_pairs ? scratch_.touching_pairs.data() : nullptr);
            // Without mesh walls (whose contacts come between the pairs and the completion) each grain is
            // completed inside the pair pass, as soon as its sums are whole.
            const bool complete_in_pairs = parameters_.grain_pairs && !meshes_;
            if (complete_in_pairs) {
                grain_pair_pass<Dim>(grains_, pairs_, blocks_, images_, history_, pair_table_, law, dt, scratch_,
                                     complete);
            } else if (parameters_.grain_pairs) {
                grain_pair_pass<Dim>(grains_, pairs_, blocks_, images_, history_, pair_table_, law, dt, scratch_);
            } else {  // grains pass through one another: no pair forces, no contacts
                Vec* f = grains_.force();
                Spin<Dim>* t = grains_.torque();
                std::int32_t* touching = grains_.grain_contact();
                for_each_grain(grains_.size(), [&](Index i) {
                    f[i] = Vec::zero();
                    t[i] = zero_spin<Dim>();
                    touching[i] = 0;
                });
            }
            if constexpr (Dim == 3) {
                if (meshes_) {
                    meshes_->place(time);
                    meshes_->contact_pass(grains_, pair_table_, law, dt);
                }
            } else {
                (void)time;
            }
            if (!complete_in_pairs) for_each_grain(grains_.size(), [&](Index i) { complete(i); });
        },
        law_);
    forces_ready_ = true;
}

template <int Dim>
void DemSystem<Dim>::compute_forces(double dt, double time) {
    update_neighbors();
    force_stage(dt, 0.0, time);
}

template <int Dim>
void DemSystem<Dim>::compute_contact_forces(double dt, double time) {
    force_stage(dt, 0.0, time);
}

template <int Dim>
void DemSystem<Dim>::kick(double dt) {
    kick_grains(grains_, 0.5 * dt);
    ++counters_.steps;
}

template <int Dim>
void DemSystem<Dim>::step(double dt, double time) {
    // The phases with the second half kick in the force stage's completion: two passes over the grains a
    // step (kick, drift and the sums' clearing; the pairs, each grain completed and kicked inside it),
    // three with mesh walls (their contacts come before the completion).
    drift(dt, time);
    update_neighbors();
    force_stage(dt, 0.5 * dt, time + dt);
    ++counters_.steps;
}

template <int Dim>
double DemSystem<Dim>::stable_time_step(double impact_speed) const {
    const Index n = grains_.size();
    const double* r = grains_.radius();
    const std::int32_t* mat = grains_.material();
    const std::int32_t* fixed = fixed_flags(grains_);
    return min_over_grains(n, 1e300, [&](Index i) {
        // A fixed grain does not move: its contacts set no step (a free grain touching it sets its own).
        if (fixed && fixed[i]) return 1e300;
        const GrainMaterial& m = materials_[static_cast<std::size_t>(mat[i])];
        // The sphere's mass in 2D too: a disc's contacts are the sphere's (contact_forces.hpp).
        if (std::holds_alternative<LinearSpringDashpot>(law_)) return linear_time_step(m, r[i]);
        double dt = 0.2 * rayleigh_time(m, r[i]);
        if (impact_speed > 0.0) {
            const PairMaterial& p = pair_table_.at(mat[i], mat[i]);
            const double mass = sphere_mass(m.density, r[i]);
            dt = std::min(dt, hertz_contact_time(0.5 * mass, 0.5 * r[i], p.youngs_effective, impact_speed) / 50.0);
        }
        return dt;
    });
}

template <int Dim>
std::size_t DemSystem<Dim>::contact_pairs() const {
    const Index n = grains_.size();
    if (list_.grain_count() != n) return 0;
    const Vec* x = grains_.position();
    const double* r = grains_.radius();
    const Index* nb = list_.indices();
    return parallel::sum(n, std::size_t{0}, [&](Index i) {
        std::size_t c = 0;
        for (Index k = list_.begin(i); k < list_.end(i); ++k) {
            const Index j = nb[k];
            const double reach = r[i] + r[j];
            c += core::norm2(parameters_.domain.nearest_image(x[j] - x[i])) < reach * reach;  // rows: each pair once
        }
        return c;
    });
}

template <int Dim>
double DemSystem<Dim>::kinetic_energy() const {
    const Vec* v = grains_.velocity();
    const auto* w = grains_.angular_velocity();
    const double* m = grains_.mass();
    const double* inertia = grains_.inertia();
    return parallel::sum(grains_.size(), 0.0, [&](Index i) {
        double rot;
        if constexpr (Dim == 2) rot = w[i] * w[i];
        else rot = core::norm2(w[i]);
        return 0.5 * m[i] * core::norm2(v[i]) + 0.5 * inertia[i] * rot;
    });
}

template <int Dim>
typename DemSystem<Dim>::Vec DemSystem<Dim>::momentum() const {
    const Vec* v = grains_.velocity();
    const double* m = grains_.mass();
    Vec p = Vec::zero();
    for (int k = 0; k < Dim; ++k) p[k] = parallel::sum(grains_.size(), 0.0, [&](Index i) { return m[i] * v[i][k]; });
    return p;
}

template <int Dim>
void DemSystem<Dim>::save(io::Hdf5Group& group) const {
    auto set = group.create_group("grains");
    grains_.save(set);
    group.write("skin", skin_);
    group.write("forces_ready", std::int64_t{forces_ready_});
    group.write("lists_dirty", std::int64_t{lists_dirty_});
    group.write("history_saved", std::int64_t{history_saved_});
    group.write("steps", counters_.steps);
    group.write("rebuilds", counters_.rebuilds);
    auto history = group.create_group("contact_history");
    history_.write(history);
    // The lists are valid for the current grains unless dirty: they are rebuilt on load from the
    // positions they were built at (sorted and wrapped then), which gives the same rows and order.
    if (!lists_dirty_ && grains_.size() > 0)
        group.write("list_reference_positions", reinterpret_cast<const double*>(list_.reference_positions()),
                    static_cast<std::size_t>(list_.grain_count()), Dim);
}

template <int Dim>
void DemSystem<Dim>::load(const io::Hdf5Group& group) {
    grains_.load(group.open_group("grains"));
    skin_ = group.read_double("skin");
    forces_ready_ = group.read_int("forces_ready") != 0;
    lists_dirty_ = group.read_int("lists_dirty") != 0;
    history_saved_ = group.read_int("history_saved") != 0;
    counters_.steps = group.read_int("steps");
    counters_.rebuilds = group.read_int("rebuilds");
    history_.read(group.open_group("contact_history"));
    drift2_ = -1.0;
    list_ = GrainNeighborList<Dim>();
    cut_pairs();
    if (lists_dirty_ || grains_.size() == 0) return;
    std::size_t rows = 0;
    const auto raw = group.read_doubles("list_reference_positions", Dim, rows);
    const Index n = grains_.size();
    if (rows != static_cast<std::size_t>(n))
        throw io::Hdf5Error(group.path() + "/list_reference_positions: one row per grain expected");
    std::vector<Vec> reference(rows);
    for (std::size_t i = 0; i < rows; ++i)
        for (int k = 0; k < Dim; ++k) reference[i][k] = raw[i * Dim + static_cast<std::size_t>(k)];
    const double rmax = max_over_grains(n, 0.0, [&](Index i) { return grains_.radius()[i]; });
    const auto grid = GrainNeighborList<Dim>::make_grid(parameters_.domain, reference.data(), n, 2.0 * rmax + skin_);
    std::vector<Index> cell_start;
    neighbors::sort_by_cell(grid, reference.data(), n, order_, cell_start);
    for (Index i = 0; i < n; ++i)
        if (order_[static_cast<std::size_t>(i)] != i)
            throw io::Hdf5Error(group.path() + ": the grains are not in the order of their neighbour lists");
    list_.build(grid, cell_start, parameters_.domain, reference.data(), std::as_const(grains_).radius(), n, skin_);
    cut_pairs();
    scratch_.reset(pairs_.upper_size());
}

template class DemSystem<2>;
template class DemSystem<3>;

}  // namespace grit::dem
