// The solid SPH sums: density rate (first seed paper eq. 28), acceleration with pressure, deviatoric
// stress, artificial viscosity and artificial stress (eq. 29), strain-rate and spin tensors (eq. 31),
// and the specific internal energy rate.
#pragma once

#include <cstdint>
#include <vector>

#include "grit/core/sym_tensor.hpp"
#include "grit/material/solid_model.hpp"
#include "grit/neighbors/neighbor_list.hpp"
#include "grit/particles/sph_particles.hpp"
#include "grit/sph/fluid_rates.hpp"
#include "grit/sph/kernels.hpp"

namespace grit::sph {

/// Per-step scratch of the solid sums (recomputed each step, never sorted).
struct SolidWorkspace {
    std::vector<core::SymTensor3> strain_rate;        ///< eq. (31) [1/s]
    std::vector<material::Spin> spin;                 ///< eq. (31) [1/s]
    std::vector<double> energy_rate;                  ///< de/dt [W/kg]
    std::vector<core::SymTensor3> correction;         ///< kernel gradient correction L (symmetric)
    /// Per neighbour-list entry of a solid particle, from the correction pass for the main pass: the
    /// kernel's gradient factor (dW/dr)/r and the artificial stress weight (W(r)/W(dx))^n.
    std::vector<double> pair_gradient, pair_stress_weight;
    std::vector<std::uint8_t> has_artificial_stress;  ///< R != 0 (a principal stress in tension)
    /// Per solid particle, compact for the pair pass: M = (sigma / rho^2) L (Dim x Dim, row-major) and
    /// the in-plane artificial stress R of Gray et al. (2001) (xx, yy, xy[, zz, yz, zx]).
    std::vector<double> stress_correction, plane_artificial_stress;
};

template <int Dim>
struct SolidRateParameters {
    core::Vec<Dim> gravity = core::Vec<Dim>::zero();
    double artificial_stress = 0.3;  ///< epsilon of Gray et al. (2001); 0 switches it off
    double artificial_stress_exponent = 4.0;  ///< n
    double spacing = 0.0;            ///< dx, for f_ab = W(r)/W(dx)
    std::vector<PairCoefficients> materials;
};

/// Fills density_rate and acceleration of every solid particle (fixed ones too: their acceleration
/// is ignored by the integrator) and the workspace's strain rate, spin and energy rate. Pressure and
/// artificial viscosity act between a solid particle and every neighbour (fluid-solid interaction is
/// SPH interaction); deviatoric stress, artificial stress and the strain rate only between solids.
/// Reads deviatoric_stress from the registry and p/rho^2, m/rho from `sph` (prepare_sph_workspace).
template <int Dim>
void compute_solid_rates(particles::SphParticles<Dim>& particles, const neighbors::NeighborList<Dim>& neighbors,
                         const Kernel<Dim>& kernel, const SolidRateParameters<Dim>& parameters,
                         const SphWorkspace& sph, SolidWorkspace& workspace);

extern template void compute_solid_rates<2>(particles::SphParticles<2>&, const neighbors::NeighborList<2>&,
                                            const Kernel<2>&, const SolidRateParameters<2>&, const SphWorkspace&,
                                            SolidWorkspace&);
extern template void compute_solid_rates<3>(particles::SphParticles<3>&, const neighbors::NeighborList<3>&,
                                            const Kernel<3>&, const SolidRateParameters<3>&, const SphWorkspace&,
                                            SolidWorkspace&);

}  // namespace grit::sph
