// The brittle solid's fragments (modules/sph_solid): fractured rock (a solid particle with damage >= 1)
// stays while it belongs to the specimen and goes once it is part of a fragment, a cluster of fractured
// particles linked within a distance of which no member touches intact rock (damage < 1). A local pass
// and a combine: the clusters are exchangeable labels (analysis/clusters), each sub-domain finds which of
// its labels are anchored by its own particles, and a label anchored anywhere is anchored everywhere.
#pragma once

#include <vector>

#include "grit/core/types.hpp"
#include "grit/domain/particle_id.hpp"
#include "grit/neighbors/neighbor_list.hpp"
#include "grit/neighbors/periodic_box.hpp"
#include "grit/particles/sph_particles.hpp"

namespace grit::analysis {

/// Each fractured solid particle's fragment label (-1 for the others), as analysis::cluster_labels over
/// the fractured particles, linked within `link` (nearest and diagonal neighbours: 1.5 spacings). A
/// symmetry plane's images are members: a fragment that reaches the plane joins its mirror image, as the
/// whole set-up's would.
template <int Dim>
std::vector<domain::ParticleId> fragment_labels(const particles::SphParticles<Dim>& particles, const double* damage,
                                                double link, Index owned,
                                                const domain::ParticleId* ghost_labels = nullptr,
                                                const neighbors::PeriodicBox<Dim>& box = {});

/// The labels (sorted, each once) of the fragments that particles [0, owned) anchor: a fractured particle
/// with an intact solid neighbour within `link` (from `list`, which holds every pair within it). A
/// path from fractured rock to intact rock runs through fractured particles and ends in one
/// fractured-intact link, so this needs no clustering of the intact rock. Sub-domains unite their lists.
template <int Dim>
std::vector<domain::ParticleId> anchored_fragments(const particles::SphParticles<Dim>& particles, const double* damage,
                                                   const std::vector<domain::ParticleId>& labels,
                                                   const neighbors::NeighborList<Dim>& list, double link, Index owned,
                                                   const neighbors::PeriodicBox<Dim>& box = {});

extern template std::vector<domain::ParticleId> fragment_labels<2>(const particles::SphParticles<2>&, const double*,
                                                                   double, Index, const domain::ParticleId*,
                                                                   const neighbors::PeriodicBox<2>&);
extern template std::vector<domain::ParticleId> fragment_labels<3>(const particles::SphParticles<3>&, const double*,
                                                                   double, Index, const domain::ParticleId*,
                                                                   const neighbors::PeriodicBox<3>&);
extern template std::vector<domain::ParticleId> anchored_fragments<2>(const particles::SphParticles<2>&, const double*,
                                                                      const std::vector<domain::ParticleId>&,
                                                                      const neighbors::NeighborList<2>&, double, Index,
                                                                      const neighbors::PeriodicBox<2>&);
extern template std::vector<domain::ParticleId> anchored_fragments<3>(const particles::SphParticles<3>&, const double*,
                                                                      const std::vector<domain::ParticleId>&,
                                                                      const neighbors::NeighborList<3>&, double, Index,
                                                                      const neighbors::PeriodicBox<3>&);

}  // namespace grit::analysis
