// What a run will cost, from its first time step, before it runs: shown by `grit check` and at the
// start of `grit run`, written to run.log.
#pragma once

#include <string>
#include <vector>

#include "grit/io/case_spec.hpp"
#include "grit/sim/state.hpp"

namespace grit::sim {

struct RunEstimate {
    double steps = 0.0;            ///< time.end / the first stable step (the step changes during a run)
    double particles = 0.0;        ///< SPH particles and grains at once: those at the start and what the
                                   ///< inlets and feeds add at a time (io::ParticleEstimate's in-flight counts)
    double outputs = 0.0;          ///< output times: time.end / output.interval + 1
    double snapshot_bytes = 0.0;   ///< all snapshots together [B] (at the largest particle count)
    /// The run's memory at its largest particle count [B]: every SPH field twice (the state and the
    /// last-good copy the health check keeps), the neighbour lists with their build scratch, the grains.
    double memory_bytes = 0.0;
    double wall_seconds = 0.0;     ///< at `rate` particle-steps per second
    double rate = 0.0;             ///< the assumed particle-steps per second (threads x per-thread rate)
    /// One line: "~N steps, ~P particles, O outputs (~S of snapshots), ~M of memory, ~T wall at R
    /// particle-steps/s".
    std::string text() const;
    /// Warnings, one line each: the run may take more than a day; its snapshots may need more than
    /// `free_bytes`, the space left where they are written; it may need more memory than
    /// `available_memory` holds now (either negative: unknown, not checked).
    std::vector<std::string> warnings(const io::CaseSpec& spec, double free_bytes, double available_memory) const;
    /// Empty, or why the run cannot fit a machine of `total_memory` bytes (negative: unknown), with the
    /// estimate and what to change: the run is refused then, before it starts.
    std::string does_not_fit(const io::CaseSpec& spec, double total_memory) const;
};

/// This machine's memory from /proc/meminfo [B]: MemTotal and MemAvailable (-1 where unknown).
struct MachineMemory {
    double total = -1.0, available = -1.0;
};
MachineMemory machine_memory();

/// Refuses (core::InputError naming numerics.particle_spacing) a case whose particles alone would not fit
/// this machine's memory, before any is built; the run's own estimate follows once they are.
void refuse_beyond_memory(const io::CaseSpec& spec);

/// The estimate from the primed `state` of a run of `spec` (its clock holds the first stable step).
template <int Dim>
RunEstimate estimate_run(const io::CaseSpec& spec, const State<Dim>& state);

}  // namespace grit::sim
