// The run's first impact (the contact velocity of a single grain) over sub-domains: each holds the earliest
// impact among its grains; the run's is the earliest of those, and of impacts in one step the lowest grain
// id, whichever sub-domain holds it and in whichever order the contacts were found.
#include <gtest/gtest.h>

#include <cmath>
#include <mutex>
#include <vector>

#include "grit/wear/impact_log.hpp"
#include "support/loopback_comm.hpp"

namespace grit::wear {
namespace {

ImpactRecord impact(double time, domain::ParticleId grain, double speed) {
    ImpactRecord r;
    r.time = time;
    r.grain = grain;
    r.target = "wall";
    r.speed = speed;
    return r;
}

TEST(ImpactLog, FirstImpactIsTheEarliestThenTheLowestGrainIdWhateverTheOrder) {
    ImpactLog log;
    const domain::SerialComm one;
    EXPECT_TRUE(std::isnan(log.first_speed(one)));
    log.add(impact(2e-6, 9, 100.0));
    log.add(impact(1e-6, 7, 120.0));  // earlier, found later
    log.add(impact(1e-6, 5, 130.0));  // the same step, a lower id
    log.add(impact(1e-6, 6, 140.0));
    EXPECT_EQ(log.first_speed(one), 130.0);
}

TEST(ImpactLog, FirstImpactOverSubDomainsIsTheWholeRunsOne) {
    // Rank 0 holds the earliest time but a higher id than rank 2's impact in the same step; rank 1 has none.
    const std::vector<std::vector<ImpactRecord>> held = {
        {impact(3e-6, 4, 90.0), impact(1e-6, 8, 110.0)}, {}, {impact(1e-6, 3, 150.0), impact(5e-6, 1, 60.0)}};
    ImpactLog all;
    for (const auto& rank : held)
        for (const auto& r : rank) all.add(r);
    const double whole = all.first_speed(domain::SerialComm{});
    EXPECT_EQ(whole, 150.0);
    std::mutex lock;
    std::vector<double> seen;
    grit::testing::run_loopback(3, [&](const domain::Comm& comm) {
        ImpactLog log;
        for (const auto& r : held[static_cast<std::size_t>(comm.rank())]) log.add(r);
        const double first = log.first_speed(comm);
        const std::lock_guard guard(lock);
        seen.push_back(first);
    });
    ASSERT_EQ(seen.size(), 3u);
    for (const double s : seen) EXPECT_EQ(s, whole);
}

}  // namespace
}  // namespace grit::wear
