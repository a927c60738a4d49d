// When a run stops before time.end, and when a checkpoint is due on wall time. A run stops cleanly (a
// checkpoint, then the CLI's exit) on SIGINT, SIGTERM, SIGUSR1 (what batch systems send ahead of their
// time limit) or at --max-wall-time; and it writes a checkpoint at least every
// output.checkpoint_wall_interval of wall time, so a run killed without warning loses at most that.
#pragma once

#include <optional>
#include <string>

#include "grit/core/timer.hpp"

namespace grit::sim {

class RunControl {
public:
    /// Installs the stop handlers for the lifetime of the run (the previous ones come back after it).
    /// max_wall_time_s, checkpoint_wall_interval_s: 0 for none.
    RunControl(double max_wall_time_s, double checkpoint_wall_interval_s);
    ~RunControl();
    RunControl(const RunControl&) = delete;
    RunControl& operator=(const RunControl&) = delete;

    struct Stop {
        int signal = 0;      ///< the signal received, 0 for the wall-time limit
        std::string reason;  ///< "interrupted by signal 2", "the wall-time limit --max-wall-time = 3600 s"
    };
    /// Why the run should stop after this step, if it should.
    std::optional<Stop> stop_requested() const;
    /// True when output.checkpoint_wall_interval has passed since the run started or since the last time
    /// this returned true.
    bool wall_checkpoint_due();

private:
    core::Stopwatch clock_;
    double max_wall_time_s_, checkpoint_wall_interval_s_;
    double last_checkpoint_s_ = 0.0;
    void (*previous_int_)(int);
    void (*previous_term_)(int);
    void (*previous_usr1_)(int);
};

}  // namespace grit::sim
