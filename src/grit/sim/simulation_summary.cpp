// What a finished (or stopped) run reports: the summary, and summary.json with its units.
#include <fmt/format.h>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>

#include "grit/analysis/diagnostics.hpp"
#include "grit/io/durable_file.hpp"
#include "grit/io/run_folder.hpp"
#include "grit/parallel/parallel.hpp"
#include "grit/sim/simulation.hpp"
#include "grit/sim/version.hpp"

namespace grit::sim {

namespace {

nlohmann::ordered_json json_number(const OutputValue& v) {
    if (!std::isfinite(v.value)) return nullptr;
    if (v.integer) return static_cast<long long>(v.value);
    return v.value;
}

}  // namespace

double RunSummary::value(const std::string& name) const {
    for (const auto& v : values)
        if (v.name == name) return v.value;
    throw std::out_of_range("no output value named '" + name + "'");
}

template <int Dim>
RunSummary Simulation<Dim>::summarize(double wall_time, const std::string& status) const {
    RunSummary s;
    s.status = status;
    s.particles = state_.particles.size() - state_.particles.image_count();
    s.steps = state_.clock.step;
    s.end_time = state_.clock.time;
    // Over every segment of the run (a restart continues the totals of the checkpoint it starts from).
    const double wall = earlier_.wall_time_s + wall_time;
    s.wall_time_s = wall;
    s.segment_wall_time_s = wall_time;
    s.segments = earlier_.count + 1;
    s.particle_steps_per_second = wall > 0.0 ? (earlier_.particle_steps + particle_steps_) / wall : 0.0;
    s.pair_interactions_per_second = wall > 0.0 ? (earlier_.pair_steps + pair_steps_) / wall : 0.0;
    s.values = output_values();
    const auto d = analysis::compute_diagnostics(state_.particles);
    s.momentum.assign(d.momentum.c, d.momentum.c + Dim);
    s.stages = pipeline_.timers();
    s.restarted_from = restarted_from_.string();
    return s;
}

template <int Dim>
void Simulation<Dim>::write_summary(const RunSummary& s, const std::string& message) const {
    if (!options_.write_files) return;
    nlohmann::ordered_json j;
    j["case"] = spec_.name;
    j["title"] = spec_.title;
    j["status"] = s.status;
    if (!message.empty()) j["message"] = message;
    j["grit_version"] = version;
    j["git_revision"] = git_revision();
    j["dimension"] = Dim;
    j["case_file"] = spec_.source.string();
    j["case_digest"] = io::text_digest(spec_.text);
    j["overrides"] = spec_.overrides;
    j["particle_spacing"] = spec_.particle_spacing;
    for (const auto& m : modules_) m->describe(j);
    // The x >= 0 half of a symmetric set-up: masses, energies and counts are the half's.
    if (spec_.symmetry_plane) j["symmetry_plane"] = "x";
    j["threads"] = run_threads_ > 0 ? run_threads_ : parallel::max_threads();
    if (options_.adapt_threads) j["thread_changes"] = thread_changes_;
    // The threads the steps of this segment actually ran with, on average (fewer than `threads` where the
    // governor gave a core to another process).
    if (thread_step_count_ > 0) j["threads_used_mean"] = thread_steps_ / static_cast<double>(thread_step_count_);
    j["particles"] = s.particles;
    j["steps"] = s.steps;
    j["end_time"] = s.end_time;
    j["wall_time_s"] = s.wall_time_s;
    j["segments"] = s.segments;
    j["segment_wall_time_s"] = s.segment_wall_time_s;
    j["particle_steps_per_second"] = s.particle_steps_per_second;
    j["pair_interactions_per_second"] = s.pair_interactions_per_second;
    j["neighbor_list_builds"] = state_.neighbors.builds();
    j["neighbor_list_compactions"] = state_.neighbors.compactions();
    for (const auto& v : s.values)
        if (v.in_summary && v.group.empty()) j[v.name] = json_number(v);
    j["momentum"] = s.momentum;
    for (const auto& v : s.values)
        if (v.in_summary && !v.group.empty()) j[v.group][v.name] = json_number(v);
    for (const auto& t : s.stages) j["stage_seconds"][t.name] = t.seconds;
    // The unit of every key above that carries one, and of every series.csv column.
    nlohmann::ordered_json units = {{"end_time", "s"},         {"wall_time_s", "s"},
                                    {"segment_wall_time_s", "s"}, {"particle_spacing", "m"},
                                    {"particle_steps_per_second", "1/s"}, {"pair_interactions_per_second", "1/s"},
                                    {"momentum", Dim == 2 ? "kg m/s per m" : "kg m/s"}};
    for (const auto& v : s.values) units[v.name] = v.unit;
    j["units"] = units;
    j["restarted_from"] = s.restarted_from.empty() ? nlohmann::ordered_json(nullptr) : nlohmann::ordered_json(s.restarted_from);
    // In place whole or not at all (a sweep reads it to tell a finished run).
    const auto file = options_.output_dir / "summary.json";
    const auto temporary = io::temporary_name(file);
    {
        std::ofstream out(temporary);
        out << j.dump(2) << '\n';
        out.flush();
        if (!out) throw std::runtime_error(fmt::format("cannot write {} (disk full or not writable?)", file.string()));
    }
    io::commit_file(temporary, file);
}

template RunSummary Simulation<2>::summarize(double, const std::string&) const;
template RunSummary Simulation<3>::summarize(double, const std::string&) const;
template void Simulation<2>::write_summary(const RunSummary&, const std::string&) const;
template void Simulation<3>::write_summary(const RunSummary&, const std::string&) const;

}  // namespace grit::sim
