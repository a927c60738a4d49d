// Open boundaries: jet inlets that emit fluid, outlets (and, with domain.on_exit = "remove", the
// domain's faces) that remove what enters them, and clamps that hold solid particles at a prescribed
// velocity. Mass in and out goes to the State's ledger (solid debris as eroded mass).
#pragma once

#include <vector>

#include "grit/boundary/jet_inlet.hpp"
#include "grit/sim/module.hpp"

namespace grit::modules {

template <int Dim>
class OpenBoundariesModule final : public sim::Module<Dim> {
public:
    OpenBoundariesModule(sim::State<Dim>& state, const sim::RunSetup<Dim>& setup);

    std::string name() const override { return "open_boundaries"; }
    /// Marks the solid particles inside each clamp box as fixed, at the clamp's velocity.
    void initialise() override;
    void install(sim::Pipeline& pipeline) override;
    /// Each inlet's progress (the distance its last layer has moved).
    void save(io::Hdf5Group& group) const override;
    void load(const io::Hdf5Group& group) override;

private:
    void apply();

    sim::State<Dim>& state_;
    const sim::RunSetup<Dim>& setup_;
    std::vector<boundary::JetInlet<Dim>> inlets_;
};

extern template class OpenBoundariesModule<2>;
extern template class OpenBoundariesModule<3>;

}  // namespace grit::modules
