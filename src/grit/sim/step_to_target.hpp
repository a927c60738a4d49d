// The step size that reaches a target time (an output, the end) in equal steps.
#pragma once

#include <cmath>

namespace grit::sim {

/// The next step from `time` toward `target` when the stable step is `dt`: the remaining time split
/// into the fewest equal steps no longer than dt. Cutting only the last step short (dt, dt, ..., a
/// sliver) changed the step by up to its whole size at every output; a grain's penalty contact (eq.
/// 13, stiffness 2 m_a / dt^2) integrated across such a change gained up to +100 % of its impact
/// energy with outputs every 0.13 us (docs/theory.md, "the grain's share"). Split evenly, the step
/// changes by 1/n at most between outputs, and the run takes at most one step more per output.
inline double step_toward(double time, double target, double dt) {
    const double remaining = target - time;
    if (remaining <= dt) return remaining;
    return remaining / std::ceil(remaining / dt);
}

}  // namespace grit::sim
