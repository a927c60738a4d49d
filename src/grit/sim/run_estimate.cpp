// Run estimate.
#include "grit/sim/run_estimate.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "grit/io/particle_budget.hpp"
#include "grit/parallel/parallel.hpp"

namespace grit::sim {

std::string RunEstimate::text() const {
    auto size = [](double b) {
        return b >= 1e9 ? fmt::format("{:.3g} GB", b / 1e9) : b >= 1e6 ? fmt::format("{:.3g} MB", b / 1e6)
                                                                        : fmt::format("{:.3g} kB", b / 1e3);
    };
    const long s = static_cast<long>(wall_seconds);
    const std::string wall = s >= 86400 ? fmt::format("{:.1f} days", wall_seconds / 86400.0)
                             : s >= 3600 ? fmt::format("{:.1f} h", wall_seconds / 3600.0)
                             : s >= 60   ? fmt::format("{:.1f} min", wall_seconds / 60.0)
                                         : fmt::format("{:.0f} s", wall_seconds);
    return fmt::format("~{:.3g} steps, ~{:.3g} particles, {:.0f} outputs (~{} of snapshots), ~{} wall at {:.2g} "
                       "particle-steps/s",
                       steps, particles, outputs, size(snapshot_bytes), wall, rate);
}

std::vector<std::string> RunEstimate::warnings(const io::CaseSpec& spec, double free_bytes) const {
    std::vector<std::string> out;
    if (wall_seconds > 86400.0)
        out.push_back(
            fmt::format("warning: this run may take {:.1f} days (time.end = {} s, numerics.particle_spacing "
                        "= {} m); Ctrl-C stops it with a checkpoint to continue from",
                        wall_seconds / 86400.0, spec.end_time, spec.particle_spacing));
    // Found out only when the disk is full, hours in, and the run stops there.
    if (free_bytes >= 0.0 && snapshot_bytes > free_bytes)
        out.push_back(
            fmt::format("warning: the snapshots may need {:.3g} GB, {:.3g} GB are free where they are "
                        "written ({:.0f} outputs at output.interval = {} s); raise output.interval, or set "
                        "output.snapshots = false",
                        snapshot_bytes / 1e9, free_bytes / 1e9, outputs, spec.output_interval));
    return out;
}

template <int Dim>
RunEstimate estimate_run(const io::CaseSpec& spec, const State<Dim>& state) {
    RunEstimate e;
    const double remaining = std::max(0.0, spec.end_time - state.clock.time);
    const double dt = state.clock.dt_stable > 0.0 ? state.clock.dt_stable : state.clock.dt;
    e.steps = dt > 0.0 ? std::ceil(remaining / dt) : 0.0;
    // What exists now and what the inlets add at a time (the budget's in-flight count: with outlets, what
    // enters while a particle crosses the domain; without, what they emit by time.end, at most the room).
    const auto budget = io::estimate_particles(spec);
    const double grains = state.grains ? static_cast<double>(state.grains->grains().size()) : 0.0;
    e.particles =
        static_cast<double>(state.particles.size()) + budget.inlets_in_flight + std::max(grains, budget.grains_in_flight);
    e.outputs = std::floor(remaining / spec.output_interval + 1e-9) + 1.0;
    double bytes_per_particle = 0.0;  // the snapshot's columns, as they are held in memory
    const auto n = static_cast<double>(state.particles.size());
    for (const auto* f : state.particles.fields().all())
        if (f->is_output() && n > 0.0) bytes_per_particle += static_cast<double>(f->bytes().size()) / n;
    e.snapshot_bytes = spec.write_snapshots ? e.outputs * e.particles * bytes_per_particle : 0.0;
    // A typical rate of this code per thread (docs/performance.md: 0.7-1e6 particle-steps/s per core
    // for 2D jets on solids); the run's own rate is in summary.json.
    e.rate = 7.5e5 * parallel::max_threads();
    e.wall_seconds = e.steps * e.particles / e.rate;
    return e;
}


template RunEstimate estimate_run<2>(const io::CaseSpec&, const State<2>&);
template RunEstimate estimate_run<3>(const io::CaseSpec&, const State<3>&);

}  // namespace grit::sim
