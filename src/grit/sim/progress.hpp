// The progress line shown on a terminal: percent, simulated time, step, particles and grains, steps per
// second, elapsed wall time, ETA ("done" at the end).
#pragma once

#include <cstdio>
#include <string>

#include "grit/core/timer.hpp"
#include "grit/core/types.hpp"

namespace grit::sim {

class Progress {
public:
    /// Shows progress only when `enabled` and standard error is a terminal.
    explicit Progress(bool enabled);
    void update(double t, double end_time, long step, Index particles, Index grains, bool force = false);
    void finish();

private:
    bool active_;
    core::Stopwatch clock_;
    double last_print_ = -1.0;
    long last_step_ = 0;
    double last_time_ = 0.0;
    double steps_per_second_ = 0.0;
};

}  // namespace grit::sim
