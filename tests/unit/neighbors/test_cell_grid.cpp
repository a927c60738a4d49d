// The cell grid: numbering in both orders, periodic axes in whole cells, the arithmetic of coords(), the
// cells around a cell, and the counting sort by cell.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <set>
#include <vector>

#include "grit/core/error.hpp"
#include "grit/neighbors/cell_grid.hpp"

using grit::Index;
using grit::neighbors::CellGrid;
using grit::neighbors::CellOrder;

namespace {

template <int Dim, CellOrder Order>
CellGrid<Dim, Order> grid_with_dims(std::array<Index, Dim> dims) {
    CellGrid<Dim, Order> g;
    g.dims = dims;
    return g;
}

}  // namespace

TEST(CellGrid, XFastestNumbering) {
    const auto g = grid_with_dims<3, CellOrder::x_fastest>({4, 3, 2});
    EXPECT_EQ(g.linear({0, 0, 0}), 0);
    EXPECT_EQ(g.linear({1, 0, 0}), 1);
    EXPECT_EQ(g.linear({0, 1, 0}), 4);
    EXPECT_EQ(g.linear({0, 0, 1}), 12);
    EXPECT_EQ(g.linear({1, 2, 1}), 1 + 4 * (2 + 3 * 1));
    const auto g2 = grid_with_dims<2, CellOrder::x_fastest>({5, 3});
    EXPECT_EQ(g2.linear({3, 2}), 3 + 5 * 2);
}

TEST(CellGrid, XSlowestNumbering) {
    const auto g = grid_with_dims<3, CellOrder::x_slowest>({4, 3, 2});
    EXPECT_EQ(g.linear({0, 0, 0}), 0);
    EXPECT_EQ(g.linear({0, 0, 1}), 1);
    EXPECT_EQ(g.linear({0, 1, 0}), 2);
    EXPECT_EQ(g.linear({1, 0, 0}), 6);
    EXPECT_EQ(g.linear({1, 2, 1}), (1 * 3 + 2) * 2 + 1);
    const auto g2 = grid_with_dims<2, CellOrder::x_slowest>({5, 3});
    EXPECT_EQ(g2.linear({3, 2}), 3 * 3 + 2);
}

TEST(CellGrid, BothNumberingsAreOneToOne) {
    const auto fast = grid_with_dims<3, CellOrder::x_fastest>({4, 3, 5});
    const auto slow = grid_with_dims<3, CellOrder::x_slowest>({4, 3, 5});
    std::set<Index> seen_fast, seen_slow;
    for (Index z = 0; z < 5; ++z)
        for (Index y = 0; y < 3; ++y)
            for (Index x = 0; x < 4; ++x) {
                seen_fast.insert(fast.linear({x, y, z}));
                seen_slow.insert(slow.linear({x, y, z}));
            }
    EXPECT_EQ(seen_fast.size(), 60u);
    EXPECT_EQ(seen_slow.size(), 60u);
    EXPECT_EQ(*seen_fast.rbegin(), 59);
    EXPECT_EQ(*seen_slow.rbegin(), 59);
}

TEST(CellGrid, CoveringHasCubicCellsOverThePoints) {
    const std::vector<grit::core::Vec<2>> x = {{{-0.5, 2.0}}, {{1.5, 2.25}}, {{0.25, 3.0}}};
    const auto g = CellGrid<2>::covering(x.data(), 3, 0.5);
    EXPECT_TRUE(g.divides);
    EXPECT_FALSE(g.periodic[0] || g.periodic[1]);
    EXPECT_EQ(g.cell_size[0], 0.5);
    EXPECT_EQ(g.cell_size[1], 0.5);
    EXPECT_EQ(g.dims[0], 6);  // (1.5 - -0.5) / 0.5 + 1 = 5, + 1
    EXPECT_EQ(g.dims[1], 4);
    EXPECT_EQ(g.coords(x[0])[0], 0);
    EXPECT_EQ(g.coords(x[1])[0], 4);
    EXPECT_EQ(g.coords(x[2])[1], 2);
    // Outside points go to the edge cells.
    EXPECT_EQ(g.coords({{-10.0, 10.0}})[0], 0);
    EXPECT_EQ(g.coords({{-10.0, 10.0}})[1], 3);
}

