// The thread governor: see thread_governor.hpp.
#include "grit/parallel/thread_governor.hpp"

#include <sched.h>
#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <ctime>
#include <fstream>
#include <sstream>

#include <fmt/format.h>

#include "grit/parallel/parallel.hpp"

namespace grit::parallel {

ThreadPolicy::ThreadPolicy(int max_threads) : max_(std::max(1, max_threads)) {}

int ThreadPolicy::next(int threads, const ThreadSample& s, double now_s) {
    if (s.wall_s <= 0.0) return threads;
    const double share = s.cpu_s / s.wall_s;
    if (threads > 1 && share < threads - 0.5 && s.preemptions / s.wall_s >= preemptions_per_second) {
        // Giving a core back soon after taking it: the core was not free after all (a process that
        // wakes now and then, a CPU quota); wait longer before the next try.
        wait_s_ = now_s - last_grow_s_ < hold_s ? std::min(2.0 * wait_s_, max_wait_s) : first_wait_s;
        last_shrink_s_ = now_s;
        return std::clamp(static_cast<int>(std::floor(share + 0.25)), 1, threads - 1);
    }
    if (threads < max_ && s.idle_cores >= idle_to_grow && now_s - last_shrink_s_ >= wait_s_) {
        last_grow_s_ = now_s;
        return std::min(max_, threads + std::max(1, static_cast<int>(std::floor(s.idle_cores + 0.25))));
    }
    return threads;
}

namespace {

double seconds_between(std::chrono::steady_clock::time_point a, std::chrono::steady_clock::time_point b) {
    return std::chrono::duration<double>(b - a).count();
}

/// Idle time [s] of the given CPUs since boot, from /proc/stat's "cpuN" lines (idle + iowait); < 0 where
/// the file cannot be read.
double idle_seconds(const std::vector<int>& cores) {
    std::ifstream in("/proc/stat");
    if (!in) return -1.0;
    static const double tick = static_cast<double>(sysconf(_SC_CLK_TCK));
    double idle = 0.0;
    std::string line;
    while (std::getline(in, line)) {
        if (line.rfind("cpu", 0) != 0) break;  // the cpu lines come first
        if (line.size() < 4 || line[3] < '0' || line[3] > '9') continue;  // the "cpu" total
        std::istringstream fields(line.substr(3));
        int cpu = -1;
        double user = 0, nice = 0, system = 0, idle_ticks = 0, iowait = 0;
        fields >> cpu >> user >> nice >> system >> idle_ticks >> iowait;
        if (std::find(cores.begin(), cores.end(), cpu) != cores.end()) idle += idle_ticks + iowait;
    }
    return idle / tick;
}

}  // namespace

ThreadGovernor::ThreadGovernor(int max_threads) : policy_(max_threads), threads_(policy_.max_threads()) {
    cpu_set_t set;
    CPU_ZERO(&set);
    if (sched_getaffinity(0, sizeof(set), &set) == 0)
        for (int c = 0; c < CPU_SETSIZE; ++c)
            if (CPU_ISSET(c, &set)) cores_.push_back(c);
    start_ = std::chrono::steady_clock::now();
    last_ = read();
    active_ = !cores_.empty() && last_.idle_s >= 0.0;
}

ThreadGovernor::Counters ThreadGovernor::read() const {
    Counters c;
    c.wall = std::chrono::steady_clock::now();
    timespec cpu{};
    if (clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &cpu) == 0)
        c.cpu_s = static_cast<double>(cpu.tv_sec) + 1e-9 * static_cast<double>(cpu.tv_nsec);
    rusage usage{};
    if (getrusage(RUSAGE_SELF, &usage) == 0) c.preemptions = static_cast<double>(usage.ru_nivcsw);
    c.idle_s = idle_seconds(cores_);
    return c;
}

std::string ThreadGovernor::after_step() {
    if (!active_) return {};
    const double window = seconds_between(last_.wall, std::chrono::steady_clock::now());
    if (window < window_s) return {};
    const Counters now = read();
    ThreadSample sample;
    sample.wall_s = seconds_between(last_.wall, now.wall);
    sample.cpu_s = now.cpu_s - last_.cpu_s;
    sample.preemptions = now.preemptions - last_.preemptions;
    sample.idle_cores = now.idle_s >= 0.0 ? (now.idle_s - last_.idle_s) / sample.wall_s : 0.0;
    last_ = now;
    const int n = policy_.next(threads_, sample, seconds_between(start_, now.wall));
    if (n == threads_) return {};
    const std::string line =
        n < threads_
            ? fmt::format("the run got {:.2f} cores' worth for {} threads and was preempted {:.0f} times a second "
                          "(another process holds a core): {} thread(s) from here, of {}",
                          sample.cpu_s / sample.wall_s, threads_, sample.preemptions / sample.wall_s, n,
                          max_threads())
            : fmt::format("{:.2f} of its cores idle: {} thread(s) from here, of {}", sample.idle_cores, n,
                          max_threads());
    threads_ = n;
    set_threads(n);
    ++changes_;
    return line;
}

}  // namespace grit::parallel
