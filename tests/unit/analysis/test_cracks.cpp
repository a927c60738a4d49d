// Crack analysis on hand-built particle sets: which particles count as damaged, which are linked into one
// crack, and the clusters against a brute-force search for one and several threads.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <vector>

#include "grit/analysis/cracks.hpp"
#include "grit/core/error.hpp"
#include "grit/parallel/parallel.hpp"

using grit::Index;
using grit::Phase;
using grit::analysis::analyse_cracks;
using grit::analysis::CrackOptions;

namespace {

constexpr double dx = 1e-3;     // lattice spacing [m]
constexpr double rho0 = 2500.0;  // [kg/m^3]

/// Appends a solid particle at x with mass rho0 * dx^Dim and returns its index.
template <int Dim>
Index add_solid(grit::particles::SphParticles<Dim>& ps, const grit::core::Vec<Dim>& x) {
    const Index i = ps.append(1);
    ps.position()[i] = x;
    ps.phase()[i] = static_cast<std::int32_t>(Phase::solid);
    ps.density()[i] = rho0;
    ps.mass()[i] = rho0 * (Dim == 2 ? dx * dx : dx * dx * dx);
    return i;
}

CrackOptions options(double link, Index min_particles = 3, double threshold = 0.5) {
    CrackOptions o;
    o.link_distance = link;
    o.min_particles = min_particles;
    o.damage_threshold = threshold;
    return o;
}

}  // namespace

// 20 x 20 solid lattice: a damaged line of 8 (row 3), one of 5 (row 10), one isolated damaged particle,
// and a damaged fluid particle touching the line of 5 that must neither count nor lengthen it.
TEST(Cracks, TwoLinesInALattice) {
    grit::particles::SphParticles<2> ps;
    auto at = [](Index i, Index j) { return i + 20 * j; };
    for (Index j = 0; j < 20; ++j)
        for (Index i = 0; i < 20; ++i) add_solid<2>(ps, {{i * dx, j * dx}});
    std::vector<double> damage(static_cast<std::size_t>(ps.size()), 0.1);
    for (Index i = 2; i < 10; ++i) damage[at(i, 3)] = 0.9;
    for (Index i = 2; i < 7; ++i) damage[at(i, 10)] = 0.8;
    damage[at(15, 15)] = 1.0;
    ps.phase()[at(7, 10)] = static_cast<std::int32_t>(Phase::fluid);
    damage[at(7, 10)] = 1.0;

    const auto r = analyse_cracks<2>(ps, damage.data(), options(1.5 * dx));
    EXPECT_EQ(r.damaged_particles, 14);
    EXPECT_EQ(r.crack_count, 2);
    EXPECT_EQ(r.largest_crack, 8);
    EXPECT_NEAR(r.damaged_area, 14 * dx * dx, 1e-12 * dx * dx);

    // With min_particles 1 the isolated particle is a crack too; with 6 only the line of 8 is.
    EXPECT_EQ(analyse_cracks<2>(ps, damage.data(), options(1.5 * dx, 1)).crack_count, 3);
    EXPECT_EQ(analyse_cracks<2>(ps, damage.data(), options(1.5 * dx, 6)).crack_count, 1);
    // A link of 8 spacings joins the two lines (7 rows apart) but not the isolated particle.
    const auto wide = analyse_cracks<2>(ps, damage.data(), options(8.0 * dx));
    EXPECT_EQ(wide.crack_count, 1);
    EXPECT_EQ(wide.largest_crack, 13);
}

// Neighbours on a diagonal are sqrt(2) spacings apart: linked by 1.5 spacings, not by 1.2.
TEST(Cracks, DiagonalChainLinksOnlyWithinLinkDistance) {
    grit::particles::SphParticles<2> ps;
    for (Index i = 0; i < 6; ++i) add_solid<2>(ps, {{i * dx, i * dx}});
    const std::vector<double> damage(6, 1.0);

    const auto linked = analyse_cracks<2>(ps, damage.data(), options(1.5 * dx));
    EXPECT_EQ(linked.crack_count, 1);
    EXPECT_EQ(linked.largest_crack, 6);
    const auto apart = analyse_cracks<2>(ps, damage.data(), options(1.2 * dx));
    EXPECT_EQ(apart.damaged_particles, 6);
    EXPECT_EQ(apart.crack_count, 0);
    EXPECT_EQ(apart.largest_crack, 1);
}

