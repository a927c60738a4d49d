// The run's outputs: the output values (series.csv and summary.json), the files opened at the start, what is
// written at each output time, the per-step dump, the run log's opening, and the state of an interrupted run.
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <filesystem>

#include "grit/analysis/diagnostics.hpp"
#include "grit/io/run_folder.hpp"
#include "grit/io/vtu_writer.hpp"
#include "grit/sim/checkpoint_files.hpp"
#include "grit/sim/named_snapshot.hpp"
#include "grit/sim/output_units.hpp"
#include "grit/sim/run_log.hpp"
#include "grit/sim/simulation.hpp"

namespace grit::sim {

template <int Dim>
std::vector<OutputValue> Simulation<Dim>::output_values() const {
    const auto& clock = state_.clock;
    const auto d = analysis::compute_diagnostics(state_.particles);
    // time, step and particles have their own summary keys.
    std::vector<OutputValue> out = {
        OutputValue::real("time", clock.time, domain::Combine::same).series_only(),
        OutputValue::count("step", static_cast<double>(clock.step), domain::Combine::same).series_only(),
        OutputValue::real("dt", clock.dt, domain::Combine::same).series_only(),
        OutputValue::real("kinetic_energy", d.kinetic_energy, domain::Combine::sum),
        OutputValue::real("mass_total", d.mass, domain::Combine::sum),
        OutputValue::real("mass_in", state_.ledger.in, domain::Combine::sum),
        OutputValue::real("mass_out", state_.ledger.out, domain::Combine::sum),
        OutputValue::real("max_velocity", d.max_velocity, domain::Combine::max),
        OutputValue::count("particles", static_cast<double>(state_.particles.size() - state_.particles.image_count()), domain::Combine::sum)
            .series_only(),
    };
    for (const auto& m : modules_) m->output_values(out);
    for (auto& v : out) {
        v.value = comm_.combine(v.combine, v.value);  // this sub-domain's value with the others'
        if (v.unit.empty()) v.unit = output_unit(v.name, Dim);
    }
    return out;
}

template <int Dim>
void Simulation<Dim>::open_output(bool restart) {
    namespace fs = std::filesystem;
    place_ = {options_.output_dir, spec_.name, spec_.write_snapshots};
    const fs::path dir = options_.output_dir;
    // A fresh run replaces what an earlier run left here (the CLI asks for --overwrite first), derived
    // files (plots) included, so that nothing stale sits beside the new data.
    if (!restart) io::clear_run_folder(dir);
    fs::create_directories(dir / "snapshots");
    fs::create_directories(dir / "checkpoints");
    if (restart) {
        // Checkpoints after the one continued belong to a future this run replaces.
        for (const auto& c : checkpoints_in(dir / "checkpoints"))
            if (checkpoint_step(c) > state_.clock.step) fs::remove(c);
    }
    if (!has_sph_) fs::remove(dir / "snapshots");
    pvd_ = std::make_unique<io::PvdWriter>(dir / (spec_.name + ".pvd"));
    if (restart) pvd_->restore(restored_pvd_);
    std::vector<std::string> columns;
    for (const auto& v : output_values())
        if (v.in_series) columns.push_back(v.name);
    series_ = restart ? std::make_unique<io::SeriesWriter>(dir / "series.csv", columns, restored_series_rows_)
                      : std::make_unique<io::SeriesWriter>(dir / "series.csv", columns);
    for (auto& m : modules_) m->open_output(place_, restart);
}

template <int Dim>
void Simulation<Dim>::write_output() {
    if (!options_.write_files) return;
    if (spec_.write_snapshots && has_sph_) {
        const auto file = fmt::format("snapshots/{}_{:06}.vtu", spec_.name, snapshot_index_++);
        io::write_vtu(options_.output_dir / file, named_snapshot(state_.particles, spec_));
        pvd_->add(state_.clock.time, file);
    }
    for (auto& m : modules_) m->write_output(place_);
    std::vector<double> row;
    for (const auto& v : output_values())
        if (v.in_series) row.push_back(v.value);
    series_->write_row(row);
}

template <int Dim>
void Simulation<Dim>::write_dump() {
    if (!options_.write_files || !has_sph_) return;
    const auto file = options_.output_dir / "dump" / fmt::format("{}_step_{:09}.vtu", spec_.name, state_.clock.step);
    std::filesystem::create_directories(file.parent_path());
    io::write_vtu(file, named_snapshot(state_.particles, spec_));
}

template <int Dim>
std::unique_ptr<RunLog> Simulation<Dim>::open_run_log(bool restart) {
    if (!options_.write_files) return nullptr;
    auto log = std::make_unique<RunLog>(options_.output_dir, restart);
    log->start(spec_, state_.particles.size(), state_.grains ? state_.grains->grains().size() : Index{0},
               restart ? restarted_from_.string() : std::string(), state_.clock.step, state_.clock.time);
    std::vector<std::string> notes = restart_notes_;
    if (series_ && !series_->added_columns().empty())
        notes.push_back(fmt::format("series.csv gains column(s) {} (nan in the rows before this restart)",
                                    fmt::join(series_->added_columns(), ", ")));
    for (const std::string& note : notes) {
        if (!options_.quiet) fmt::print(stderr, "{}\n", note);
        log->warn(note);
    }
    return log;
}

template <int Dim>
void Simulation<Dim>::stop_cleanly(const std::string& reason, int signal, RunLog* log) {
    // A checkpoint to continue from, and the state now as a snapshot.
    const auto& c = state_.clock;
    std::string message = fmt::format("{} at step {} (t = {:.9g} s)", reason, c.step, c.time);
    if (options_.write_files) {
        write_checkpoint();
        if (has_sph_) {
            const auto file = fmt::format("snapshots/{}_interrupted_{:06}.vtu", spec_.name, c.step);
            io::write_vtu(options_.output_dir / file, named_snapshot(state_.particles, spec_));
            message += "; state written to " + (options_.output_dir / file).string();
        }
        message += "; continue with --restart " + options_.output_dir.string();
    }
    write_summary(summarize(segment_clock_.seconds(), "interrupted"), message);
    if (log) log->warn(message);
    throw Interrupted(signal, message);
}

template std::vector<OutputValue> Simulation<2>::output_values() const;
template void Simulation<2>::open_output(bool);
template void Simulation<2>::write_output();
template void Simulation<2>::write_dump();
template std::unique_ptr<RunLog> Simulation<2>::open_run_log(bool);
template void Simulation<2>::stop_cleanly(const std::string&, int, RunLog*);
template std::vector<OutputValue> Simulation<3>::output_values() const;
template void Simulation<3>::open_output(bool);
template void Simulation<3>::write_output();
template void Simulation<3>::write_dump();
template std::unique_ptr<RunLog> Simulation<3>::open_run_log(bool);
template void Simulation<3>::stop_cleanly(const std::string&, int, RunLog*);

}  // namespace grit::sim
