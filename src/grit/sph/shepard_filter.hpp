// Shepard density filter (second seed paper section 2.1, its ref. [45];
// Colagrossi & Landrini 2003): rho_a <- sum_b m_b W_ab / sum_b (m_b / rho_b)
// W_ab over the particle itself and its fluid neighbours. It smooths the
// high-wavenumber density noise of a disordered fluid and keeps a uniform
// density as it is.
#pragma once

#include <vector>

#include "grit/neighbors/neighbor_list.hpp"
#include "grit/neighbors/periodic_box.hpp"
#include "grit/particles/sph_particles.hpp"
#include "grit/sph/kernels.hpp"

namespace grit::sph {

/// The Shepard density of every fluid particle (others keep theirs) into `out`;
/// a gather loop.
template <int Dim>
void shepard_density(const particles::SphParticles<Dim>& particles, const neighbors::NeighborList<Dim>& neighbors,
                     const Kernel<Dim>& kernel, const neighbors::PeriodicBox<Dim>& box, std::vector<double>& out);

extern template void shepard_density<2>(const particles::SphParticles<2>&, const neighbors::NeighborList<2>&,
                                        const Kernel<2>&, const neighbors::PeriodicBox<2>&, std::vector<double>&);
extern template void shepard_density<3>(const particles::SphParticles<3>&, const neighbors::NeighborList<3>&,
                                        const Kernel<3>&, const neighbors::PeriodicBox<3>&, std::vector<double>&);

}  // namespace grit::sph
