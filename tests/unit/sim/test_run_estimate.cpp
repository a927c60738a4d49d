// The warnings `grit run` prints from a run's estimate (sim/run_estimate.hpp).
#include <gtest/gtest.h>

#include <string>

#include "grit/io/case_spec.hpp"
#include "grit/sim/run_estimate.hpp"

namespace {

grit::io::CaseSpec spec_of_a_long_run() {
    grit::io::CaseSpec spec;
    spec.end_time = 0.03;
    spec.output_interval = 1e-6;
    spec.particle_spacing = 1e-4;
    return spec;
}

bool has(const std::string& text, const std::string& part) {
    return text.find(part) != std::string::npos;
}

}  // namespace

// The paper's 30 ms of the AWJ with the case's output every microsecond: 30,001 snapshots, tens of GB.
TEST(RunEstimate, SnapshotsBeyondTheFreeSpaceAreWarnedOfNamingTheKeys) {
    grit::sim::RunEstimate e;
    e.outputs = 30001.0;
    e.snapshot_bytes = 6.6e10;
    e.wall_seconds = 3600.0;
    const auto warnings = e.warnings(spec_of_a_long_run(), 2.0e10);
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_TRUE(has(warnings[0], "66 GB")) << warnings[0];
    EXPECT_TRUE(has(warnings[0], "20 GB are free")) << warnings[0];
    EXPECT_TRUE(has(warnings[0], "output.interval = 1e-06 s")) << warnings[0];
    EXPECT_TRUE(has(warnings[0], "output.snapshots = false")) << warnings[0];
    // Room enough, or the free space unknown: nothing to say.
    EXPECT_TRUE(e.warnings(spec_of_a_long_run(), 1.0e11).empty());
    EXPECT_TRUE(e.warnings(spec_of_a_long_run(), -1.0).empty());
}

TEST(RunEstimate, RunsOverADayAreWarnedOf) {
    grit::sim::RunEstimate e;
    e.wall_seconds = 2.5 * 86400.0;
    const auto warnings = e.warnings(spec_of_a_long_run(), -1.0);
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_TRUE(has(warnings[0], "may take 2.5 days")) << warnings[0];
    e.wall_seconds = 86000.0;
    EXPECT_TRUE(e.warnings(spec_of_a_long_run(), -1.0).empty());
}
