// The abrasive feed module: grains enter the jet during the run, one per liquid column of length
// y_dis (first seed paper Fig. 9, eqs. 54-55; [abrasive] in a case file). They join the grains module's
// set at the boundaries stage, after the inlets have emitted their water, so the coupling sees them in
// the same step.
#pragma once

#include "grit/boundary/abrasive_inlet.hpp"
#include "grit/sim/module.hpp"

namespace grit::modules {

template <int Dim>
class AbrasiveFeedModule final : public sim::Module<Dim> {
public:
    /// The grains module must exist (state.grains).
    AbrasiveFeedModule(sim::State<Dim>& state, const sim::RunSetup<Dim>& setup);

    std::string name() const override { return "abrasive_feed"; }
    void install(sim::Pipeline& pipeline) override;
    /// grains_injected; abrasive_mass_flow_rate, abrasive_spacing and abrasive_volume_fraction (summary).
    void output_values(std::vector<sim::OutputValue>& out) const override;
    /// The next column's index (the draws are keyed by column) and the count injected.
    void save(io::Hdf5Group& group) const override;
    void load(const io::Hdf5Group& group) override;

private:
    void feed();

    sim::State<Dim>& state_;
    const sim::RunSetup<Dim>& setup_;
    boundary::AbrasiveInlet<Dim> inlet_;
    std::int64_t injected_ = 0;
};

extern template class AbrasiveFeedModule<2>;
extern template class AbrasiveFeedModule<3>;

}  // namespace grit::modules
