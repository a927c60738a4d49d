// The thread governor's decisions on made-up samples (what a 2-core machine measured: alone, two
// threads get 2.00 cores' worth and 20-90 preemptions a second; beside a busy process 1.0-1.2 cores and
// about 250-280 a second).
#include <gtest/gtest.h>

#include <algorithm>

#include "grit/parallel/parallel.hpp"
#include "grit/parallel/thread_governor.hpp"

using grit::parallel::ThreadPolicy;
using grit::parallel::ThreadSample;

namespace {

ThreadSample sample(double cores_used, double preemptions_per_s, double idle_cores) {
    ThreadSample s;
    s.wall_s = 0.25;
    s.cpu_s = cores_used * s.wall_s;
    s.preemptions = preemptions_per_s * s.wall_s;
    s.idle_cores = idle_cores;
    return s;
}

}  // namespace

TEST(ThreadPolicy, AloneKeepsItsThreads) {
    ThreadPolicy policy(2);
    EXPECT_EQ(policy.next(2, sample(2.0, 90.0, 0.0), 1.0), 2);
    EXPECT_EQ(policy.next(2, sample(1.98, 40.0, 0.02), 1.25), 2);
}

TEST(ThreadPolicy, BesideABusyProcessGivesACoreBack) {
    ThreadPolicy policy(2);
    EXPECT_EQ(policy.next(2, sample(1.19, 280.0, 0.0), 1.0), 1);
    // 16 threads of which 4 cores are taken: 12.
    ThreadPolicy wide(16);
    EXPECT_EQ(wide.next(16, sample(12.0, 2000.0, 0.0), 1.0), 12);
    // Never fewer than one.
    EXPECT_EQ(wide.next(4, sample(0.3, 2000.0, 0.0), 2.0), 1);
}

TEST(ThreadPolicy, ASerialStretchIsNotAnotherProcess) {
    // Threads that sleep through a serial stretch (writing a snapshot) use less CPU, but nothing takes
    // their cores: few preemptions.
    ThreadPolicy policy(2);
    EXPECT_EQ(policy.next(2, sample(1.05, 20.0, 0.9), 1.0), 2);
}

TEST(ThreadPolicy, TakesAFreeCoreBackAfterAWait) {
    ThreadPolicy policy(2);
    ASSERT_EQ(policy.next(2, sample(1.0, 250.0, 0.0), 10.0), 1);
    EXPECT_EQ(policy.next(1, sample(1.0, 5.0, 0.5), 11.5), 1);  // not idle enough
    EXPECT_EQ(policy.next(1, sample(1.0, 5.0, 1.0), 10.5), 1);  // idle, but within the first wait (1 s)
    EXPECT_EQ(policy.next(1, sample(1.0, 5.0, 1.0), 11.0), 2);  // a second after giving it back
    EXPECT_EQ(policy.next(2, sample(2.0, 40.0, 1.0), 12.0), 2);  // never above the maximum
}

TEST(ThreadPolicy, TriesLessOftenWhenTheFreeCoreIsNotFree) {
    // A core that looks idle but is not the run's to use (a CPU quota; a process that wakes now and
    // then): each try that fails within 10 s doubles the wait before the next, up to 64 s.
    ThreadPolicy policy(2);
    double t = 0.0;
    ASSERT_EQ(policy.next(2, sample(1.0, 250.0, 0.0), t), 1);
    double expected_wait = ThreadPolicy::first_wait_s;
    for (int attempt = 0; attempt < 9; ++attempt) {
        EXPECT_EQ(policy.next(1, sample(1.0, 5.0, 1.0), t + expected_wait - 0.01), 1) << "attempt " << attempt;
        t += expected_wait;
        ASSERT_EQ(policy.next(1, sample(1.0, 5.0, 1.0), t), 2) << "attempt " << attempt;
        t += 0.25;
        ASSERT_EQ(policy.next(2, sample(1.0, 250.0, 0.0), t), 1);
        expected_wait = std::min(2.0 * expected_wait, ThreadPolicy::max_wait_s);
    }
    EXPECT_EQ(expected_wait, ThreadPolicy::max_wait_s);
    // A try that holds longer than 10 s resets the wait.
    t += expected_wait;
    ASSERT_EQ(policy.next(1, sample(1.0, 5.0, 1.0), t), 2);
    t += 20.0;
    ASSERT_EQ(policy.next(2, sample(1.0, 250.0, 0.0), t), 1);
    EXPECT_EQ(policy.next(1, sample(1.0, 5.0, 1.0), t + ThreadPolicy::first_wait_s), 2);
}

TEST(ThreadGovernor, ReadsThisMachineAndChangesNothingWithinAWindow) {
    const int before = grit::parallel::max_threads();
    grit::parallel::ThreadGovernor governor(2);
#ifdef __linux__
    EXPECT_TRUE(governor.active());
#endif
    EXPECT_EQ(governor.threads(), 2);
    EXPECT_EQ(governor.after_step(), "");  // the first window is not over
    EXPECT_EQ(governor.changes(), 0);
    EXPECT_EQ(grit::parallel::max_threads(), before);
}
