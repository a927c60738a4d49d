// SimulationHandle: a case in memory for the Python module (simulation_handle.hpp).
#include "simulation_handle.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>

#include "grit/core/error.hpp"
#include "grit/core/types.hpp"
#include "grit/io/case_reader.hpp"
#include "grit/io/hdf5_file.hpp"
#include "grit/io/run_folder.hpp"
#include "grit/sim/output_times.hpp"
#include "grit/sim/run_estimate.hpp"

namespace grit::python {

io::CaseSpec read_case(const CaseSource& source) {
    if (source.from_text) return io::read_case_text(source.text, source.file, source.overrides);
    return io::read_case(source.file, source.overrides);
}

namespace {

/// The rows of `cloud` that `keep` selects, as position (n x dim) and arrays.
template <class Keep>
PhaseArrays select_rows(const io::PointCloud& cloud, int dim, Keep keep) {
    PhaseArrays out;
    out.dimension = dim;
    std::vector<std::size_t> rows;
    for (std::size_t i = 0; i < cloud.size(); ++i)
        if (keep(i)) rows.push_back(i);
    out.position.reserve(rows.size() * static_cast<std::size_t>(dim));
    for (const std::size_t i : rows)
        for (int k = 0; k < dim; ++k) out.position.push_back(cloud.points[3 * i + static_cast<std::size_t>(k)]);
    for (const auto& a : cloud.arrays) {
        io::PointArray b = a;
        const auto c = static_cast<std::size_t>(a.components);
        auto pick = [&](auto& values, const auto& from) {
            values.clear();
            for (const std::size_t i : rows)
                for (std::size_t k = 0; k < c; ++k) values.push_back(from[i * c + k]);
        };
        if (a.is_int64)
            pick(b.integer64, a.integer64);
        else if (a.is_integer)
            pick(b.integer, a.integer);
        else
            pick(b.real, a.real);
        out.arrays.push_back(std::move(b));
    }
    return out;
}

template <int Dim>
PhaseArrays phase_arrays(sim::Simulation<Dim>& s, const std::string& phase) {
    if (phase == "grains") {
        if (!s.grains()) return select_rows(io::PointCloud{}, Dim, [](std::size_t) { return false; });
        return select_rows(s.grains()->grains().snapshot(), Dim, [](std::size_t) { return true; });
    }
    std::int32_t code = 0;
    if (phase == "fluid")
        code = static_cast<std::int32_t>(Phase::fluid);
    else if (phase == "solid")
        code = static_cast<std::int32_t>(Phase::solid);
    else if (phase == "wall")
        code = static_cast<std::int32_t>(Phase::wall);
    else
        throw std::invalid_argument(fmt::format("fields('{}'): the phases are 'fluid', 'solid', 'wall' and 'grains'", phase));
    const io::PointCloud cloud = s.particles().snapshot();
    const auto it = std::find_if(cloud.arrays.begin(), cloud.arrays.end(), [](const io::PointArray& a) { return a.name == "phase"; });
    if (it == cloud.arrays.end()) throw std::logic_error("the particles' snapshot has no phase array");
    const auto& codes = it->integer;
    return select_rows(cloud, Dim, [&](std::size_t i) { return codes[i] == code; });
}

sim::RunOptions in_memory() {
    sim::RunOptions o;
    o.write_files = false;
    o.quiet = true;
    return o;
}

}  // namespace

SimulationHandle::SimulationHandle(const io::CaseSpec& spec, const std::filesystem::path& checkpoint)
    : dimension_(spec.dimension) {
    if (spec.dimension == 2)
        simulation_ = std::make_unique<sim::Simulation<2>>(spec, in_memory());
    else
        simulation_ = std::make_unique<sim::Simulation<3>>(spec, in_memory());
    if (!checkpoint.empty()) std::visit([&](auto& s) { s->load_checkpoint(checkpoint); }, simulation_);
}

SimulationHandle::~SimulationHandle() = default;

double SimulationHandle::time() const {
    return std::visit([](const auto& s) { return s->time(); }, simulation_);
}

long SimulationHandle::step() const {
    return std::visit([](const auto& s) { return s->steps(); }, simulation_);
}

double SimulationHandle::time_step() const {
    return std::visit([](const auto& s) { return s->time_step(); }, simulation_);
}

const io::CaseSpec& SimulationHandle::spec() const {
    return std::visit([](const auto& s) -> const io::CaseSpec& { return s->spec(); }, simulation_);
}

void SimulationHandle::advance(double time, const std::function<void()>& after_each_step) {
    std::visit(
        [&](auto& s) {
            // As Simulation::run steps: toward the next output time or the end, whichever comes first.
            const sim::Cadence outputs{s->spec().output_interval};
            while (s->time() < time * (1.0 - sim::same_time_tolerance)) {
                const double target = std::min(time, outputs.at(outputs.next_after(s->time())));
                s->advance_to(target, after_each_step);
            }
        },
        simulation_);
}

PhaseArrays SimulationHandle::fields(const std::string& phase) const {
    return std::visit([&](const auto& s) { return phase_arrays(*s, phase); }, simulation_);
}

std::vector<sim::OutputValue> SimulationHandle::outputs() const {
    return std::visit([](const auto& s) { return s->output_values(); }, simulation_);
}

void SimulationHandle::checkpoint(const std::filesystem::path& file) {
    std::visit([&](auto& s) { s->save_checkpoint(file); }, simulation_);
}

std::string SimulationHandle::estimate() {
    return std::visit([](auto& s) { return s->estimate().text(); }, simulation_);
}

sim::RunSummary run_case(const io::CaseSpec& spec, const std::filesystem::path& out, bool write_files, bool quiet,
                         bool overwrite, std::function<void(double, long)> on_output) {
    sim::RunOptions options;
    options.on_output = std::move(on_output);
    options.write_files = write_files;
    options.quiet = quiet;
    options.adapt_threads = true;  // as the CLI's runs: fewer threads while another process holds a core
    if (write_files) {
        options.output_dir = out;
        const std::string earlier = io::earlier_run(out);
        if (!earlier.empty() && !overwrite)
            throw core::InputError(fmt::format("out='{}': the folder holds {}; replace it with overwrite=True",
                                               out.string(), earlier));
        io::check_writable_folder(out, "out");
    }
    sim::refuse_beyond_memory(spec);
    return sim::run_case(spec, options);
}

sim::RunSummary restart_run(const std::filesystem::path& folder, const CaseSource* source, double end_time, bool quiet) {
    const auto checkpoint = sim::resolve_checkpoint(folder);
    CaseSource from;
    if (source) {
        from = *source;
        // The checkpointed run's overrides first, as the CLI's restart applies them, then the case's own.
        from.overrides = sim::checkpoint_overrides(checkpoint, read_case(*source).name);
        from.overrides.insert(from.overrides.end(), source->overrides.begin(), source->overrides.end());
    } else {
        const auto h5 = io::Hdf5File::open(checkpoint);
        if (!h5.has_attribute("case_text"))
            throw core::InputError(fmt::format("checkpoint {}: it holds no case text; give the case", checkpoint.string()));
        from.file = h5.read_string("case_file");
        from.text = h5.read_string("case_text");
        from.from_text = true;
        const std::int64_t n = h5.has_attribute("override_count") ? h5.read_int("override_count") : 0;
        for (std::int64_t k = 0; k < n; ++k) from.overrides.push_back(h5.read_string(fmt::format("override {}", k)));
    }
    if (end_time > 0.0) from.overrides.push_back(fmt::format("time.end={:.17g}", end_time));
    const io::CaseSpec spec = read_case(from);
    sim::RunOptions options;
    options.quiet = quiet;
    options.adapt_threads = true;
    options.restart = checkpoint;
    // The checkpoint's run folder: the one that holds checkpoints/.
    const auto parent = checkpoint.parent_path();
    options.output_dir = parent.filename() == "checkpoints" ? parent.parent_path() : parent;
    sim::refuse_beyond_memory(spec);
    return sim::run_case(spec, options);
}

}  // namespace grit::python
