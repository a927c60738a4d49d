// Clusters of particles as labels that sub-domains can exchange: the members of a set (damaged rock for
// the crack count, fractured rock for the fragment test) linked within a distance, each cluster named by
// the smallest particle id in it. Ids are by origin, so every sub-domain names a cluster alike.
#pragma once

#include <cstdint>
#include <vector>

#include "grit/core/types.hpp"
#include "grit/domain/particle_id.hpp"
#include "grit/neighbors/periodic_box.hpp"
#include "grit/particles/sph_particles.hpp"

namespace grit::analysis {

/// Each member's cluster label (member[i] != 0): the smallest id in its cluster, two members linked when
/// their distance is <= link_distance (across a periodic face of `box`, that of the nearest image);
/// -1 for the others. Over a sub-domain, particles [0, owned) are its own and [owned, size) ghosts of
/// other sub-domains' particles within link_distance of its own: pass `ghost_labels` (size - owned
/// values, each ghost's label as its owner computed it at the last exchange; null the first time),
/// exchange the ghosts' labels again and repeat until none changes, and every sub-domain holds the
/// whole set's labels. The result does not depend on the thread count. link_distance must be > 0 and
/// less than half of each period (std::invalid_argument).
template <int Dim>
std::vector<domain::ParticleId> cluster_labels(const particles::SphParticles<Dim>& particles,
                                               const std::vector<std::uint8_t>& member, double link_distance,
                                               Index owned, const domain::ParticleId* ghost_labels = nullptr,
                                               const neighbors::PeriodicBox<Dim>& box = {});

extern template std::vector<domain::ParticleId> cluster_labels<2>(const particles::SphParticles<2>&,
                                                                  const std::vector<std::uint8_t>&, double, Index,
                                                                  const domain::ParticleId*,
                                                                  const neighbors::PeriodicBox<2>&);
extern template std::vector<domain::ParticleId> cluster_labels<3>(const particles::SphParticles<3>&,
                                                                  const std::vector<std::uint8_t>&, double, Index,
                                                                  const domain::ParticleId*,
                                                                  const neighbors::PeriodicBox<3>&);

}  // namespace grit::analysis
