// Run estimate.
#include "grit/sim/run_estimate.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <string>

#include "grit/core/error.hpp"
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
    return fmt::format("~{:.3g} steps, ~{:.3g} particles, {:.0f} outputs (~{} of snapshots), ~{} of memory, ~{} "
                       "wall at {:.2g} particle-steps/s",
                       steps, particles, outputs, size(snapshot_bytes), size(memory_bytes), wall, rate);
}

std::vector<std::string> RunEstimate::warnings(const io::CaseSpec& spec, double free_bytes,
                                               double available_memory) const {
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
    // Found out as swapping that slows the run a hundredfold, or the kernel's out-of-memory kill.
    if (available_memory >= 0.0 && memory_bytes > available_memory)
        out.push_back(fmt::format("warning: the run may need {:.3g} GB of memory, {:.3g} GB are available now "
                                  "(~{:.3g} particles at numerics.particle_spacing = {} m)",
                                  memory_bytes / 1e9, available_memory / 1e9, particles, spec.particle_spacing));
    return out;
}

std::string RunEstimate::does_not_fit(const io::CaseSpec& spec, double total_memory) const {
    if (total_memory < 0.0 || memory_bytes <= total_memory) return "";
    return fmt::format("key 'numerics.particle_spacing' = {}: the run needs about {:.3g} GB of memory at its largest "
                       "(~{:.3g} particles), more than this machine's {:.3g} GB; coarsen the spacing, shrink the "
                       "domain or the inlets' reach, or run it on a larger machine",
                       spec.particle_spacing, memory_bytes / 1e9, particles, total_memory / 1e9);
}

MachineMemory machine_memory() {
    MachineMemory m;
    std::ifstream in("/proc/meminfo");
    std::string key;
    double kb = 0.0;
    std::string unit;
    while (in >> key >> kb >> unit) {
        if (key == "MemTotal:") m.total = kb * 1024.0;
        if (key == "MemAvailable:") m.available = kb * 1024.0;
    }
    return m;
}

void refuse_beyond_memory(const io::CaseSpec& spec) {
    const auto memory = machine_memory();
    if (!(memory.total > 0.0)) return;
    const auto budget = io::estimate_particles(spec);
    if (budget.bytes > memory.total)
        throw core::InputError(fmt::format(
            "key 'numerics.particle_spacing' = {}: the case would make about {:.2g} particles (~{:.3g} GB), "
            "more than this machine's {:.3g} GB of memory; coarsen the spacing or shrink the domain",
            spec.particle_spacing, budget.total(), budget.bytes / 1e9, memory.total / 1e9));
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
    // Memory: the program itself (about 20 MB), every SPH field twice (the state and the last-good copy),
    // each list entry with the build scratch, the half lists cut from it and the pair caches (32 B), the
    // grains' fields; at the largest SPH count, what the inlets add included. Against the peak resident
    // size: +23 % for the 2D dam break at 0.5 mm (246 MB), +2 % for the 3D dam break, -34 % for the 3D
    // Taylor bar (whose solid keeps more per pair); an estimate to refuse what cannot fit, not a budget.
    double field_bytes = 0.0;
    for (const auto* f : state.particles.fields().all()) field_bytes += static_cast<double>(f->bytes().size());
    const double sph_now = std::max(1.0, n);
    const double sph_max = n + budget.inlets_in_flight;
    const double entries_per_particle = static_cast<double>(state.neighbors.list().pair_count()) / sph_now;
    double grain_bytes = 0.0;
    if (state.grains)
        for (const auto* f : state.grains->grains().fields().all()) grain_bytes += static_cast<double>(f->bytes().size());
    const double grains_max = std::max(grains, budget.grains_in_flight);
    const double bytes_per_grain = grains > 0.0 ? grain_bytes / grains : 0.0;
    e.memory_bytes = 2.0e7 + sph_max * (2.0 * field_bytes / sph_now + 32.0 * entries_per_particle) +
                     grains_max * bytes_per_grain;
    // A typical rate of this code per thread (docs/performance.md: 0.7-1e6 particle-steps/s per core
    // for 2D jets on solids); the run's own rate is in summary.json.
    e.rate = 7.5e5 * parallel::max_threads();
    e.wall_seconds = e.steps * e.particles / e.rate;
    return e;
}


template RunEstimate estimate_run<2>(const io::CaseSpec&, const State<2>&);
template RunEstimate estimate_run<3>(const io::CaseSpec&, const State<3>&);

}  // namespace grit::sim