TEST(CellGrid, DiluteGrainsGetLargerCellsNotABlowUp) {
    // 1000 grains of 0.5 mm strewn through a 0.3 x 0.15 x 0.15 m tank: cells of 0.5 mm would number 5.5e7,
    // over the budget of max(64 (n + 1000), 4e6); the cells double until the grid fits (2 mm: 8.6e5).
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    std::vector<grit::core::Vec<3>> x(1000);
    for (auto& p : x) p = {{0.3 * u(rng), 0.15 * u(rng), 0.15 * u(rng)}};
    x[0] = {{0.0, 0.0, 0.0}};
    x[1] = {{0.3, 0.15, 0.15}};
    const auto g = CellGrid<3, CellOrder::x_slowest>::covering(x.data(), 1000, 0.5e-3);
    EXPECT_EQ(g.cell_size[0], 2e-3);
    EXPECT_EQ(g.cell_size[2], 2e-3);
    EXPECT_LE(g.cell_count(), 4'000'000);
    EXPECT_EQ(g.dims[0], 152);  // 0.3 / 2e-3 + 1 = 151, + 1
    // The same on the open axes of a box with a periodic one.
    const auto b = CellGrid<3, CellOrder::x_slowest>::over_box({false, true, false}, {{0.0, 0.0, 0.0}},
                                                               {{0.3, 0.15, 0.15}}, x.data(), 1000, 0.5e-3);
    EXPECT_EQ(b.dims[1], 300);
    EXPECT_EQ(b.cell_size[0], 2e-3);  // 151 x 300 x 76 cells: the periodic axis keeps its 300
    EXPECT_LE(b.cell_count(), 4'000'000);
    // A point flung 100 m away (cells 8 times the reach would not do: 3.6e7 of them) or not finite is a
    // blow-up.
    x[2] = {{100.0, 0.0, 0.0}};
    EXPECT_THROW((CellGrid<3>::covering(x.data(), 1000, 0.5e-3)), grit::core::BlowUpError);
    x[2] = {{std::nan(""), 0.0, 0.0}};
    EXPECT_THROW((CellGrid<3>::covering(x.data(), 1000, 0.5e-3)), grit::core::BlowUpError);
}

TEST(CellGrid, PeriodicAxesHoldAWholeNumberOfCells) {
    const grit::core::Vec<3> lower{{-1.0, 0.0, 0.0}}, upper{{1.0, 0.95, 5.0}};
    const std::vector<grit::core::Vec<3>> x = {{{-1.0, 0.0, 1.0}}, {{0.999, 0.949, 2.0}}, {{0.0, 0.35, 1.5}}};
    const auto g = CellGrid<3, CellOrder::x_slowest>::over_box({true, true, false}, lower, upper, x.data(), 3, 0.3);
    EXPECT_FALSE(g.divides);
    EXPECT_TRUE(g.periodic[0] && g.periodic[1] && !g.periodic[2]);
    EXPECT_EQ(g.dims[0], 6);  // floor(2 / 0.3)
    EXPECT_EQ(g.dims[1], 3);  // floor(0.95 / 0.3)
    EXPECT_EQ(g.origin[0], -1.0);
    EXPECT_EQ(g.origin[1], 0.0);
    EXPECT_EQ(g.inverse_cell_size[0], 6 / 2.0);
    EXPECT_EQ(g.inverse_cell_size[1], 3 / 0.95);
    EXPECT_GE(g.cell_size[0], 0.3);
    EXPECT_GE(g.cell_size[1], 0.3);
    EXPECT_DOUBLE_EQ(g.cell_size[0] * g.dims[0], 2.0);
    EXPECT_DOUBLE_EQ(g.cell_size[1] * g.dims[1], 0.95);
    // The open axis covers the points with cells of the requested size.
    EXPECT_EQ(g.cell_size[2], 0.3);
    EXPECT_EQ(g.dims[2], 5);  // extent 1 / 0.3 + 1 = 4.33, + 1
    EXPECT_EQ(g.coords(x[0])[0], 0);
    EXPECT_EQ(g.coords(x[1])[0], 5);
    EXPECT_EQ(g.coords(x[1])[1], 2);
    EXPECT_EQ(g.coords(x[2])[2], 1);
    // Fewer than three cells on a periodic axis could not be scanned without visiting a cell twice: the
    // axis is one cell, its own neighbour.
    const auto short_axis =
        CellGrid<3, CellOrder::x_slowest>::over_box({true, true, false}, lower, upper, x.data(), 3, 0.34);
    EXPECT_EQ(short_axis.dims[0], 5);  // floor(2 / 0.34)
    EXPECT_EQ(short_axis.dims[1], 1);  // floor(0.95 / 0.34) = 2 cells: one
    EXPECT_DOUBLE_EQ(short_axis.cell_size[1], 0.95);
    int visits = 0;
    short_axis.for_each_cell_around(short_axis.coords(x[2]), [&](Index) { ++visits; });
    EXPECT_EQ(visits, 3 * 1 * 3);  // x: 3 cells, y: its own, z: 3 (open, inside the grid)
}

