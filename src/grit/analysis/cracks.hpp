// Crack analysis of brittle (JH-2) solids: damaged volume, and clusters of damaged particles counted as
// cracks, so that the first seed paper's radial and lateral cracks are counted rather than eyeballed.
#pragma once

#include "grit/core/types.hpp"
#include "grit/particles/sph_particles.hpp"

namespace grit::analysis {

/// What counts as damaged and which damaged particles belong to one crack.
struct CrackOptions {
    double damage_threshold = 0.5;  ///< a solid particle with D >= this is damaged [-]
    double link_distance = 0.0;     ///< two damaged particles closer than this are in the same crack [m]
    Index min_particles = 3;        ///< clusters smaller than this are not counted as cracks
};

struct CrackMeasures {
    double damaged_area = 0.0;   ///< sum of m/rho of damaged solid particles [m^2 per metre of thickness in 2D; m^3 in 3D]
    Index damaged_particles = 0;
    Index crack_count = 0;       ///< connected clusters of damaged particles with >= min_particles members
    Index largest_crack = 0;     ///< particles in the largest cluster
};

/// Damaged solid particles (phase solid, damage[i] >= damage_threshold) and their connected clusters,
/// two particles linked when their distance is <= link_distance. `damage` is the per-particle "damage"
/// field. The result does not depend on the thread count. Throws core::InputError if link_distance <= 0.
template <int Dim>
CrackMeasures analyse_cracks(const particles::SphParticles<Dim>& particles, const double* damage,
                             const CrackOptions& options);

extern template CrackMeasures analyse_cracks<2>(const particles::SphParticles<2>&, const double*, const CrackOptions&);
extern template CrackMeasures analyse_cracks<3>(const particles::SphParticles<3>&, const double*, const CrackOptions&);

}  // namespace grit::analysis
