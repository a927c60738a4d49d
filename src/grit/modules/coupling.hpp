// The fluid-grain coupling module (first seed paper section 2.5): the porosity of the fluid particles
// and the locally averaged density (eqs. 20-21) before the equation of state, and the force exchange
// of eqs. (42)-(50) between the SPH sums and the grains' step.
#pragma once

#include <cstdint>

#include "grit/coupling/fluid_grain_coupling.hpp"
#include "grit/sim/module.hpp"

namespace grit::modules {

template <int Dim>
class CouplingModule final : public sim::Module<Dim> {
public:
    /// Registers `porosity` on the SPH particles and `fluid_force`, `drag_force` on the grains (which
    /// must exist: the grains module is built first). Throws InputError without a fluid material.
    CouplingModule(sim::State<Dim>& state, const sim::RunSetup<Dim>& setup);

    /// The fluid particles' porosity eps (eq. 20), the field this module registers: what the fluid
    /// solvers read when grains are coupled to them; nullptr in a run without the coupling.
    static constexpr const char* porosity_field = "porosity";
    static const double* porosity(const particles::SphParticles<Dim>& particles) {
        const auto& fields = particles.fields();
        return fields.has(porosity_field) ? fields.template get<double>(porosity_field).data() : nullptr;
    }

    std::string name() const override { return "coupling"; }
    void install(sim::Pipeline& pipeline) override;
    void prime() override { priming_ = true; }
    double stable_time_step() const override { return coupling_.stable_time_step(); }
    void output_values(std::vector<sim::OutputValue>& out) const override;

private:
    /// Pairs and porosity at the positions of this step; fluid particles new to the coupling (the
    /// initial ones, and each one an inlet emits) take the porosity into their mass and density.
    void update_porosity();
    /// The force exchange, after the SPH sums and before the grains' step.
    void exchange();
    /// superficial_velocity, pressure_gradient and bed_porosity of the fixed grains (a packed bed).
    void bed_values(std::vector<sim::OutputValue>& out) const;

    sim::State<Dim>& state_;
    const sim::RunSetup<Dim>& setup_;
    coupling::FluidGrainCoupling<Dim> coupling_;
    core::Vec<Dim> gravity_;
    std::uint64_t pairs_generation_ = 0;  ///< the particle set's generation the pairs were found at
    bool priming_ = false;
};

extern template class CouplingModule<2>;
extern template class CouplingModule<3>;

}  // namespace grit::modules
