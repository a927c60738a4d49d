// Unresolved fluid-grain coupling (first seed paper section 2.5, eqs. 18-23 and 42-50; second paper
// eqs. 15-21): the porosity of the fluid particles, the force of the fluid on each grain (Shepard-
// interpolated pressure and viscous force plus drag) and its reaction spread back over the fluid
// particles with the same kernel weights, so the exchange conserves momentum to round-off.
//
// Only fluid SPH particles exchange forces with grains: walls and SPH solids meet grains through the
// penalty contact. Wall particles are paired too, to complete a grain's kernel near a wall: they count
// in its immersed fraction and, with their Adami pressure, in -grad p at the grain. SPH solid particles
// are paired for the immersed fraction alone (their pressure is the solid's, not the water's).
// Grain i reaches the fluid particles a within R_c,i = radius_factor d_i with the SPH kernel of
// smoothing length h_c,i = R_c,i / 2 (W_ai below).
#pragma once

#include <cstdint>
#include <vector>

#include "grit/core/types.hpp"
#include "grit/core/vec.hpp"
#include "grit/coupling/drag_laws.hpp"
#include "grit/dem/grain_set.hpp"
#include "grit/neighbors/cross_pairs.hpp"
#include "grit/particles/sph_particles.hpp"
#include "grit/sph/kernels.hpp"

namespace grit::coupling {

/// Settings of the coupling (case keys under [coupling]).
struct CouplingParameters {
    double radius_factor = 2.0;   ///< R_c / d_i (coupling.radius) [-]
    DragLaw drag = DragLaw::gidaspow;
    double min_porosity = 0.2;    ///< floor of eps_a (coupling.min_porosity) [-]
    double fluid_density = 1000.0;  ///< rho_f of the drag laws: the fluid's reference density [kg/m^3]
    double viscosity = 1e-3;        ///< mu_f [Pa s]
};

/// Per-grain results of the last force evaluation.
template <int Dim>
struct GrainCouplingState {
    std::vector<double> shepard;   ///< S_i = sum_a V_a W_ai (eq. 50) [-]
    std::vector<double> porosity;  ///< eps_i (eq. 45) [-]
    std::vector<double> drag_coefficient;  ///< c_i = |F_d| / |u| [kg/s]
};

template <int Dim>
class FluidGrainCoupling {
public:
    using Vec = core::Vec<Dim>;

    FluidGrainCoupling() = default;
    /// `box`: the run's periodic axes (domain.periodic); a grain near a periodic face reaches the fluid
    /// across it, at the nearest image.
    FluidGrainCoupling(CouplingParameters parameters, const sph::Kernel<Dim>& kernel_type,
                       const neighbors::PeriodicBox<Dim>& box = {})
        : parameters_(parameters), kernel_type_(kernel_type), box_(box) {}

    /// Lists the fluid, wall and SPH solid particles within R_c,i of every grain and the weights W_ai, at the
    /// current positions. Valid while neither set changes.
    void find_pairs(const dem::GrainSet<Dim>& grains, const particles::SphParticles<Dim>& particles);

    /// eps_a = max(1 - sum_i V_i W_ai, min_porosity) for fluid particles (eq. 20), 1 for the others.
    void compute_porosity(const dem::GrainSet<Dim>& grains, const particles::SphParticles<Dim>& particles,
                          double* porosity) const;

    /// The fluid force on each grain, F_i = V_i (-grad p + div tau)_i + F_d (eqs. 42-49), added to the
    /// grains' force (and written to fluid_force and drag_force), and its reaction
    /// F_a = -V_a sum_i F_i W_ai / S_i (eq. 50) added to the fluid particles' acceleration as F_a / m_a.
    /// -grad p and div tau = mu lap v are interpolated at the grain in difference forms (docs/theory.md:
    /// the printed eq. 43 averages the particles' accelerations, which carry the kernel truncation
    /// error of free surfaces).
    void exchange_forces(dem::GrainSet<Dim>& grains, particles::SphParticles<Dim>& particles,
                         const double* porosity, Vec* fluid_force, Vec* drag_force);

    /// Largest step for which the explicit drag is stable with a margin of 2: 1 / (largest relaxation
    /// rate), over grains (c_i / m_i) and fluid particles (sum_i c_i W_ai / (S_i rho_bar_a)).
    double stable_time_step() const noexcept { return stable_dt_; }

    std::size_t pair_count() const noexcept { return pairs_.pair_count(); }
    /// How often the candidate pairs (R_c,i plus the skin) were searched for on the grid.
    long candidate_builds() const noexcept { return candidate_builds_; }
    const GrainCouplingState<Dim>& grain_state() const noexcept { return grain_; }
    const CouplingParameters& parameters() const noexcept { return parameters_; }

private:
    CouplingParameters parameters_;
    sph::Kernel<Dim> kernel_type_{sph::CubicSpline<Dim>(1.0)};
    neighbors::PeriodicBox<Dim> box_;
    /// Whether the candidates no longer hold every pair: the particle set or the grains changed, or the
    /// particles and grains moved, between them, as far as the skin since the candidates were found.
    bool candidates_stale(const dem::GrainSet<Dim>& grains, const particles::SphParticles<Dim>& particles) const;

    // The pairs within R_c,i + skin, searched for on a cell grid only when they go stale; each step's pairs
    // are refined from them by the same distance test, so they are those a fresh search would give.
    neighbors::CrossPairList<Dim> candidates_;
    double skin_ = 0.0;
    std::uint64_t candidate_generation_ = ~std::uint64_t{0};  // the particle set's, at the search
    std::vector<Vec> particle_at_search_, grain_at_search_;
    std::vector<domain::ParticleId> grain_ids_at_search_;
    long candidate_builds_ = 0;
    neighbors::CrossPairList<Dim> pairs_;        // grains near each fluid particle (rows by particle)
    std::vector<double> weight_;                 // W_ai, in the order of pairs_
    std::vector<double> reach_;                  // R_c,i per grain
    std::vector<Index> grain_start_, grain_order_;  // pairs of grain i: grain_order_[grain_start_[i] ..]
    std::vector<Index> solid_start_, solid_order_;  // its pairs with SPH solid particles, likewise
    std::vector<Index> pair_particle_;           // particle a of each pair
    GrainCouplingState<Dim> grain_;
    std::vector<Vec> grain_force_;               // F_i of the last exchange
    double stable_dt_ = 1e300;
};

/// Volume of a grain of radius r: pi r^2 per metre in 2D, 4/3 pi r^3 in 3D.
template <int Dim>
constexpr double grain_volume(double radius) noexcept {
    return dem::grain_mass<Dim>(1.0, radius);  // the mass at unit density
}

extern template class FluidGrainCoupling<2>;
extern template class FluidGrainCoupling<3>;

}  // namespace grit::coupling
