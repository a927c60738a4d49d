// The erosion log's first removal time (summary.json's first_removal_time, the end of the paper's Stage
// One): the first record's, kept by a restart, and unknown after a restart from a checkpoint that had
// removals but no time for them.
#include <gtest/gtest.h>

#include <cmath>

#include "grit/analysis/erosion_log.hpp"

namespace {

using grit::analysis::ErosionLog;
using grit::analysis::ErosionRecord;

ErosionRecord removed_at(double time) {
    ErosionRecord r;
    r.time = time;
    r.mass = 1.0;
    return r;
}

TEST(ErosionLog, FirstRemovalTimeIsTheFirstRecordsAndSurvivesARestart) {
    ErosionLog log;
    EXPECT_TRUE(std::isnan(log.first_time()));  // nothing gone yet
    log.add(removed_at(2.5e-4));
    log.add(removed_at(1.0e-3));
    EXPECT_EQ(log.first_time(), 2.5e-4);
    EXPECT_EQ(log.total(), 2u);

    // A restart with the checkpoint's count and time: a later removal does not move it.
    ErosionLog restarted;
    restarted.restore(log.total(), log.first_time());
    restarted.add(removed_at(3.0e-3));
    EXPECT_EQ(restarted.first_time(), 2.5e-4);
    EXPECT_EQ(restarted.total(), 3u);

    // A checkpoint from before the time was saved: removals, no time. It stays unknown rather than
    // taking the next removal's time.
    ErosionLog old;
    old.restore(2, std::nan(""));
    old.add(removed_at(3.0e-3));
    EXPECT_TRUE(std::isnan(old.first_time()));

    // A checkpoint taken before any removal: the first one after it sets the time.
    ErosionLog early;
    early.restore(0, std::nan(""));
    early.add(removed_at(4.0e-3));
    EXPECT_EQ(early.first_time(), 4.0e-3);
}

}  // namespace
