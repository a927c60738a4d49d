// The analyses as modules: the crater of an eroded surface (crater.csv, crater_depth, crater_width),
// the cracks of a brittle solid (damaged_area, crack_count), the fluid enclosed by solids
// (fluid_in_solid) and the probes (one column each). They read the state at output times and add no
// stage to the step.
#pragma once

#include <fstream>

#include "grit/analysis/crater.hpp"
#include "grit/analysis/probes.hpp"
#include "grit/modules/probes_table.hpp"
#include "grit/sim/module.hpp"

namespace grit::modules {

template <int Dim>
class CraterModule final : public sim::Module<Dim> {
public:
    CraterModule(const sim::State<Dim>& state, const sim::RunSetup<Dim>& setup);
    std::string name() const override { return "crater"; }
    void install(sim::Pipeline&) override {}
    void output_values(std::vector<sim::OutputValue>& out) const override;
    /// summary.json's crater_region: where the crater is measured (`grit plot`'s profiles, `grit crater`).
    void describe(nlohmann::ordered_json& summary) const override;
    void open_output(const sim::OutputPlace& place, bool restart) override;
    /// crater.csv: the surface profile at the output time (x, surface, time; in 3D the map: x, y,
    /// surface, time), rewritten each output; and the same rows appended to crater_history.csv, the
    /// profile at every output (a long run's crater over time without snapshots: `grit plot`).
    void write_output(const sim::OutputPlace& place) override;
    /// The rows crater_history.csv holds, so that a restart continues it from the checkpoint's output.
    void save(io::Hdf5Group& group) const override;
    void load(const io::Hdf5Group& group) override;
    /// A 3D run checkpointed before grit analysed 3D craters: its crater_history.csv starts at the restart.
    bool continues_without_saved_state() const override { return true; }

private:
    /// The columns of crater.csv and crater_history.csv.
    static std::string header();

    const sim::State<Dim>& state_;
    const sim::RunSetup<Dim>& setup_;
    analysis::CraterRegion region_;  ///< where the crater is measured (crater_region)
    std::ofstream history_;
    long history_rows_ = 0;
    bool history_restored_ = false;  // load() found the count (a checkpoint from before it has none)
};

template <int Dim>
class CracksModule final : public sim::Module<Dim> {
public:
    /// Throws core::InputError when the link distance is not less than half a period (a particle would
    /// link to two images of one).
    CracksModule(const sim::State<Dim>& state, const sim::RunSetup<Dim>& setup);
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
    ProbesModule(const sim::State<Dim>& state, const sim::RunSetup<Dim>& setup);
    std::string name() const override { return "probes"; }
    void install(sim::Pipeline&) override {}
    void output_values(std::vector<sim::OutputValue>& out) const override;
    /// Every probe's value now (case order): each sub-domain's samples, point probes' sums added and
    /// fronts' maxima taken over every sub-domain, then the values (the same on every rank).
    std::vector<double> values() const;
    /// The value of probe k (case order) now.
    double value(std::size_t k) const;
    /// The value of the probe named `name` now; throws std::out_of_range if there is none.
    double value(const std::string& name) const;

private:
    const sim::State<Dim>& state_;
    const sim::RunSetup<Dim>& setup_;
    const std::vector<analysis::ProbeSpec>& probes_;
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
