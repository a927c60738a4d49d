// How far a run is: on a terminal, one line kept up to date (percent, simulated time, step, particles
// and grains, steps per second, elapsed wall time, ETA); in a log (make, `| tee`, nohup, a batch job,
// and run.log always) the same as a plain line every so many seconds of wall time, as LAMMPS' thermo
// output does, so that a run never goes quiet for minutes.
#pragma once

#include <cstdio>
#include <functional>
#include <string>

#include "grit/core/timer.hpp"
#include "grit/core/types.hpp"

namespace grit::sim {

class Progress {
public:
    /// `show`: print to standard error (a live line on a terminal, plain lines every `every_s` seconds
    /// otherwise); `log`, if given, receives a plain line every `every_s` seconds whether shown or not.
    Progress(bool show, double every_s, std::function<void(const std::string&)> log = {});
    void update(double t, double end_time, long step, Index particles, Index grains, bool force = false);
    void finish();

private:
    /// "12.5% t = 1.2500e-04 s, step 24000, 5603 particles + 120 grains, 2100 steps/s, elapsed 0:00:12, ETA 0:01:24"
    std::string line(double now, double t, double end_time, long step, Index particles, Index grains);

    bool live_;                 ///< a terminal: the line is rewritten in place
    bool plain_;                ///< standard error is not a terminal: plain lines
    double every_s_;
    std::function<void(const std::string&)> log_;
    core::Stopwatch clock_;
    double last_live_ = -1.0, last_plain_ = 0.0;
    long last_step_ = -1;
    double last_time_ = 0.0;
    double steps_per_second_ = 0.0;
    double start_fraction_ = -1.0;  ///< where this segment started (a restart's ETA counts from there)
    bool printed_live_ = false;
};

}  // namespace grit::sim
