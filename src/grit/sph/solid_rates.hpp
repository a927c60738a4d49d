// The solid SPH sums: density rate (first seed paper eq. 28), acceleration with pressure, deviatoric
// stress, artificial viscosity and artificial stress (eq. 29), strain-rate and spin tensors (eq. 31),
// and the specific internal energy rate.
#pragma once

#include <cstdint>
#include <vector>

#include "grit/core/sym_tensor.hpp"
#include "grit/material/solid_model.hpp"
#include "grit/neighbors/half_lists.hpp"
#include "grit/neighbors/neighbor_list.hpp"
#include "grit/neighbors/periodic_box.hpp"
#include "grit/particles/sph_particles.hpp"
#include "grit/sph/fluid_rates.hpp"
#include "grit/sph/kernels.hpp"

namespace grit::sph {

/// A solid particle's sums over its pairs (neighbors::sum_pairs_once).
template <int Dim>
struct SolidSum {
    core::Vec<Dim> dv;           ///< acceleration less gravity [m/s^2]
    double continuity;           ///< sum over wall neighbours of V_b v_ab . grad W [1/s]
    core::SymTensor3 grad_v;     ///< strain rate, eq. (31) [1/s]
    material::Spin spin;         ///< spin, eq. (31) [1/s]
    double work;                 ///< de/dt [W/kg]
    SolidSum& operator+=(const SolidSum& o) noexcept {
        dv += o.dv;
        continuity += o.continuity;
        grad_v += o.grad_v;
        spin.xy += o.spin.xy;
        spin.yz += o.spin.yz;
        spin.zx += o.spin.zx;
        work += o.work;
        return *this;
    }
};

/// A solid particle's kernel moment sum_b V_b f x_ab (x) x_ab over solid neighbours (upper triangle).
template <int Dim>
struct MomentSum {
    double m[Dim * (Dim + 1) / 2];
    MomentSum& operator+=(const MomentSum& o) noexcept {
        for (int e = 0; e < Dim * (Dim + 1) / 2; ++e) m[e] += o.m[e];
        return *this;
    }
};

/// Scratch of the solid sums: per step (recomputed each step, never sorted), and the half lists that
/// let each solid-solid pair be evaluated once (cut again when the neighbour lists change).
template <int Dim>
struct SolidWorkspace {
    std::vector<core::SymTensor3> strain_rate;        ///< eq. (31) [1/s]
    std::vector<material::Spin> spin;                 ///< eq. (31) [1/s]
    std::vector<double> energy_rate;                  ///< de/dt [W/kg]
    std::vector<core::SymTensor3> correction;         ///< kernel gradient correction L (symmetric)
    neighbors::HalfLists lists;                       ///< solid pairs once, fluid and wall neighbours
    /// Per half-list entry, from the correction pass for the main pass: the kernel's gradient factor
    /// (dW/dr)/r, and between solids the artificial stress weight (W(r)/W(dx))^n.
    std::vector<double> upper_gradient, upper_stress_weight, other_gradient;
    std::vector<std::uint8_t> has_artificial_stress;  ///< R != 0 (a principal stress in tension)
    /// Per solid particle, compact for the pair pass: M = (sigma / rho^2) L (Dim x Dim, row-major) and
    /// the in-plane artificial stress R of Gray et al. (2001) (xx, yy, xy[, zz, yz, zx]).
    std::vector<double> stress_correction, plane_artificial_stress;
    std::vector<MomentSum<Dim>> moment_own, moment_spill;  ///< the correction pass's sums
    std::vector<SolidSum<Dim>> own, spill;                 ///< the main pass's sums
};

template <int Dim>
struct SolidRateParameters {
    core::Vec<Dim> gravity = core::Vec<Dim>::zero();
    double artificial_stress = 0.3;  ///< epsilon of Gray et al. (2001); 0 switches it off
    double artificial_stress_exponent = 4.0;  ///< n
    double spacing = 0.0;            ///< dx, for f_ab = W(r)/W(dx)
    std::vector<PairCoefficients> materials;
    neighbors::PeriodicBox<Dim> periodic_box;  ///< pairs across a periodic face by their nearest image
};

/// Fills density_rate and acceleration of every solid particle (fixed ones too: their acceleration
/// is ignored by the integrator) and the workspace's strain rate, spin and energy rate. Pressure and
/// artificial viscosity act between a solid particle and every neighbour (fluid-solid interaction is
/// SPH interaction); deviatoric stress, artificial stress and the strain rate only between solids.
/// Reads deviatoric_stress from the registry and p/rho^2, m/rho from `sph` (prepare_sph_workspace).
template <int Dim>
void compute_solid_rates(particles::SphParticles<Dim>& particles, const neighbors::NeighborList<Dim>& neighbors,
                         const Kernel<Dim>& kernel, const SolidRateParameters<Dim>& parameters,
                         const SphWorkspace& sph, SolidWorkspace<Dim>& workspace);

extern template void compute_solid_rates<2>(particles::SphParticles<2>&, const neighbors::NeighborList<2>&,
                                            const Kernel<2>&, const SolidRateParameters<2>&, const SphWorkspace&,
                                            SolidWorkspace<2>&);
extern template void compute_solid_rates<3>(particles::SphParticles<3>&, const neighbors::NeighborList<3>&,
                                            const Kernel<3>&, const SolidRateParameters<3>&, const SphWorkspace&,
                                            SolidWorkspace<3>&);

}  // namespace grit::sph
