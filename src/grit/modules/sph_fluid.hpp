// The SPH module: the leap-frog integrator of fluid and solid particles, their neighbour lists, the
// fluid's equation of state, the wall pressure, the fluid sums and the CFL time step (eq. 51).
#pragma once

#include <vector>

#include "grit/sim/module.hpp"
#include "grit/sph/fluid_rates.hpp"

namespace grit::modules {

template <int Dim>
class SphModule final : public sim::Module<Dim> {
public:
    SphModule(sim::State<Dim>& state, const sim::RunSetup<Dim>& setup);

    std::string name() const override { return "sph"; }
    void install(sim::Pipeline& pipeline) override;
    void prime() override;
    double stable_time_step() const override;

    /// p/rho^2 and m/rho of every particle for this step (the solid sums read them too), valid while
    /// the particle set is unchanged since the sph_prepare stage.
    const sph::SphWorkspace& workspace() const;
    /// The pair coefficients of each material (sound speed, density, viscosities).
    const std::vector<sph::PairCoefficients>& pair_coefficients() const { return fluid_.materials; }

private:
    void integrate_predict();
    void integrate_update();
    void update_neighbors(bool force);
    /// Every numerics.shepard_interval steps: the whole-step density to its Shepard average, and the
    /// half-step density by the same change (the leap-frog carries rho^(n+1/2)).
    void shepard_filter();
    /// The fluid particles' porosity when grains are coupled to the fluid, else nullptr.
    const double* porosity() const;

    sim::State<Dim>& state_;
    const sim::RunSetup<Dim>& setup_;
    sph::FluidRateParameters<Dim> fluid_;
    std::vector<double> signal_speed_;  ///< per material: the wave speed of the CFL condition [m/s]
    sph::SphWorkspace workspace_;
    sph::FluidPairs<Dim> pairs_;  ///< each fluid-fluid pair once: half lists and sums
    std::uint64_t workspace_generation_ = 0;
    std::vector<sph::GradientCorrection<Dim>> correction_;  ///< L_a (numerics.kernel_correction), else empty
    std::vector<double> shepard_;                            ///< scratch of the Shepard filter
};

extern template class SphModule<2>;
extern template class SphModule<3>;

}  // namespace grit::modules
