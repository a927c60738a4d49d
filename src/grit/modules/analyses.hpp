// The analyses as modules: the crater of an eroded surface (crater.csv, crater_depth, crater_width),
// the cracks of a brittle solid (damaged_area, crack_count), the fluid enclosed by solids
// (fluid_in_solid) and the probes (one column each). They read the state at output times and add no
// stage to the step.
#pragma once

#include "grit/sim/module.hpp"

namespace grit::modules {

template <int Dim>
class CraterModule final : public sim::Module<Dim> {
public:
    CraterModule(const sim::State<Dim>& state, const sim::RunSetup<Dim>& setup) : state_(state), setup_(setup) {}
    std::string name() const override { return "crater"; }
    void install(sim::Pipeline&) override {}
    void output_values(std::vector<sim::OutputValue>& out) const override;
    /// crater.csv: the surface profile at the output time (x, surface, time), rewritten each output.
    void write_output(const sim::OutputPlace& place) override;

private:
    const sim::State<Dim>& state_;
    const sim::RunSetup<Dim>& setup_;
};

template <int Dim>
class CracksModule final : public sim::Module<Dim> {
public:
    CracksModule(const sim::State<Dim>& state, const sim::RunSetup<Dim>& setup) : state_(state), setup_(setup) {}
    std::string name() const override { return "cracks"; }
    void install(sim::Pipeline&) override {}
    void output_values(std::vector<sim::OutputValue>& out) const override;

private:
    const sim::State<Dim>& state_;
    const sim::RunSetup<Dim>& setup_;
};

/// fluid_in_solid: the fluid particles a solid encloses (analysis::count_fluid_in_solids within the kernel
/// support) at each output, zero while the interface holds.
template <int Dim>
class FluidInSolidModule final : public sim::Module<Dim> {
public:
    FluidInSolidModule(const sim::State<Dim>& state, const sim::RunSetup<Dim>& setup) : state_(state), setup_(setup) {}
    std::string name() const override { return "fluid_in_solid"; }
    void install(sim::Pipeline&) override {}
    void output_values(std::vector<sim::OutputValue>& out) const override;

private:
    const sim::State<Dim>& state_;
    const sim::RunSetup<Dim>& setup_;
};

template <int Dim>
class ProbesModule final : public sim::Module<Dim> {
public:
    ProbesModule(const sim::State<Dim>& state, const sim::RunSetup<Dim>& setup) : state_(state), setup_(setup) {}
    std::string name() const override { return "probes"; }
    void install(sim::Pipeline&) override {}
    void output_values(std::vector<sim::OutputValue>& out) const override;
    /// The value of probe k now.
    double value(std::size_t k) const;

private:
    const sim::State<Dim>& state_;
    const sim::RunSetup<Dim>& setup_;
};

extern template class CraterModule<2>;
extern template class CraterModule<3>;
extern template class CracksModule<2>;
extern template class CracksModule<3>;
extern template class FluidInSolidModule<2>;
extern template class FluidInSolidModule<3>;
extern template class ProbesModule<2>;
extern template class ProbesModule<3>;

}  // namespace grit::modules
