// Progress line.
#include "grit/sim/progress.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>

namespace grit::sim {

Progress::Progress(bool show, double every_s, std::function<void(const std::string&)> log)
    : live_(show && isatty(fileno(stderr))),
      plain_(show && !live_ && every_s > 0.0),
      every_s_(every_s),
      log_(every_s > 0.0 ? std::move(log) : nullptr) {}

namespace {
std::string clock_text(double seconds) {
    const long s = static_cast<long>(seconds);
    return fmt::format("{}:{:02}:{:02}", s / 3600, (s / 60) % 60, s % 60);
}
}  // namespace

std::string Progress::line(double now, double t, double end_time, long step, Index particles, Index grains) {
    if (last_step_ >= 0 && now > last_time_) steps_per_second_ = (step - last_step_) / (now - last_time_);
    last_step_ = step;
    last_time_ = now;
    const double fraction = end_time > 0.0 ? std::clamp(t / end_time, 0.0, 1.0) : 1.0;
    if (start_fraction_ < 0.0) start_fraction_ = fraction;
    std::string eta = "ETA --:--:--";
    if (fraction >= 1.0)
        eta = "done";
    else if (fraction > start_fraction_)
        eta = "ETA " + clock_text(now * (1.0 - fraction) / (fraction - start_fraction_));
    const std::string grain_text = grains > 0 ? fmt::format(" + {} grains", grains) : std::string();
    return fmt::format("{:5.1f}% t = {:.4e} s, step {}, {} particles{}, {:.0f} steps/s, elapsed {}, {}",
                       100.0 * fraction, t, step, particles, grain_text, steps_per_second_, clock_text(now), eta);
}

void Progress::update(double t, double end_time, long step, Index particles, Index grains, bool force) {
    if (!live_ && !plain_ && !log_) return;
    const double now = clock_.seconds();
    if (start_fraction_ < 0.0) {
        // Where the segment starts: the rate and the ETA count from here, the first plain line one
        // interval on.
        (void)line(now, t, end_time, step, particles, grains);
        last_plain_ = now;
        if (!force) return;
    }
    const bool live_due = live_ && (force || now - last_live_ >= 0.5);
    const bool plain_due = (plain_ || log_) && every_s_ > 0.0 && now - last_plain_ >= every_s_;
    if (!live_due && !plain_due) return;
    const std::string text = line(now, t, end_time, step, particles, grains);
    if (live_due) {
        fmt::print(stderr, "\r[{}]   ", text);
        std::fflush(stderr);
        last_live_ = now;
        printed_live_ = true;
    }
    if (plain_due) {
        if (plain_) {
            fmt::print(stderr, "progress: {}\n", text);
            std::fflush(stderr);
        }
        if (log_) log_("progress: " + text);
        last_plain_ = now;
    }
}

void Progress::finish() {
    if (printed_live_) fmt::print(stderr, "\n");
    printed_live_ = false;
}

}  // namespace grit::sim
