// Fixed wall (dummy) particles: pressure extrapolated from the fluid (Adami, Hu & Adams 2012), density
// from the inverse equation of state, so that walls push back exactly as much as the fluid presses.
#pragma once

#include <vector>

#include "grit/core/vec.hpp"
#include "grit/material/material.hpp"
#include "grit/neighbors/neighbor_list.hpp"
#include "grit/neighbors/periodic_box.hpp"
#include "grit/particles/sph_particles.hpp"
#include "grit/sph/kernels.hpp"

namespace grit::boundary {

/// For each wall particle w:
///   p_w = [sum_f p_f W_wf + g . sum_f rho_f x_wf W_wf] / sum_f W_wf,  x_wf = x_w - x_f,
/// limited to p_w >= 0 so that walls never pull fluid towards them (no sticking); with no fluid
/// neighbour p_w = 0. Then rho_w = EOS^-1(p_w) of the wall's material. Walls are at rest (a_w = 0).
/// Along the periodic axes of `box`, x_wf is the nearest image.
template <int Dim>
void update_wall_pressure(particles::SphParticles<Dim>& particles, const neighbors::NeighborList<Dim>& neighbors,
                          const sph::Kernel<Dim>& kernel, const core::Vec<Dim>& gravity,
                          const std::vector<material::Material>& materials,
                          const neighbors::PeriodicBox<Dim>& box = {});

extern template void update_wall_pressure<2>(particles::SphParticles<2>&, const neighbors::NeighborList<2>&,
                                             const sph::Kernel<2>&, const core::Vec<2>&,
                                             const std::vector<material::Material>&,
                                             const neighbors::PeriodicBox<2>&);
extern template void update_wall_pressure<3>(particles::SphParticles<3>&, const neighbors::NeighborList<3>&,
                                             const sph::Kernel<3>&, const core::Vec<3>&,
                                             const std::vector<material::Material>&,
                                             const neighbors::PeriodicBox<3>&);

}  // namespace grit::boundary
