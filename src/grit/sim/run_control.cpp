#include "grit/sim/run_control.hpp"

#include <fmt/format.h>

#include <atomic>
#include <csignal>

namespace grit::sim {

namespace {

// The handlers set this; the run loop reads it after each step.
std::atomic<int> pending_signal{0};
extern "C" void on_stop_signal(int signal) { pending_signal.store(signal); }

}  // namespace

RunControl::RunControl(double max_wall_time_s, double checkpoint_wall_interval_s)
    : max_wall_time_s_(max_wall_time_s), checkpoint_wall_interval_s_(checkpoint_wall_interval_s) {
    pending_signal.store(0);
    previous_int_ = std::signal(SIGINT, on_stop_signal);
    previous_term_ = std::signal(SIGTERM, on_stop_signal);
    previous_usr1_ = std::signal(SIGUSR1, on_stop_signal);
}

RunControl::~RunControl() {
    std::signal(SIGINT, previous_int_);
    std::signal(SIGTERM, previous_term_);
    std::signal(SIGUSR1, previous_usr1_);
}

std::optional<RunControl::Stop> RunControl::stop_requested() const {
    if (const int signal = pending_signal.load(); signal != 0)
        return Stop{signal, fmt::format("interrupted by signal {}", signal)};
    if (max_wall_time_s_ > 0.0 && clock_.seconds() >= max_wall_time_s_)
        return Stop{0, fmt::format("stopped at the wall-time limit (--max-wall-time {:g} s)", max_wall_time_s_)};
    return std::nullopt;
}

bool RunControl::wall_checkpoint_due() {
    if (checkpoint_wall_interval_s_ <= 0.0) return false;
    const double now = clock_.seconds();
    if (now - last_checkpoint_s_ < checkpoint_wall_interval_s_) return false;
    last_checkpoint_s_ = now;
    return true;
}

}  // namespace grit::sim
