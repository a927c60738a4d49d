// How many threads a run uses while other processes come and go on the machine.
//
// libgomp's threads spin for a few milliseconds at the end of each parallel loop before they sleep. On
// a machine of one's own that is what makes grit fast (a thread that sleeps after a short spin takes
// tens of microseconds to wake, at each of the ~30 loops of a step); on a machine where another process
// holds a core, a thread spins away the time slice its descheduled partner needs, and two threads run
// up to 35x slower than one (docs/performance.md, "Threads that wait for a descheduled partner").
//
// The governor watches, every quarter second of wall time, how much CPU the run actually got and how
// often the scheduler took a core away from it. When the run got a core less than its threads and was
// preempted often, another process holds that core: it uses fewer threads. When a core it does not use
// stands idle, it takes it back. Results do not depend on the thread count (docs/architecture.md), so
// the count may change between any two steps.
#pragma once

#include <chrono>
#include <string>
#include <vector>

namespace grit::parallel {

/// What the governor measured over one window.
struct ThreadSample {
    double wall_s = 0.0;             ///< the window's length
    double cpu_s = 0.0;              ///< the process's CPU time in it (all threads)
    double preemptions = 0.0;        ///< involuntary context switches in it (all threads)
    double idle_cores = 0.0;         ///< idle CPU time of the cores the run may use, over wall_s
};

/// The decision, apart from the clocks (unit-tested with made-up samples).
class ThreadPolicy {
public:
    explicit ThreadPolicy(int max_threads);

    /// The thread count for the next window, given the last one's sample; `now_s` is wall time since
    /// the start (for the back-off of probes).
    int next(int threads, const ThreadSample& sample, double now_s);

    int max_threads() const { return max_; }

    /// The run got fewer than threads - 1/2 cores' worth of CPU and was preempted at least this many
    /// times a second: another process holds a core. (Measured on a 2-core machine: 20-90 per second
    /// alone, 250 per second beside a busy process with libgomp's default waits.)
    static constexpr double preemptions_per_second = 100.0;
    /// Idle CPU of the run's cores, in cores, that lets the run take one more thread.
    static constexpr double idle_to_grow = 0.75;
    /// After the run gave a core back, it tries to take one again no sooner than this (seconds),
    /// doubled each time a try fails within `hold_s`, up to `max_wait_s`.
    static constexpr double first_wait_s = 1.0, max_wait_s = 64.0, hold_s = 10.0;

private:
    int max_;
    double wait_s_ = first_wait_s;
    double last_grow_s_ = -1e300, last_shrink_s_ = -1e300;
};

/// The governor itself: call after_step() between time steps.
class ThreadGovernor {
public:
    /// Starts with max_threads (the run's --threads or every core) and never goes above it. Does
    /// nothing where /proc/stat cannot be read (not Linux).
    explicit ThreadGovernor(int max_threads);

    /// Checks the window when it is over, and changes the thread count if it must. Returns a line for
    /// the run log when it did, else an empty string.
    std::string after_step();

    bool active() const { return active_; }
    int threads() const { return threads_; }
    int max_threads() const { return policy_.max_threads(); }
    int changes() const { return changes_; }

    static constexpr double window_s = 0.25;

private:
    struct Counters {
        std::chrono::steady_clock::time_point wall;
        double cpu_s = 0.0, preemptions = 0.0, idle_s = 0.0;
    };
    Counters read() const;

    ThreadPolicy policy_;
    bool active_ = false;
    int threads_;
    int changes_ = 0;
    std::vector<int> cores_;  // the CPUs the run may use (its affinity)
    std::chrono::steady_clock::time_point start_;
    Counters last_;
};

}  // namespace grit::parallel