TEST(CellGrid, CoordsDivideOrMultiplyAsTheGridSays) {
    // 0.3 / 0.1 rounds to 2.9999999999999996 and 0.3 * (1 / 0.1) to 3: the two grids that this type
    // replaced differed there, and each user keeps its own.
    CellGrid<2> g;
    g.origin = grit::core::Vec<2>::zero();
    g.cell_size = grit::core::Vec<2>::filled(0.1);
    g.inverse_cell_size = grit::core::Vec<2>::filled(1.0 / 0.1);
    g.dims = {10, 10};
    g.divides = true;
    EXPECT_EQ(g.coords({{0.3, 0.0}})[0], 2);
    g.divides = false;
    EXPECT_EQ(g.coords({{0.3, 0.0}})[0], 3);
}

TEST(CellGrid, CellsAroundWrapOnPeriodicAxesAndStopAtOpenEdges) {
    CellGrid<2, CellOrder::x_slowest> g;
    g.dims = {4, 5};
    std::vector<Index> cells;
    g.for_each_cell_around({0, 0}, [&](Index c) { cells.push_back(c); });
    EXPECT_EQ(cells, (std::vector<Index>{0, 5, 1, 6}));  // x fastest in the visit, x slowest in the number
    g.periodic = {true, false};
    cells.clear();
    g.for_each_cell_around({0, 0}, [&](Index c) { cells.push_back(c); });
    EXPECT_EQ(cells, (std::vector<Index>{15, 0, 5, 16, 1, 6}));
    g.periodic = {true, true};
    cells.clear();
    g.for_each_cell_around({3, 4}, [&](Index c) { cells.push_back(c); });
    std::sort(cells.begin(), cells.end());
    EXPECT_EQ(cells, (std::vector<Index>{0, 3, 4, 10, 13, 14, 15, 18, 19}));
}

namespace {

template <int Dim, CellOrder Order>
void check_sort(const CellGrid<Dim, Order>& grid, const std::vector<grit::core::Vec<Dim>>& x) {
    const auto n = static_cast<Index>(x.size());
    std::vector<Index> order, cell_start;
    grit::neighbors::sort_by_cell(grid, x.data(), n, order, cell_start);
    ASSERT_EQ(order.size(), x.size());
    ASSERT_EQ(cell_start.size(), static_cast<std::size_t>(grid.cell_count()) + 1);
    EXPECT_EQ(cell_start.front(), 0);
    EXPECT_EQ(cell_start.back(), n);
    std::vector<bool> seen(x.size(), false);
    for (Index c = 0; c < grid.cell_count(); ++c)
        for (Index s = cell_start[c]; s < cell_start[c + 1]; ++s) {
            const Index i = order[static_cast<std::size_t>(s)];
            ASSERT_FALSE(seen[static_cast<std::size_t>(i)]);
            seen[static_cast<std::size_t>(i)] = true;
            ASSERT_EQ(grid.cell_of(x[static_cast<std::size_t>(i)]), c);
            if (s > cell_start[c]) {
                ASSERT_LT(order[static_cast<std::size_t>(s) - 1], i);  // stable
            }
        }
    EXPECT_TRUE(std::all_of(seen.begin(), seen.end(), [](bool b) { return b; }));
}

template <int Dim>
std::vector<grit::core::Vec<Dim>> random_points(Index n, double lo, double hi, unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(lo, hi);
    std::vector<grit::core::Vec<Dim>> x(static_cast<std::size_t>(n));
    for (auto& p : x)
        for (int k = 0; k < Dim; ++k) p[k] = u(rng);
    return x;
}

}  // namespace

TEST(CellGrid, SortByCellGroupsPointsStably) {
    const auto x2 = random_points<2>(3000, -1.0, 2.0, 4);
    check_sort(CellGrid<2>::covering(x2.data(), 3000, 0.2), x2);
    const auto x3 = random_points<3>(3000, 0.0, 1.0, 5);
    check_sort(CellGrid<3>::covering(x3.data(), 3000, 0.15), x3);
    check_sort(CellGrid<3, CellOrder::x_slowest>::over_box({true, false, true}, grit::core::Vec<3>::zero(),
                                                           grit::core::Vec<3>::filled(1.0), x3.data(), 3000, 0.15),
               x3);
    check_sort(CellGrid<3>::covering(x3.data(), 0, 0.15), std::vector<grit::core::Vec<3>>{});
}
