// Grain-boundary contact as a module: the penalty contact of grains with SPH solid and wall particles
// (first seed paper eqs. 12-14) at the state the SPH sums saw, forces on both sides, and each grain's
// first contact with a solid or the walls in the impact log.
#pragma once

#include "grit/coupling/grain_boundary_contact.hpp"
#include "grit/sim/module.hpp"

namespace grit::modules {

template <int Dim>
class GrainContactModule final : public sim::Module<Dim> {
public:
    GrainContactModule(sim::State<Dim>& state, const sim::RunSetup<Dim>& setup);

    std::string name() const override { return "grain_contact"; }
    void install(sim::Pipeline& pipeline) override;

private:
    void couple();
    /// Warns (once, at a fresh start) of grains that start in contact with SPH walls or solids.
    void warn_of_grains_starting_in_contact();

    sim::State<Dim>& state_;
    const sim::RunSetup<Dim>& setup_;
    coupling::GrainBoundaryContact<Dim> contact_;
    bool start_checked_ = false;
};

extern template class GrainContactModule<2>;
extern template class GrainContactModule<3>;

}  // namespace grit::modules
