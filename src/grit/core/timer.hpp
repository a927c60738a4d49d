// Wall-clock timers accumulated by name (the pipeline times each stage with these).
#pragma once

#include <chrono>
#include <string>
#include <vector>

namespace grit::core {

/// Accumulated wall time of one named activity [s].
struct TimerEntry {
    std::string name;
    double seconds = 0.0;
    long calls = 0;
};

/// A monotonic stopwatch.
class Stopwatch {
public:
    Stopwatch() : start_(std::chrono::steady_clock::now()) {}
    double seconds() const {
        return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    }
    void restart() { start_ = std::chrono::steady_clock::now(); }

private:
    std::chrono::steady_clock::time_point start_;
};

}  // namespace grit::core
