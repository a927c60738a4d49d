// Progress line.
#include "grit/sim/progress.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>

namespace grit::sim {

Progress::Progress(bool enabled) : active_(enabled && isatty(fileno(stderr))) {}

namespace {
std::string clock_text(double seconds) {
    const long s = static_cast<long>(seconds);
    return fmt::format("{}:{:02}:{:02}", s / 3600, (s / 60) % 60, s % 60);
}
}  // namespace

void Progress::update(double t, double end_time, long step, Index particles, Index grains, bool force) {
    if (!active_) return;
    const double now = clock_.seconds();
    if (!force && now - last_print_ < 0.5) return;
    if (now > last_time_) steps_per_second_ = (step - last_step_) / (now - last_time_);
    const double fraction = end_time > 0.0 ? std::clamp(t / end_time, 0.0, 1.0) : 1.0;
    std::string eta = "ETA --:--:--";
    if (fraction >= 1.0) eta = "done        ";
    else if (fraction > 0.0) eta = "ETA " + clock_text(now * (1.0 - fraction) / fraction);
    const std::string grain_text = grains > 0 ? fmt::format(" + {} grains", grains) : std::string();
    fmt::print(stderr, "\r[{:5.1f}%] t = {:.4e} s  step {}  {} particles{}  {:.0f} steps/s  elapsed {}  {}   ",
               100.0 * fraction, t, step, particles, grain_text, steps_per_second_, clock_text(now), eta);
    std::fflush(stderr);
    last_print_ = now;
    last_step_ = step;
    last_time_ = now;
}

void Progress::finish() {
    if (active_) fmt::print(stderr, "\n");
}

}  // namespace grit::sim
