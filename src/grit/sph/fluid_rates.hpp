// The fluid SPH sums: density rate (continuity, first seed paper eq. 22) and acceleration (momentum,
// eq. 23) with Monaghan artificial viscosity (eqs. 26-27), laminar viscosity (eq. 25), optional
// density diffusion (delta-SPH) and gravity.
#pragma once

#include <vector>

#include "grit/core/vec.hpp"
#include "grit/neighbors/half_lists.hpp"
#include "grit/neighbors/neighbor_list.hpp"
#include "grit/neighbors/periodic_box.hpp"
#include "grit/particles/sph_particles.hpp"
#include "grit/sph/kernel_correction.hpp"
#include "grit/sph/kernels.hpp"
#include "grit/sph/pair_coefficients.hpp"

namespace grit::sph {


template <int Dim>
struct FluidRateParameters {
    core::Vec<Dim> gravity = core::Vec<Dim>::zero();  ///< [m/s^2]
    /// The part of gravity a hydrostatic pressure balances, for the hydrostatic correction of the density
    /// diffusion: gravity without its components along periodic axes.
    core::Vec<Dim> hydrostatic_gravity = core::Vec<Dim>::zero();
    /// Periodic axes: pairs across a face are listed, and x_a - x_b is taken to its nearest image.
    neighbors::PeriodicBox<Dim> periodic_box;
    /// delta of the density-diffusion term (Molteni & Colagrossi 2009 with the hydrostatic correction
    /// of Fourtakas et al. 2019); 0 switches it off.
    double density_diffusion = 0.0;
    std::vector<PairCoefficients> materials;
};

/// Per-step scratch of the SPH sums (recomputed each step, never sorted): p/rho^2 and m/rho of each
/// particle, so the pair loop divides as little as possible.
struct SphWorkspace {
    std::vector<double> pressure_term;
    std::vector<double> volume;
};

/// A fluid particle's sums over its pairs (sum_pairs_once).
template <int Dim>
struct FluidSum {
    double dv[Dim];     ///< acceleration less gravity [m/s^2]
    double continuity;  ///< sum_b V_b v_ab . grad_a W_ab [1/s]
    double diffusion;   ///< the density-diffusion sum, before its factor 2 delta h c0
    FluidSum& operator+=(const FluidSum& o) noexcept {
        for (int d = 0; d < Dim; ++d) dv[d] += o.dv[d];
        continuity += o.continuity;
        diffusion += o.diffusion;
        return *this;
    }
};

/// What the fluid sums keep between steps to evaluate each fluid-fluid pair once: the half lists
/// (cut again when the neighbour lists change) and the per-particle sums.
template <int Dim>
struct FluidPairs {
    neighbors::HalfLists lists;
    std::vector<FluidSum<Dim>> own, spill;
};

/// Fills the workspace for this step: p/rho^2 and m/rho of every particle.
template <int Dim>
void prepare_sph_workspace(const particles::SphParticles<Dim>& particles, SphWorkspace& workspace);

/// Fills density_rate and acceleration of every fluid particle from its neighbours (fluid, wall and
/// solid particles). Each fluid-fluid pair is evaluated once, into sums whose order the lists fix
/// (neighbors::sum_pairs_once: the same at any thread count); with the kernel-gradient correction
/// (its two gradients per pair differ) the gather form, each particle over its whole list.
///
/// The densities read are the locally averaged densities rho_bar = porosity * rho of eq. (22); without
/// grains (`porosity` null) the porosity is 1 and rho_bar is the particle density.
/// `correction`: the kernel-gradient correction L_a of each particle (numerics.kernel_correction), or null.
template <int Dim>
void compute_fluid_rates(particles::SphParticles<Dim>& particles, const neighbors::NeighborList<Dim>& neighbors,
                         const Kernel<Dim>& kernel, const FluidRateParameters<Dim>& parameters,
                         const SphWorkspace& workspace, FluidPairs<Dim>& pairs, const double* porosity = nullptr,
                         const GradientCorrection<Dim>* correction = nullptr);

extern template void prepare_sph_workspace<2>(const particles::SphParticles<2>&, SphWorkspace&);
extern template void prepare_sph_workspace<3>(const particles::SphParticles<3>&, SphWorkspace&);
extern template void compute_fluid_rates<2>(particles::SphParticles<2>&, const neighbors::NeighborList<2>&,
                                            const Kernel<2>&, const FluidRateParameters<2>&, const SphWorkspace&,
                                            FluidPairs<2>&, const double*, const GradientCorrection<2>*);
extern template void compute_fluid_rates<3>(particles::SphParticles<3>&, const neighbors::NeighborList<3>&,
                                            const Kernel<3>&, const FluidRateParameters<3>&, const SphWorkspace&,
                                            FluidPairs<3>&, const double*, const GradientCorrection<3>*);

}  // namespace grit::sph
