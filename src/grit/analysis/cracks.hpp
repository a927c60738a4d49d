// Crack analysis of brittle (JH-2) solids: damaged volume, and clusters of damaged particles counted as
// cracks, so that the first seed paper's radial and lateral cracks are counted rather than eyeballed.
#pragma once

#include <map>
#include <vector>

#include "grit/core/types.hpp"
#include "grit/domain/particle_id.hpp"
#include "grit/neighbors/periodic_box.hpp"
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
/// two particles linked when their distance is <= link_distance (across a periodic face of `box`, that
/// of the nearest image). `damage` is the per-particle "damage" field. The result does not depend on the
/// thread count. Throws core::InputError if link_distance <= 0, or if it is not less than half a period.
template <int Dim>
CrackMeasures analyse_cracks(const particles::SphParticles<Dim>& particles, const double* damage,
                             const CrackOptions& options, const neighbors::PeriodicBox<Dim>& box = {});

/// Each particle's crack label: the smallest id in its cluster of damaged particles (-1: not damaged). An
/// id does not depend on where a particle is stored or how the set is split, so the labels are the same
/// whoever computes them. Over a sub-domain, particles [0, owned) are its own and [owned, size) ghosts of
/// other sub-domains' particles within link_distance of its own; a cluster that crosses the boundary is
/// joined through them: pass `ghost_labels` (size - owned values: each ghost's label as its owner
/// computed it at the last exchange; null the first time), exchange the labels of the ghosts again and
/// repeat until none changes, and every sub-domain holds the whole set's labels. Symmetry-plane images
/// are left out (-1). Along the periodic axes of `box` a cluster closes across the face: the damaged
/// particles near a face are linked to those near the other face by their periodic images. Throws
/// core::InputError if link_distance <= 0, or if it is not less than half a period.
template <int Dim>
std::vector<domain::ParticleId> crack_labels(const particles::SphParticles<Dim>& particles, const double* damage,
                                             const CrackOptions& options, Index owned,
                                             const domain::ParticleId* ghost_labels = nullptr,
                                             const neighbors::PeriodicBox<Dim>& box = {});

/// How many of the particles [0, owned) carry each crack label (one sub-domain's share; sub-domains add
/// their shares label by label).
std::map<domain::ParticleId, Index> crack_sizes(const std::vector<domain::ParticleId>& labels, Index owned);

/// crack_count and largest_crack of the members per label over every sub-domain.
void count_cracks(const std::map<domain::ParticleId, Index>& sizes, const CrackOptions& options, CrackMeasures& out);

extern template std::vector<domain::ParticleId> crack_labels<2>(const particles::SphParticles<2>&, const double*,
                                                                const CrackOptions&, Index, const domain::ParticleId*,
                                                                const neighbors::PeriodicBox<2>&);
extern template std::vector<domain::ParticleId> crack_labels<3>(const particles::SphParticles<3>&, const double*,
                                                                const CrackOptions&, Index, const domain::ParticleId*,
                                                                const neighbors::PeriodicBox<3>&);
extern template CrackMeasures analyse_cracks<2>(const particles::SphParticles<2>&, const double*, const CrackOptions&,
                                                const neighbors::PeriodicBox<2>&);
extern template CrackMeasures analyse_cracks<3>(const particles::SphParticles<3>&, const double*, const CrackOptions&,
                                                const neighbors::PeriodicBox<3>&);

}  // namespace grit::analysis
