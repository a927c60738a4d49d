// How many particles a case would make and about how much memory they would take, from the shapes of
// its blocks (no lattice is generated), so that a case asking for more than numerics.max_particles
// is refused before anything is allocated.
#pragma once

#include "grit/io/case_spec.hpp"

namespace grit::io {

/// Particle counts of a case (doubles: a tiny spacing gives counts far beyond any integer type): the most
/// that exist at once, which is what the memory and the cost of a step follow.
struct ParticleEstimate {
    double sph = 0.0;          ///< fluid, solid and wall particles plus `inlets_held`
    double inlets = 0.0;       ///< every particle the inlets emit by time.end
    double inlets_held = 0.0;  ///< the most of `inlets` in the domain at once (its room the blocks leave)
    double grains_fed = 0.0;   ///< every grain the abrasive and the grain feeds insert by time.end
    double grains = 0.0;       ///< DEM grains at once: the blocks' plus `grains_fed`, at most the domain's room
    /// What a run holds at a time, for the time estimate rather than the memory bound: where outlets drain
    /// the domain, an inlet holds about what it emits while a particle crosses the domain's diagonal at its
    /// speed, and the abrasive one grain per `abrasive.spacing` of that diagonal; without outlets, or
    /// without a domain box, `inlets_held` and `grains`.
    double inlets_in_flight = 0.0;
    double grains_in_flight = 0.0;
    double bytes = 0.0;        ///< memory of both, fields and neighbour lists (an estimate, see the .cpp)
    double total() const { return sph + grains; }
};

/// Room for particles of spacing dx in the domain box: 10 % above its lattice points (water compressed by
/// a jet's impact holds a little more). What inlets emit beyond it has left through outlets or the
/// domain's faces: a jet run for milliseconds holds a few thousand particles, not the millions it emits.
double domain_particle_room(const CaseSpec& c);

/// Length of the domain box's diagonal [m]; infinity without a domain box.
double domain_diagonal(const CaseSpec& c);

/// Room for grains of diameter d in the domain box: its volume over d^Dim, times 1.5 (above the densest
/// packing of discs, 1.155, and of spheres, 1.414).
double domain_grain_room(const CaseSpec& c, double d);

/// Upper bound of the lattice points (spacing dx) that `shape` holds in `dim` dimensions: exact for
/// boxes, a little above the count for discs, spheres, cylinders and tanks.
double shape_particle_bound(const ShapeSpec& shape, int dim, double dx);

/// The counts of `c`'s blocks, inlets and grains.
ParticleEstimate estimate_particles(const CaseSpec& c);

/// Throws core::InputError naming numerics.particle_spacing (or the grains block that makes the most)
/// and numerics.max_particles when the estimate exceeds c.max_particles.
void check_particle_budget(const CaseSpec& c);

/// Fewest particles across a fluid or solid body (its thinnest side) that the SPH sums can resolve: the
/// kernel's support is 2.5 spacings, so a thinner body has no particle with a full neighbourhood.
inline constexpr double min_particles_across = 3.0;

/// Throws core::InputError naming numerics.particle_spacing, the block and the unit when a fluid or
/// solid block is fewer than min_particles_across spacings across: most often a spacing, or a block,
/// given in millimetres.
void check_resolution(const CaseSpec& c);

}  // namespace grit::io
