// One running case for the Python module, whatever its dimension: the Simulation it holds, its fields as
// arrays, its output values, its checkpoints. What the bindings (grit_module.cpp) hand to Python.
#pragma once

#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <variant>
#include <vector>

#include "grit/io/case_spec.hpp"
#include "grit/io/point_data.hpp"
#include "grit/sim/simulation.hpp"

namespace grit::python {

/// A case as Python gives it: a file, or text with the file name it stands for, and the --set overrides.
struct CaseSource {
    std::filesystem::path file;
    std::string text;  ///< empty: read `file`
    bool from_text = false;
    std::vector<std::string> overrides;
};

/// The case read and validated (throws core::InputError naming the key, the value and the reason).
io::CaseSpec read_case(const CaseSource& source);

/// One phase's particles as arrays: positions (n x Dim) and every output field of that phase, named as in
/// the snapshots.
struct PhaseArrays {
    int dimension = 2;
    std::vector<double> position;  ///< n x dimension
    std::vector<io::PointArray> arrays;
    std::size_t size() const { return position.size() / static_cast<std::size_t>(dimension); }
};

/// A case built in memory (no files unless asked), advanced by the caller.
class SimulationHandle {
public:
    /// The case at its start, or (`checkpoint` not empty) at the state a checkpoint of it holds.
    explicit SimulationHandle(const io::CaseSpec& spec, const std::filesystem::path& checkpoint = {});
    ~SimulationHandle();

    int dimension() const noexcept { return dimension_; }
    double time() const;
    long step() const;
    double time_step() const;
    const io::CaseSpec& spec() const;

    /// Advances to `time` [s], landing on every output time on the way as a run does (output k at
    /// k x output.interval), so advancing in pieces that end on output times gives a run's states bit for bit.
    /// `after_each_step` runs after every step (the bindings poll Ctrl-C there).
    void advance(double time, const std::function<void()>& after_each_step = {});
    /// The particles of `phase`: "fluid", "solid", "wall" (SPH) or "grains" (symmetry images left out).
    /// Throws std::invalid_argument for another name.
    PhaseArrays fields(const std::string& phase) const;
    /// Every output value now, as series.csv and summary.json name them.
    std::vector<sim::OutputValue> outputs() const;
    /// A checkpoint of the state now (a SimulationHandle given it continues from it).
    void checkpoint(const std::filesystem::path& file);
    /// `grit check`'s estimate line (steps, particles, outputs, memory, wall time), from the primed state.
    std::string estimate();

private:
    int dimension_ = 2;
    std::variant<std::unique_ptr<sim::Simulation<2>>, std::unique_ptr<sim::Simulation<3>>> simulation_;
};

/// What the Python module's run() did: the run's summary, or a note (a run already at its end time).
/// `on_output`: called after each output with the time and step (may be empty).
sim::RunSummary run_case(const io::CaseSpec& spec, const std::filesystem::path& out, bool write_files, bool quiet,
                         bool overwrite, std::function<void(double, long)> on_output = {});

/// Continues the run in `folder` from its latest checkpoint, into its own files, as `grit run CASE --restart
/// folder` does. The case is `source` when given (its overrides after the checkpointed run's), else the one the
/// checkpoint holds (its file name, text and overrides). `end_time` > 0 extends or shortens it (time.end).
sim::RunSummary restart_run(const std::filesystem::path& folder, const CaseSource* source, double end_time, bool quiet);

}  // namespace grit::python
