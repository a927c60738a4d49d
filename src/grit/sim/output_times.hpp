// When a run writes its outputs and checkpoints: output k at k x interval (one multiplication, never a
// running sum), and an end time that lies on an output time within round-off taken as that output time.
// A run that ends at T and one that passes T then aim their steps at the same doubles, so extending a
// finished run is bit-identical to a run that never stopped.
#pragma once

#include <cmath>

namespace grit::sim {

/// Relative distance within which two times are the same time (a parsed 6e-5 and 3 x 2e-5 differ by one
/// unit in the last place; a step that lands on its target does so to a few).
inline constexpr double same_time_tolerance = 1e-12;

/// Times k x interval, k = 0, 1, 2, ... (interval > 0).
struct Cadence {
    double interval = 0.0;

    /// Time k x interval.
    double at(long k) const { return static_cast<double>(k) * interval; }

    /// The first k whose time lies after `time` by more than round-off: the next output due once the
    /// one at `time` (if any) is written. It depends on the time alone, so a restart needs no stored index.
    long next_after(double time) const {
        long k = static_cast<long>(std::floor(time / interval));
        if (k < 0) k = 0;
        while (k > 0 && at(k - 1) > time * (1.0 + same_time_tolerance)) --k;
        while (at(k) <= time * (1.0 + same_time_tolerance)) ++k;
        return k;
    }

    /// `end` itself, or the time k x interval it lies on within round-off.
    double snap(double end) const {
        const double k = std::round(end / interval);
        const double t = k * interval;
        return std::abs(t - end) <= same_time_tolerance * std::abs(end) ? t : end;
    }
};

}  // namespace grit::sim
