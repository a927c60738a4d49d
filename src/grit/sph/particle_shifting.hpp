// Particle shifting for incompressible SPH (Lind et al. 2012, J. Comput. Phys. 231:1499; Skillen et
// al. 2013): a divergence-free projection moves particles along streamlines, where they cluster and
// open voids until the pressure sums fail. Each step every fluid particle moves down its concentration
// gradient, dr_a = -D grad C_a with D = A h |v_a| dt and grad C_a = sum_b V_b (1 + R (W_ab / W(dx))^n)
// grad_a W_ab (R = 0.2, n = 4: the term that keeps pairs apart), at most 0.2 dx a step. On the free
// surface and within a kernel of it only the tangential part is kept (the truncated kernel would push
// particles out of the fluid). The velocity follows to the new place to first order, v += (dr . grad) v.
#pragma once

#include <cstdint>
#include <vector>

#include "grit/core/vec.hpp"
#include "grit/neighbors/neighbor_list.hpp"
#include "grit/neighbors/periodic_box.hpp"
#include "grit/particles/sph_particles.hpp"
#include "grit/sph/kernels.hpp"

namespace grit::sph {

template <int Dim>
struct ShiftingSettings {
    double coefficient = 2.0;  ///< A of D = A h |v| dt (Lind et al. 2012)
    double spacing = 0.0;      ///< dx [m]: W(dx) of the anti-pairing term and the 0.2 dx cap
    neighbors::PeriodicBox<Dim> periodic_box;
};

/// Shifts the fluid particles and corrects their velocity (and velocity_half) in place; the walls stay.
/// `free_surface` flags the surface particles (1), `shift` is the caller's storage for dr.
template <int Dim>
void shift_particles(particles::SphParticles<Dim>& particles, const neighbors::NeighborList<Dim>& neighbors,
                     const Kernel<Dim>& kernel, const ShiftingSettings<Dim>& settings, double dt,
                     const std::int32_t* free_surface, std::vector<core::Vec<Dim>>& shift);

extern template void shift_particles<2>(particles::SphParticles<2>&, const neighbors::NeighborList<2>&,
                                        const Kernel<2>&, const ShiftingSettings<2>&, double, const std::int32_t*,
                                        std::vector<core::Vec<2>>&);
extern template void shift_particles<3>(particles::SphParticles<3>&, const neighbors::NeighborList<3>&,
                                        const Kernel<3>&, const ShiftingSettings<3>&, double, const std::int32_t*,
                                        std::vector<core::Vec<3>>&);

}  // namespace grit::sph
