// The grains' physics: the grain set, its neighbour lists and contact history, plane and mesh walls, the
// chosen contact law and materials, and the phases of the velocity-Verlet step. A run calls the phases as
// stages of its one pipeline (modules/grains.cpp), on its one clock: the system keeps no time of its own;
// tests and benchmarks call step(), which runs them all.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "grit/core/types.hpp"
#include "grit/core/vec.hpp"
#include "grit/dem/contact_forces.hpp"
#include "grit/dem/contact_history.hpp"
#include "grit/dem/contact_laws.hpp"
#include "grit/dem/grain_material.hpp"
#include "grit/dem/grain_neighbors.hpp"
#include "grit/dem/grain_set.hpp"
#include "grit/dem/mesh_walls.hpp"
#include "grit/dem/plane_wall.hpp"
#include "grit/neighbors/half_lists.hpp"

namespace grit::dem {

/// Settings of a DemSystem.
template <int Dim>
struct DemParameters {
    std::string contact_law = "hertz";            ///< "linear" (first paper) or "hertz" (second paper)
    core::Vec<Dim> gravity = core::Vec<Dim>::zero();  ///< [m/s^2]
    /// Verlet skin [m]; lists hold pairs within R_i + R_j + skin and are rebuilt when a grain has moved
    /// more than skin/2. Negative: 0.2 x the largest diameter at the first build.
    double skin = -1.0;
    GrainDomain<Dim> domain;                       ///< periodic axes and their bounds
    /// Grains touch each other (the pair pass); false: they pass through one another, and their walls,
    /// SPH and coupling forces are all they feel.
    bool grain_pairs = true;
};

/// Counters of the neighbour search and contacts (for benchmarks and diagnostics).
struct DemCounters {
    std::int64_t steps = 0;
    std::int64_t rebuilds = 0;
};

template <int Dim>
class DemSystem {
public:
    using Vec = core::Vec<Dim>;

    /// A system with the given materials (index = position in the vector); walls and grains refer to
    /// materials by index. Throws InputError for an unknown law or an empty material list.
    DemSystem(DemParameters<Dim> parameters, std::vector<GrainMaterial> materials);

    GrainSet<Dim>& grains() noexcept { return grains_; }
    const GrainSet<Dim>& grains() const noexcept { return grains_; }
    const std::vector<GrainMaterial>& materials() const noexcept { return materials_; }
    const std::vector<PlaneWall<Dim>>& walls() const noexcept { return walls_; }
    const ContactLaw& law() const noexcept { return law_; }
    const DemParameters<Dim>& parameters() const noexcept { return parameters_; }
    const DemCounters& counters() const noexcept { return counters_; }
    const GrainNeighborList<Dim>& neighbors() const noexcept { return list_; }
    /// The lists cut into each pair once (partners of higher index): the pairs the contact pass evaluates
    /// and the entries of contact_history().values().
    const neighbors::HalfLists& pairs() const noexcept { return pairs_; }
    const ContactHistory<Dim>& contact_history() const noexcept { return history_; }

    /// Adds one grain of material `material` (index) with the id its source gave it (by origin,
    /// domain/particle_id.hpp) and returns its index (valid until the next step, which may re-sort
    /// grains; use the `id` field to follow a grain).
    Index add_grain(domain::ParticleId id, const Vec& x, double radius, std::int32_t material,
                    const Vec& v = Vec::zero());
    /// The same for a system built by hand (tests, tools): ids in the order grains are added.
    Index add_grain(const Vec& x, double radius, std::int32_t material, const Vec& v = Vec::zero());
    /// Adds a grain during a run (a feed), before the step's force stages: its force starts at its
    /// weight and its contacts enter at the next force stage, while the forces the other grains hold
    /// stay valid (add_grain would have them recomputed, dropping what coupling stages added).
    Index inject_grain(domain::ParticleId id, const Vec& x, double radius, std::int32_t material, const Vec& v);
    /// Adds a plane wall; its history field `wall_history_<k>` joins the grain registry.
    void add_wall(const PlaneWall<Dim>& wall);
    /// Adds a triangle-mesh wall (3D only; InputError in 2D or for a material index out of range).
    void add_mesh(MeshWall wall);
    /// The mesh walls; null when there are none.
    const MeshWalls* meshes() const noexcept { return meshes_.get(); }
    /// Reorders/removes grains (new[i] = old[source[i]]); contact history follows by id.
    void gather(const std::vector<Index>& source);

