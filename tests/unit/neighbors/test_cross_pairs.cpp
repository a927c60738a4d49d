// The cross-set pair list against a brute-force search over every (point, body) pair, and the same list
// at 1 and 2 threads.
#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "grit/neighbors/cross_pairs.hpp"
#include "grit/parallel/parallel.hpp"

using grit::Index;
using grit::neighbors::CrossPairList;

namespace {

template <int Dim>
struct Sets {
    std::vector<grit::core::Vec<Dim>> a, b;
    std::vector<double> radius;
};

/// Points spread over a box larger than the bodies' (so some are far from every body), bodies of radii
/// between r_min and r_max.
template <int Dim>
Sets<Dim> random_sets(Index na, Index nb, double r_min, double r_max, unsigned seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    Sets<Dim> s;
    s.a.resize(static_cast<std::size_t>(na));
    s.b.resize(static_cast<std::size_t>(nb));
    s.radius.resize(static_cast<std::size_t>(nb));
    for (auto& p : s.a)
        for (int k = 0; k < Dim; ++k) p[k] = -0.3 + 1.6 * u(rng);
    for (std::size_t i = 0; i < s.b.size(); ++i) {
        for (int k = 0; k < Dim; ++k) s.b[i][k] = u(rng);
        s.radius[i] = r_min + (r_max - r_min) * u(rng);
    }
    if (na > 2 && nb > 1) s.a[1] = s.b[0];  // a point at a body's centre
    return s;
}

template <int Dim>
void check_against_brute_force(Index na, Index nb, double r_min, double r_max, double reach, unsigned seed) {
    const auto s = random_sets<Dim>(na, nb, r_min, r_max, seed);
    auto keep = [](Index a) { return a % 3 != 2; };
    CrossPairList<Dim> list;
    list.build(s.a.data(), na, keep, s.b.data(), s.radius.data(), nb, reach);
    ASSERT_EQ(list.point_count(), na);
    std::size_t pairs = 0;
    for (Index a = 0; a < na; ++a) {
        std::vector<Index> expected;
        if (keep(a))
            for (Index b = 0; b < nb; ++b) {
                const double r = s.radius[static_cast<std::size_t>(b)] + reach;
                if (grit::core::norm2(s.a[static_cast<std::size_t>(a)] - s.b[static_cast<std::size_t>(b)]) < r * r)
                    expected.push_back(b);
            }
        const std::vector<Index> got(list.indices() + list.begin(a), list.indices() + list.end(a));
        ASSERT_EQ(got, expected) << "point " << a;  // same bodies, ascending
        pairs += got.size();
    }
    EXPECT_EQ(list.pair_count(), pairs);
    EXPECT_GT(pairs, static_cast<std::size_t>(na) / 20);  // not a vacuous test
}

}  // namespace

TEST(CrossPairList, MatchesBruteForce2D) { check_against_brute_force<2>(4000, 300, 0.01, 0.06, 0.02, 1); }
TEST(CrossPairList, MatchesBruteForce3D) { check_against_brute_force<3>(4000, 500, 0.02, 0.1, 0.03, 2); }
TEST(CrossPairList, MatchesBruteForceWithEqualRadiiAndNoReach) {
    check_against_brute_force<3>(3000, 200, 0.08, 0.08, 0.0, 3);
}
TEST(CrossPairList, MatchesBruteForceWithOneBody) { check_against_brute_force<2>(500, 1, 0.2, 0.2, 0.05, 4); }

TEST(CrossPairList, EmptySetsGiveEmptyRows) {
    const auto s = random_sets<2>(50, 10, 0.05, 0.1, 5);
    CrossPairList<2> list;
    list.build(s.a.data(), 50, [](Index) { return true; }, s.b.data(), s.radius.data(), 0, 0.1);
    EXPECT_EQ(list.point_count(), 50);
    EXPECT_EQ(list.pair_count(), 0u);
    EXPECT_EQ(list.end(49), 0);
    list.build(s.a.data(), 0, [](Index) { return true; }, s.b.data(), s.radius.data(), 10, 0.1);
    EXPECT_EQ(list.point_count(), 0);
    EXPECT_EQ(list.pair_count(), 0u);
    list.build(s.a.data(), 50, [](Index) { return false; }, s.b.data(), s.radius.data(), 10, 0.1);
    EXPECT_EQ(list.point_count(), 50);
    EXPECT_EQ(list.pair_count(), 0u);
}

TEST(CrossPairList, SameListAtOneAndTwoThreads) {
    // Enough points and bodies for the parallel loops to run in parallel (parallel::serial_below).
    const Index na = 4 * grit::parallel::serial_below, nb = 2 * grit::parallel::serial_below;
    const auto s = random_sets<3>(na, nb, 0.005, 0.02, 6);
    auto keep = [](Index a) { return a % 5 != 0; };
    const int threads = grit::parallel::max_threads();
    CrossPairList<3> one, two;
    grit::parallel::set_threads(1);
    one.build(s.a.data(), na, keep, s.b.data(), s.radius.data(), nb, 0.01);
    grit::parallel::set_threads(2);
    two.build(s.a.data(), na, keep, s.b.data(), s.radius.data(), nb, 0.01);
    grit::parallel::set_threads(threads);
    ASSERT_GT(one.pair_count(), 0u);
    ASSERT_EQ(one.pair_count(), two.pair_count());
    for (Index a = 0; a < na; ++a) ASSERT_EQ(one.end(a), two.end(a)) << "point " << a;
    EXPECT_EQ(std::vector<Index>(one.indices(), one.indices() + one.pair_count()),
              std::vector<Index>(two.indices(), two.indices() + two.pair_count()));
}

// The fluid-grain coupling keeps a list found with a skin and refines it each step: once points and bodies
// have moved less than the skin together, the refined list is the list a fresh search gives, row for row.
TEST(CrossPairList, RefiningAListFoundWithASkinGivesTheFreshList3D) {
    constexpr Index na = 3000, nb = 300;
    auto s = random_sets<3>(na, nb, 0.06, 0.12, 6);
    auto keep = [](Index a) { return a % 4 != 3; };
    const double skin = 0.02;
    CrossPairList<3> wider;
    wider.build(s.a.data(), na, keep, s.b.data(), s.radius.data(), nb, skin);
    // Each point and each body moves just under skin / 2 in a random direction.
    std::mt19937_64 rng(7);
    std::normal_distribution<double> g(0.0, 1.0);
    auto move = [&](auto& points) {
        for (auto& p : points) {
            grit::core::Vec<3> d{{g(rng), g(rng), g(rng)}};
            p += d * (0.499 * skin / grit::core::norm(d));
        }
    };
    move(s.a);
    move(s.b);
    CrossPairList<3> fresh, refined;
    fresh.build(s.a.data(), na, keep, s.b.data(), s.radius.data(), nb, 0.0);
    refined.refine(wider, s.a.data(), s.b.data(), s.radius.data(), 0.0);
    ASSERT_EQ(refined.point_count(), na);
    ASSERT_EQ(refined.pair_count(), fresh.pair_count());
    EXPECT_GT(fresh.pair_count(), static_cast<std::size_t>(na) / 20);  // not a vacuous test
    EXPECT_LT(fresh.pair_count(), wider.pair_count());                  // the skin held more
    for (Index a = 0; a < na; ++a) {
        const std::vector<Index> want(fresh.indices() + fresh.begin(a), fresh.indices() + fresh.end(a));
        const std::vector<Index> got(refined.indices() + refined.begin(a), refined.indices() + refined.end(a));
        ASSERT_EQ(got, want) << "point " << a;
    }
}