// A damaged line that crosses a periodic face (x in [0, 20 dx)): one crack of 8 with the box, two of 4
// without it; a link distance of half the period or more is refused.
TEST(Cracks, ALineAcrossAPeriodicFaceIsOneCrack) {
    grit::particles::SphParticles<2> ps;
    auto at = [](Index i, Index j) { return i + 20 * j; };
    for (Index j = 0; j < 10; ++j)
        for (Index i = 0; i < 20; ++i) add_solid<2>(ps, {{(i + 0.5) * dx, j * dx}});
    std::vector<double> damage(static_cast<std::size_t>(ps.size()), 0.0);
    for (Index i : {16, 17, 18, 19, 0, 1, 2, 3}) damage[at(i, 4)] = 1.0;
    const auto box = grit::neighbors::PeriodicBox<2>::make({true, false}, {{0.0, -1.0}}, {{20 * dx, 1.0}});

    const auto across = analyse_cracks<2>(ps, damage.data(), options(1.5 * dx), box);
    EXPECT_EQ(across.crack_count, 1);
    EXPECT_EQ(across.largest_crack, 8);
    const auto open = analyse_cracks<2>(ps, damage.data(), options(1.5 * dx));
    EXPECT_EQ(open.crack_count, 2);
    EXPECT_EQ(open.largest_crack, 4);
    EXPECT_THROW(analyse_cracks<2>(ps, damage.data(), options(10.0 * dx), box), grit::core::InputError);
}

// D exactly at the threshold is damaged; just below is not, and splits the line in two.
TEST(Cracks, DamageAtThresholdCounts) {
    grit::particles::SphParticles<2> ps;
    for (Index i = 0; i < 7; ++i) add_solid<2>(ps, {{i * dx, 0.0}});
    const std::vector<double> damage{0.5, 0.5, 0.5, 0.4999, 0.5, 0.5, 0.5};

    const auto r = analyse_cracks<2>(ps, damage.data(), options(1.1 * dx));
    EXPECT_EQ(r.damaged_particles, 6);
    EXPECT_EQ(r.crack_count, 2);
    EXPECT_EQ(r.largest_crack, 3);
    const auto lower = analyse_cracks<2>(ps, damage.data(), options(1.1 * dx, 3, 0.4999));
    EXPECT_EQ(lower.damaged_particles, 7);
    EXPECT_EQ(lower.crack_count, 1);
    EXPECT_EQ(lower.largest_crack, 7);
    const auto none = analyse_cracks<2>(ps, damage.data(), options(1.1 * dx, 3, 0.6));
    EXPECT_EQ(none.damaged_particles, 0);
    EXPECT_EQ(none.crack_count, 0);
    EXPECT_EQ(none.largest_crack, 0);
    EXPECT_EQ(none.damaged_area, 0.0);
}

// 3D: a damaged 3 x 3 patch in a plane and a line of 4 three spacings from it; face neighbours only.
TEST(Cracks, PatchAndLineIn3D) {
    grit::particles::SphParticles<3> ps;
    std::vector<double> damage;
    for (Index k = 0; k < 6; ++k)
        for (Index j = 0; j < 6; ++j)
            for (Index i = 0; i < 6; ++i) {
                add_solid<3>(ps, {{i * dx, j * dx, k * dx}});
                const bool patch = i <= 2 && j <= 2 && k == 2;
                const bool line = i == 5 && j == 0 && k <= 3;
                damage.push_back(patch || line ? 0.7 : 0.0);
            }
    const auto r = analyse_cracks<3>(ps, damage.data(), options(1.1 * dx));
    EXPECT_EQ(r.damaged_particles, 13);
    EXPECT_EQ(r.crack_count, 2);
    EXPECT_EQ(r.largest_crack, 9);
    EXPECT_NEAR(r.damaged_area, 13 * dx * dx * dx, 1e-12 * dx * dx * dx);
    // Three spacings apart: a link of 3.1 spacings joins them.
    EXPECT_EQ(analyse_cracks<3>(ps, damage.data(), options(3.1 * dx)).largest_crack, 13);
}

