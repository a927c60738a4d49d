// Output times as products of their interval, and an end time snapped onto them (sim/output_times.hpp).
#include <gtest/gtest.h>

#include "grit/sim/output_times.hpp"

using grit::sim::Cadence;

// Six additions of 2e-5 give 1.2e-4; the product 6 x 2e-5 is 1.2000000000000002e-4. The cadence
// knows only products, so a run that ends at an output and one that passes it aim at the same double.
TEST(OutputTimes, OutputKIsKTimesTheInterval) {
    const Cadence c{2e-5};
    double sum = 0.0;
    for (int k = 0; k < 6; ++k) sum += 2e-5;
    EXPECT_NE(sum, c.at(6));
    EXPECT_EQ(c.at(6), 6.0 * 2e-5);
    EXPECT_EQ(c.at(0), 0.0);
}

// The next output after a time: the first product beyond it by more than round-off, whether the time
// lies just below, on or just above an output time.
TEST(OutputTimes, NextAfterSkipsTheOutputATimeLiesOn) {
    const Cadence c{2e-5};
    EXPECT_EQ(c.next_after(0.0), 1);
    EXPECT_EQ(c.next_after(1e-5), 1);
    EXPECT_EQ(c.next_after(c.at(6)), 7);
    EXPECT_EQ(c.next_after(c.at(6) * (1.0 - 1e-14)), 7);  // landed a few units short: that output is written
    EXPECT_EQ(c.next_after(c.at(6) * (1.0 + 1e-14)), 7);
    EXPECT_EQ(c.next_after(c.at(6) * (1.0 - 1e-9)), 6);   // still short of it: it is the next
    EXPECT_EQ(c.next_after(1.23e-4), 7);
    const Cadence tenth{0.1};
    for (long k = 0; k < 100000; k += 997) {
        EXPECT_EQ(tenth.next_after(tenth.at(k)), k + 1) << k;
        EXPECT_EQ(tenth.next_after(0.5 * (tenth.at(k) + tenth.at(k + 1))), k + 1) << k;
    }
}

// An end within 1e-12 (relative) of an output time is that output time; one further off stays as given.
TEST(OutputTimes, EndOnAnOutputTimeIsSnappedOntoIt) {
    const Cadence c{2.5e-6};
    EXPECT_EQ(c.snap(7.5e-6), c.at(3));
    EXPECT_NE(7.5e-6, c.at(3));
    EXPECT_EQ(c.snap(2e-5), c.at(8));
    EXPECT_EQ(c.snap(7.6e-6), 7.6e-6);
    EXPECT_EQ(c.snap(0.0), 0.0);
    const Cadence d{2e-5};
    EXPECT_EQ(d.snap(1.2e-4), d.at(6));
}
