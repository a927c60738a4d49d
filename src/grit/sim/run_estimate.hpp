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
    double wall_seconds = 0.0;     ///< at `rate` particle-steps per second
    double rate = 0.0;             ///< the assumed particle-steps per second (threads x per-thread rate)
    /// One line: "~N steps, ~P particles, O outputs (~S of snapshots), ~T wall at R particle-steps/s".
    std::string text() const;
    /// Warnings, one line each: the run may take more than a day; its snapshots may need more than
    /// `free_bytes`, the space left where they are written (negative: unknown, not checked).
    std::vector<std::string> warnings(const io::CaseSpec& spec, double free_bytes) const;
};

/// The estimate from the primed `state` of a run of `spec` (its clock holds the first stable step).
template <int Dim>
RunEstimate estimate_run(const io::CaseSpec& spec, const State<Dim>& state);

}  // namespace grit::sim
