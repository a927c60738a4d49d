// The run state: everything a run is at a step boundary, and nothing else. A checkpoint is this state
// plus what each module saves of its own (inlet progress); an MPI sub-domain will be a State with ghosts.
#pragma once

#include <memory>

#include "grit/analysis/erosion_log.hpp"
#include "grit/dem/dem_system.hpp"
#include "grit/domain/halo.hpp"
#include "grit/neighbors/particle_neighbors.hpp"
#include "grit/particles/sph_particles.hpp"
#include "grit/wear/impact_log.hpp"

namespace grit::sim {

/// Simulated time and the step counter. `dt` is the next step's size (the time-step stage sets it at
/// the end of a step; the steps to an output time are shortened, evenly, to land on it: step_toward),
/// `dt_stable` the last stable step before any shortening.
struct Clock {
    double time = 0.0;
    long step = 0;
    double dt = 0.0;
    double dt_stable = 0.0;
};

/// Where the mass went [kg] (per metre of thickness in 2D): in through inlets, out through outlets
/// and the domain's faces, eroded (failed or detached solid particles, solid debris leaving).
struct MassLedger {
    double in = 0.0, out = 0.0, eroded = 0.0;
};

template <int Dim>
struct State {
    /// Fluid, solid and wall particles, sorted by cell at each neighbour-list build; every per-particle
    /// value is a field of its registry (ids, counters).
    particles::SphParticles<Dim> particles;
    /// Their neighbour lists (derived data, but kept with the set: several modules read and invalidate
    /// them, and a checkpoint rebuilds them exactly).
    neighbors::ParticleNeighbors<Dim> neighbors;
    /// The particles' ghosts: which owner each copies and how (a symmetry plane's mirror images, which
    /// its module finds afresh whenever the set changed). A stage that derives a value the sums read of
    /// a ghost (the projection's v*, the solved pressure) forwards it from the owner through this.
    domain::Halo<Dim> ghosts;
    /// The grains with their neighbour lists and tangential contact histories; null without grains.
    std::unique_ptr<dem::DemSystem<Dim>> grains;
    /// First contacts of grains with targets.
    wear::ImpactLog impacts;
    /// Solid particles removed: failed, detached, or carried out through an outlet (eroded.csv; the
    /// solid module writes it).
    analysis::ErosionLog erosion;
    Clock clock;
    MassLedger ledger;
};

}  // namespace grit::sim