// Two small cracks 100 m apart with a 1 mm link: the grid must not need a cell per millimetre.
TEST(Cracks, SparseDamageOverALargeRegion) {
    grit::particles::SphParticles<2> ps;
    for (Index i = 0; i < 3; ++i) add_solid<2>(ps, {{i * dx, 0.0}});
    for (Index i = 0; i < 3; ++i) add_solid<2>(ps, {{100.0 + i * dx, 0.0}});
    const std::vector<double> damage(6, 1.0);
    const auto r = analyse_cracks<2>(ps, damage.data(), options(1.5 * dx));
    EXPECT_EQ(r.crack_count, 2);
    EXPECT_EQ(r.largest_crack, 3);
}

// Random damage in a random cloud: clusters as a brute-force all-pairs search finds them, the same for
// one and two threads (enough damaged particles for the parallel loops to run in parallel).
TEST(Cracks, MatchesBruteForceForOneAndTwoThreads) {
    grit::particles::SphParticles<2> ps;
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(0.0, 0.1);
    std::vector<double> damage;
    for (Index i = 0; i < 6000; ++i) {
        add_solid<2>(ps, {{u(rng), u(rng)}});
        damage.push_back(u(rng) * 10.0);
    }
    const double link = 1.2e-3;
    const auto opts = options(link, 4);

    std::vector<Index> damaged;
    for (Index i = 0; i < ps.size(); ++i)
        if (damage[i] >= 0.5) damaged.push_back(i);
    std::vector<Index> label(damaged.size());
    for (std::size_t a = 0; a < label.size(); ++a) label[a] = static_cast<Index>(a);
    for (bool changed = true; changed;) {  // label propagation to the smallest label in each cluster
        changed = false;
        for (std::size_t a = 0; a < damaged.size(); ++a)
            for (std::size_t b = 0; b < damaged.size(); ++b)
                if (label[b] < label[a] &&
                    grit::core::norm2(ps.position()[damaged[a]] - ps.position()[damaged[b]]) <= link * link) {
                    label[a] = label[b];
                    changed = true;
                }
    }
    std::vector<Index> size(label.size(), 0);
    for (const Index l : label) ++size[static_cast<std::size_t>(l)];
    const auto cracks = static_cast<Index>(std::count_if(size.begin(), size.end(), [](Index s) { return s >= 4; }));
    const Index largest = *std::max_element(size.begin(), size.end());
    ASSERT_GT(damaged.size(), 2048u);  // parallel::serial_below
    ASSERT_GT(cracks, 10);  // the case has several clusters, not one or none

    for (const int threads : {1, 2}) {
        grit::parallel::set_threads(threads);
        const auto r = analyse_cracks<2>(ps, damage.data(), opts);
        EXPECT_EQ(r.damaged_particles, static_cast<Index>(damaged.size())) << threads << " threads";
        EXPECT_EQ(r.crack_count, cracks) << threads << " threads";
        EXPECT_EQ(r.largest_crack, largest) << threads << " threads";
    }
}

TEST(Cracks, RejectsANonPositiveLinkDistance) {
    grit::particles::SphParticles<2> ps;
    add_solid<2>(ps, {{0.0, 0.0}});
    const std::vector<double> damage(1, 1.0);
    EXPECT_THROW(analyse_cracks<2>(ps, damage.data(), options(0.0)), grit::core::InputError);
    EXPECT_THROW(analyse_cracks<2>(ps, damage.data(), options(-1e-3)), grit::core::InputError);
}
