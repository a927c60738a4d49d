// The incompressible SPH module (fluid.solver = "isph"): neighbour lists, the
// projection step of Cummins & Rudman (1999) (second seed paper eq. 6), the
// velocity CFL time step. It replaces the SPH module for a case of fluid and
// wall particles, with or without grains (coupled or not); the pressure comes
// from a Poisson equation, not from an equation of state, so the step is not
// bound to a sound speed.
#pragma once

#include <vector>

#include "grit/sim/module.hpp"
#include "grit/sph/fluid_rates.hpp"
#include "grit/sph/particle_shifting.hpp"
#include "grit/sph/pressure_poisson.hpp"

namespace grit::modules {

template <int Dim>
class IsphModule final : public sim::Module<Dim> {
  public:
    IsphModule(sim::State<Dim>& state, const sim::RunSetup<Dim>& setup);

    std::string name() const override { return "isph"; }
    void install(sim::Pipeline& pipeline) override;
    void initialise() override;
    void prime() override;
    double stable_time_step() const override;
    std::string check_health() const override;
    void output_values(std::vector<sim::OutputValue>& out) const override;
    /// The solve counters behind the summary's means, the last solve's figures and the relaxation time
    /// of the next projection (a step cut for an output time leaves it longer than the step).
    void save(io::Hdf5Group& group) const override;
    void load(const io::Hdf5Group& group) override;

  private:
    void update_neighbors(bool force);
    void prepare();
    void predict();
    void project();
    void integrate();
    /// The coupling module's field: the fluid's porosity when grains are coupled to it, else nullptr.
    const double* porosity() const;

    sim::State<Dim>& state_;
    const sim::RunSetup<Dim>& setup_;
    sph::FluidRateParameters<Dim> viscous_;  ///< the fluid sums without pressure: gravity and viscosity
    sph::ProjectionSettings<Dim> projection_settings_;
    sph::PressureProjection<Dim> projection_;
    sph::ShiftingSettings<Dim> shifting_;
    sph::SphWorkspace workspace_;
    sph::FluidPairs<Dim> pairs_;  ///< each fluid-fluid pair once: half lists and sums
    std::vector<sph::GradientCorrection<Dim>> correction_;  ///< L_a (numerics.kernel_correction), else empty
    std::vector<core::Vec<Dim>> v_star_, pressure_acc_, shift_;
    std::vector<double> av_limit_;  ///< per material: 0.125 h^2 / nu of its
                                    ///< artificial viscosity [s]
    sph::ProjectionResult last_;
    long solves_ = 0;
    long restarts_ = 0;  ///< solves BiCGSTAB restarted from p = 0 after a breakdown
    double iterations_total_ = 0.0;
    std::string failure_;
    /// The longest time over which the carried divergence and the density invariance act, from the
    /// last check of the step: the fluid's own step [s]
    mutable double relaxation_dt_ = 0.0;
};

extern template class IsphModule<2>;
extern template class IsphModule<3>;

}  // namespace grit::modules
