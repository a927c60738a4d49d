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
    const auto warnings = e.warnings(spec_of_a_long_run(), 2.0e10, -1.0);
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_TRUE(has(warnings[0], "66 GB")) << warnings[0];
    EXPECT_TRUE(has(warnings[0], "20 GB are free")) << warnings[0];
    EXPECT_TRUE(has(warnings[0], "output.interval = 1e-06 s")) << warnings[0];
    EXPECT_TRUE(has(warnings[0], "output.snapshots = false")) << warnings[0];
    // Room enough, or the free space unknown: nothing to say.
    EXPECT_TRUE(e.warnings(spec_of_a_long_run(), 1.0e11, -1.0).empty());
    EXPECT_TRUE(e.warnings(spec_of_a_long_run(), -1.0, -1.0).empty());
}

TEST(RunEstimate, RunsOverADayAreWarnedOf) {
    grit::sim::RunEstimate e;
    e.wall_seconds = 2.5 * 86400.0;
    const auto warnings = e.warnings(spec_of_a_long_run(), -1.0, -1.0);
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_TRUE(has(warnings[0], "may take 2.5 days")) << warnings[0];
    e.wall_seconds = 86000.0;
    EXPECT_TRUE(e.warnings(spec_of_a_long_run(), -1.0, -1.0).empty());
}

// The paper's spacing over the whole specimen in 3D: more memory than is available now is warned of; more
// than the machine has is refused, naming the spacing and the estimate.
TEST(RunEstimate, MemoryBeyondTheMachineIsRefusedAndBeyondWhatIsFreeWarnedOf) {
    grit::sim::RunEstimate e;
    e.particles = 2.0e8;
    e.memory_bytes = 6.0e10;
    const auto warnings = e.warnings(spec_of_a_long_run(), -1.0, 2.0e10);
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_TRUE(has(warnings[0], "60 GB of memory, 20 GB are available")) << warnings[0];
    EXPECT_TRUE(e.warnings(spec_of_a_long_run(), -1.0, 1.0e11).empty());
    const std::string why = e.does_not_fit(spec_of_a_long_run(), 2.4e10);
    EXPECT_TRUE(has(why, "key 'numerics.particle_spacing' = 0.0001")) << why;
    EXPECT_TRUE(has(why, "about 60 GB")) << why;
    EXPECT_TRUE(has(why, "this machine's 24 GB")) << why;
    EXPECT_TRUE(e.does_not_fit(spec_of_a_long_run(), 1.0e11).empty());
    EXPECT_TRUE(e.does_not_fit(spec_of_a_long_run(), -1.0).empty());
    const auto machine = grit::sim::machine_memory();
    EXPECT_GT(machine.total, 1e8);
    EXPECT_GT(machine.available, 0.0);
    EXPECT_LE(machine.available, machine.total);
}
