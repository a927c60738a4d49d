// Deterministic loops: sums do not depend on the number of threads.
#include <gtest/gtest.h>

#include <cmath>

#include "grit/parallel/parallel.hpp"

using grit::Index;

TEST(Parallel, SumIsBitIdenticalForOneAndTwoThreads) {
    const Index n = 100'003;
    auto term = [](Index i) { return std::sin(0.001 * i) * 1e-3 + 1.0 / (1.0 + i); };
    grit::parallel::set_threads(1);
    const double one = grit::parallel::sum(n, 0.0, term);
    grit::parallel::set_threads(2);
    const double two = grit::parallel::sum(n, 0.0, term);
    EXPECT_EQ(one, two);  // bit-identical, not merely close
    double serial = 0.0;
    for (Index i = 0; i < n; ++i) serial += term(i);
    EXPECT_NEAR(one, serial, 1e-12 * std::abs(serial));
}

TEST(Parallel, MinMaxAndFirstIndex) {
    const Index n = 5000;
    auto f = [](Index i) { return static_cast<double>((i * 37) % 1001); };
    EXPECT_EQ(grit::parallel::max(n, -1.0, f), 1000.0);
    EXPECT_EQ(grit::parallel::min(n, 1e9, f), 0.0);
    EXPECT_EQ(grit::parallel::first_index(n, [](Index i) { return i >= 1234 && i % 7 == 0; }), 1239);
    EXPECT_EQ(grit::parallel::first_index(n, [](Index) { return false; }), -1);
    EXPECT_EQ(grit::parallel::max(0, -1.0, f), -1.0);
}

// first_index gives the smallest matching index wherever it lies: first, last, around multiples of 512
// (where a chunked scan would cut), below and above parallel::serial_below, at 1 and 2 threads.
TEST(Parallel, FirstIndexIsTheSmallestAnywhere) {
    const Index chunk = 512;
    const int before = grit::parallel::max_threads();
    for (const int threads : {1, 2}) {
        grit::parallel::set_threads(threads);
        for (const Index n : {Index{1}, Index{700}, 3 * chunk + 5, Index{100'003}}) {
            for (const Index target : {Index{0}, chunk - 1, chunk, chunk + 1, 3 * chunk + 4, n - 1}) {
                if (target < 0 || target >= n) continue;
                // The target and every index after it match: the smallest is the target.
                EXPECT_EQ(grit::parallel::first_index(n, [&](Index i) { return i >= target; }), target)
                    << "n " << n << " target " << target << " threads " << threads;
                // Only the target and the last index match.
                EXPECT_EQ(grit::parallel::first_index(n, [&](Index i) { return i == target || i == n - 1; }), target);
            }
            EXPECT_EQ(grit::parallel::first_index(n, [](Index) { return false; }), -1);
        }
    }
    grit::parallel::set_threads(before);
}
