// Neighbour lists from the cell grid match a brute-force search, in 2D and 3D.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <set>

#include "grit/neighbors/cell_grid.hpp"
#include "grit/neighbors/neighbor_list.hpp"

using grit::Index;

template <int Dim>
void check_against_brute_force(Index n, double radius, unsigned seed) {
    using Vec = grit::core::Vec<Dim>;
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(-0.3, 1.7);
    std::vector<Vec> x(static_cast<std::size_t>(n));
    for (auto& p : x)
        for (int k = 0; k < Dim; ++k) p[k] = u(rng);

    auto grid = grit::neighbors::CellGrid<Dim>::covering(x.data(), n, radius);
    std::vector<Index> order, cell_start;
    grit::neighbors::sort_by_cell(grid, x.data(), n, order, cell_start);
    std::vector<Vec> sorted(x.size());
    for (std::size_t i = 0; i < x.size(); ++i) sorted[i] = x[static_cast<std::size_t>(order[i])];
    // Sorting puts each cell's particles together.
    for (std::size_t i = 0; i + 1 < sorted.size(); ++i) EXPECT_LE(grid.cell_of(sorted[i]), grid.cell_of(sorted[i + 1]));

    grit::neighbors::NeighborList<Dim> list;
    list.build(grid, cell_start, sorted.data(), n, radius);
    for (Index i = 0; i < n; ++i) {
        std::set<Index> expected, found;
        for (Index j = 0; j < n; ++j)
            if (j != i && grit::core::norm2(sorted.at(static_cast<std::size_t>(i)) -
                                            sorted.at(static_cast<std::size_t>(j))) < radius * radius)
                expected.insert(j);
        for (Index k = list.begin(i); k < list.end(i); ++k) found.insert(list.indices()[k]);
        ASSERT_EQ(found, expected) << "particle " << i;
    }
    EXPECT_EQ(list.max_displacement2(sorted.data(), n), 0.0);
}

TEST(NeighborList, MatchesBruteForce2D) { check_against_brute_force<2>(1500, 0.1, 1); }
TEST(NeighborList, MatchesBruteForce3D) { check_against_brute_force<3>(1500, 0.25, 2); }
TEST(NeighborList, HandlesASingleParticle) { check_against_brute_force<3>(1, 0.25, 3); }

// Walls thinner than the kernel: a pair is listed unless its normals are more than 90 degrees apart, or
// more than 60 (far_cos = 0.5) when one of the two is a far-side wall particle; a zero normal pairs with
// every particle.
TEST(NeighborList, SideSeparationLeavesOutPairsOnOppositeSides) {
    using Vec = grit::core::Vec<3>;
    const Index n = 800;
    const double radius = 0.3;
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    std::vector<Vec> x(static_cast<std::size_t>(n));
    for (auto& p : x)
        for (int k = 0; k < 3; ++k) p[k] = u(rng);
    auto grid = grit::neighbors::CellGrid<3>::covering(x.data(), n, radius);
    std::vector<Index> order, cell_start;
    grit::neighbors::sort_by_cell(grid, x.data(), n, order, cell_start);
    std::vector<Vec> sorted(x.size()), normal(x.size());
    std::vector<std::int32_t> far(x.size(), 0);
    for (std::size_t i = 0; i < x.size(); ++i) {
        sorted[i] = x[static_cast<std::size_t>(order[i])];
        // A membrane at x = 0.5: particles within 0.2 of it carry a normal on their side, tilted at
        // random; every fifth is a far-side wall particle.
        const double gap = sorted[i][0] - 0.5;
        if (std::abs(gap) < 0.2) {
            const Vec t{{gap > 0.0 ? 1.0 : -1.0, 0.0, 3.0 * (u(rng) - 0.5)}};
            normal[i] = t * (1.0 / grit::core::norm(t));
            far[i] = i % 5 == 0;
        }
    }
    const grit::neighbors::SideSeparation<3> sides{normal.data(), far.data(), 0.5};
    grit::neighbors::NeighborList<3> list;
    list.build(grid, cell_start, sorted.data(), n, radius, nullptr, {}, &sides);
    std::size_t across = 0, far_apart = 0;
    for (Index i = 0; i < n; ++i) {
        std::set<Index> expected, found;
        for (Index j = 0; j < n; ++j) {
            const auto a = static_cast<std::size_t>(i), b = static_cast<std::size_t>(j);
            if (j == i || grit::core::norm2(sorted[a] - sorted[b]) >= radius * radius) continue;
            const bool both = grit::core::norm2(normal[a]) > 0.0 && grit::core::norm2(normal[b]) > 0.0;
            const double angle = both ? std::acos(std::clamp(grit::core::dot(normal[a], normal[b]), -1.0, 1.0)) * 180.0 / M_PI : 0.0;
            if (angle > 90.0) {
                ++across;
                continue;
            }
            if ((far[a] || far[b]) && angle > 60.0) {
                ++far_apart;
                continue;
            }
            expected.insert(j);
        }
        for (Index k = list.begin(i); k < list.end(i); ++k) found.insert(list.indices()[k]);
        ASSERT_EQ(found, expected) << "particle " << i;
    }
    // The test has pairs of both kinds to leave out.
    EXPECT_GT(across, 1000u);
    EXPECT_GT(far_apart, 100u);
}