    /// The phases of a velocity-Verlet step, in the order a run's stages call them. Between
    /// compute_contact_forces and kick, other stages (fluid drag, grain-solid penalty) add to
    /// grains().force()/torque(). `time` is the time at the start of the step (where moving meshes are
    /// placed: at time + dt for the new positions).
    ///
    /// Half kick with the forces held: the second half of the step that computed them.
    void kick(double dt);
    /// First half kick with the forces held (computed first at `time` when no step has: new grains or
    /// walls), then the drift; measures how far the grains moved since their lists were built.
    void drift(double dt, double time);
    /// New lists (grains wrapped and sorted by cell, histories carried over by id) when a grain has moved
    /// more than skin/2 since they were built, or grains came or went.
    void update_neighbors();
    /// force = m g + contacts, torque = contacts at the current lists, the grains at time + dt; the
    /// tangential histories grow by v_t dt.
    void compute_contact_forces(double dt, double time);
    /// One whole step from `time` (tests, benchmarks): drift, update_neighbors, compute_contact_forces
    /// with the second half kick inside the force pass.
    void step(double dt, double time);
    /// The forces of the current state, at `time`: update_neighbors then the force stage (dt = 0
    /// evaluates forces without advancing the histories).
    void compute_forces(double dt, double time);

    /// Largest stable step for the chosen law over all grains: eq. (51) (alpha_tn = 300) for the linear
    /// law; for Hertz, 0.2 of the Rayleigh time and, if impact_speed > 0, 1/50 of the Hertz impact time
    /// at that speed against an equal grain.
    double stable_time_step(double impact_speed = 0.0) const;

    /// Number of grain-grain pairs in contact and of pairs in the neighbour lists (each counted once).
    std::size_t contact_pairs() const;
    std::size_t list_entries() const noexcept { return list_.entry_count(); }

    /// Total kinetic energy (translation + rotation) [J] (per metre of thickness in 2D).
    double kinetic_energy() const;
    /// Total linear momentum [kg m/s] (per metre of thickness in 2D).
    Vec momentum() const;

    /// Writes the grains, the contact history, the lists' reference positions and the step state into
    /// `group`, so that load() continues bit for bit (a checkpoint).
    void save(io::Hdf5Group& group) const;
    /// Reads back what save() wrote, into a system built from the same case (same materials and
    /// walls): grains, history and step state; the lists are rebuilt exactly as they were.
    void load(const io::Hdf5Group& group);

private:
    /// Contact, weight and wall forces at the current lists; with half_kick != 0 the second half kick.
    /// `time`: the time of the grains' positions (where moving meshes are placed).
    void force_stage(double dt, double half_kick, double time);
    void rebuild_neighbors();
    /// Cuts pairs_ from the current lists.
    void cut_pairs();
    double skin() const;

    DemParameters<Dim> parameters_;
    std::vector<GrainMaterial> materials_;
    PairMaterialTable pair_table_;
    ContactLaw law_;
    GrainSet<Dim> grains_;
    std::vector<PlaneWall<Dim>> walls_;
    std::unique_ptr<MeshWalls> meshes_;
    GrainNeighborList<Dim> list_;
    // The lists' rows as HalfLists (each pair once; their blocks go unused: the pair pass runs over
    // blocks_, whole slabs of cells coloured so no grain receives from two blocks at once).
    neighbors::HalfLists pairs_;
    ContactHistory<Dim> history_;
    PairScratch<Dim> scratch_;
    SlabBlocks blocks_;        // the pair pass's blocks over the current lists
    PairImages<Dim> images_;   // each listed pair's periodic image
    std::vector<Index> order_;
    // The largest squared move the last drift measured against the lists' positions; < 0: not measured
    // (lists dirty or built for another set).
    double drift2_ = -1.0;
    double skin_ = -1.0;
    bool forces_ready_ = false;
    bool lists_dirty_ = true;
    bool history_saved_ = false;  // gather() saved it before reordering
    DemCounters counters_;
};

extern template class DemSystem<2>;
extern template class DemSystem<3>;

}  // namespace grit::dem
