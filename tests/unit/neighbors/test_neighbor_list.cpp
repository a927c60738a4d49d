// Neighbour lists from the cell grid match a brute-force search, in 2D and 3D.
#include <gtest/gtest.h>

#include <algorithm>
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
