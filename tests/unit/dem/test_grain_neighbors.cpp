// The grain neighbour lists (each pair once, in its lower index's row) against a brute-force search, with
// and without periodic axes, and the slabs the pair pass's blocks are made of.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <functional>
#include <random>
#include <vector>

#include "grit/dem/grain_neighbors.hpp"
#include "grit/dem/slab_blocks.hpp"

using namespace grit::dem;
using grit::Index;

namespace {

template <int Dim>
void check_against_brute_force(bool periodic, double length = 0.02, Index n = 600) {
    GrainDomain<Dim> domain;
    for (int k = 0; k < Dim; ++k) {
        domain.periodic[k] = periodic && k < 2;
        domain.lower[k] = 0.0;
        domain.upper[k] = length;
    }
    domain.finalise();
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    std::vector<grit::core::Vec<Dim>> x(n);
    std::vector<double> r(n);
    for (Index i = 0; i < n; ++i) {
        for (int k = 0; k < Dim; ++k) x[i][k] = length * u(rng);
        r[i] = 0.0005 + 0.0005 * u(rng);
    }
    const double skin = 0.0003;
    const auto grid = GrainNeighborList<Dim>::make_grid(domain, x.data(), n, 0.002 + skin);
    std::vector<Index> order, cell_start;
    grit::neighbors::sort_by_cell(grid, x.data(), n, order, cell_start);
    std::vector<grit::core::Vec<Dim>> xs(n);
    std::vector<double> rs(n);
    for (Index i = 0; i < n; ++i) xs[i] = x[order[i]], rs[i] = r[order[i]];
    GrainNeighborList<Dim> list;
    list.build(grid, cell_start, domain, xs.data(), rs.data(), n, skin);
    // The slab of each grain: its partners lie in the same slab or the next, or across a periodic x
    // boundary from the first slab in the last (SlabBlocks relies on it).
    const std::vector<Index>& slabs = list.slab_starts();
    ASSERT_EQ(slabs.size(), static_cast<std::size_t>(grid.dims[0]) + 1);
    ASSERT_EQ(slabs.front(), 0);
    ASSERT_EQ(slabs.back(), n);
    auto slab_of = [&](Index i) {
        return static_cast<Index>(std::upper_bound(slabs.begin(), slabs.end(), i) - slabs.begin()) - 1;
    };
    const Index last = grid.dims[0] - 1;
    std::size_t entries = 0;
    for (Index i = 0; i < n; ++i) {
        std::vector<Index> expected;
        for (Index j = i + 1; j < n; ++j) {
            const double reach = rs[i] + rs[j] + skin;
            if (grit::core::norm2(domain.nearest_image(xs[j] - xs[i])) < reach * reach) expected.push_back(j);
        }
        const std::vector<Index> got(list.indices() + list.begin(i), list.indices() + list.end(i));
        ASSERT_EQ(got, expected) << "grain " << i;  // ascending index, as the brute force's
        entries += got.size();
        for (const Index j : got) {
            const Index si = slab_of(i), sj = slab_of(j);
            EXPECT_TRUE(sj == si || sj == si + 1 || (periodic && si == 0 && sj == last))
                << "grains " << i << " and " << j << " in slabs " << si << " and " << sj;
        }
    }
    EXPECT_GT(entries, static_cast<std::size_t>(n) / 2);
    EXPECT_FALSE(list.stale(xs.data(), n));
    xs[5][0] += 0.6 * skin;
    EXPECT_TRUE(list.stale(xs.data(), n));
}

}  // namespace

TEST(GrainNeighbors, MatchBruteForce2D) { check_against_brute_force<2>(false); }
TEST(GrainNeighbors, MatchBruteForce3D) { check_against_brute_force<3>(false); }
TEST(GrainNeighbors, MatchBruteForcePeriodic2D) { check_against_brute_force<2>(true); }
TEST(GrainNeighbors, MatchBruteForcePeriodic3D) { check_against_brute_force<3>(true); }
// Periods between two and three list cells (cells of 2.3 mm): one cell along x and y.
TEST(GrainNeighbors, MatchBruteForceShortPeriods) {
    check_against_brute_force<2>(true, 0.005, 60);
    check_against_brute_force<3>(true, 0.005, 120);
}

TEST(GrainNeighbors, WrapAndNearestImage) {
    GrainDomain<2> d;
    d.periodic = {true, false};
    d.lower = {{-1.0, 0.0}};
    d.upper = {{1.0, 5.0}};
    d.finalise();
    const auto w = d.wrap({{1.25, 7.0}});
    EXPECT_DOUBLE_EQ(w[0], -0.75);
    EXPECT_DOUBLE_EQ(w[1], 7.0);
    const auto m = d.nearest_image({{1.5, 3.0}});
    EXPECT_DOUBLE_EQ(m[0], -0.5);
    EXPECT_DOUBLE_EQ(m[1], 3.0);
}

// The pair pass completes each grain inside its blocks' loop (SlabBlocks::completed_after): every block
// exactly once, and only after every block that adds to its grains (blocks j - 1 and j, and block 0 for
// the last block across a periodic x boundary) has run, in for_each_block's serial order (the colours one
// after the other; a colour's blocks run in parallel, and none of them adds to another's completed blocks).
TEST(SlabBlocks, EveryBlockCompletedOnceAfterAllThatAddToIt) {
    for (const Index slabs : {Index{1}, Index{2}, Index{3}, Index{7}, Index{9}, Index{13}}) {
        std::vector<Index> starts;
        for (Index s = 0; s <= slabs; ++s) starts.push_back(10 * s);  // ten grains a slab
        SlabBlocks blocks;
        blocks.assign(starts);
        const Index count = blocks.count();
        std::vector<int> ran(static_cast<std::size_t>(count), 0), completed(static_cast<std::size_t>(count), 0);
        auto writers_done = [&](Index k) {
            bool done = ran[static_cast<std::size_t>(k)] != 0;
            if (k > 0) done = done && ran[static_cast<std::size_t>(k - 1)] != 0;
            if (k == count - 1) done = done && ran[0] != 0;
            return done;
        };
        Index grains = 0;
        blocks.for_each_block(0, [&](Index j) {  // 0 grains: the serial order
            ran[static_cast<std::size_t>(j)] = 1;
            const auto [first, last] = blocks.completed_after(j);
            for (Index k = first; k < last; ++k) {
                EXPECT_TRUE(writers_done(k)) << slabs << " slabs: block " << k << " completed after block " << j;
                ++completed[static_cast<std::size_t>(k)];
                grains += blocks.end(k) - blocks.begin(k);
            }
        });
        for (Index k = 0; k < count; ++k)
            EXPECT_EQ(completed[static_cast<std::size_t>(k)], 1) << slabs << " slabs: block " << k;
        EXPECT_EQ(grains, 10 * slabs);
    }
}

// Without barriers between the colours (SlabBlocks::for_each_block in parallel) a block waits only for its
// earlier_neighbours(). Checked for every block count: the serial order is every block once, colour by
// colour; two blocks that add to the same grains never run at once (the later waits for the earlier); and
// a block completed at the end of block j is read and written by no block that may still be running then
// (each of its readers and writers is j or runs before j: a chain of waits).
TEST(SlabBlocks, BlocksThatShareGrainsWaitForOneAnother) {
    for (const Index slabs : {Index{3}, Index{4}, Index{6}, Index{9}, Index{13}, Index{41}}) {
        std::vector<Index> starts;
        for (Index s = 0; s <= slabs; ++s) starts.push_back(10 * s);
        SlabBlocks blocks;
        blocks.assign(starts);
        const Index count = blocks.count();
        std::vector<Index> place(static_cast<std::size_t>(count), -1);
        for (Index q = 0; q < count; ++q) {
            const Index j = blocks.in_serial_order(q);
            ASSERT_TRUE(j >= 0 && j < count) << slabs << " slabs, place " << q;
            EXPECT_EQ(place[static_cast<std::size_t>(j)], -1) << slabs << " slabs: block " << j << " twice";
            place[static_cast<std::size_t>(j)] = q;
            if (q > 0) {
                EXPECT_LE(blocks.in_serial_order(q - 1) % SlabBlocks::colours, j % SlabBlocks::colours);
            }
        }
        // The grains' blocks that block j adds to (its own, the next, and the last for block 0), and the
        // blocks whose grains it reads (the same: a pair reads both grains).
        auto touches = [&](Index j) {
            std::vector<Index> t{j};
            if (j + 1 < count) t.push_back(j + 1);
            if (j == 0 && count > 1) t.push_back(count - 1);
            return t;
        };
        // m runs before j (or is j): j waits for m, or for a block that runs after m.
        std::function<bool(Index, Index)> before = [&](Index m, Index j) {
            if (m == j) return true;
            for (const Index k : blocks.earlier_neighbours(j))
                if (k >= 0 && before(m, k)) return true;
            return false;
        };
        for (Index j = 0; j < count; ++j)
            for (Index m = 0; m < count; ++m) {
                if (m == j || place[static_cast<std::size_t>(m)] > place[static_cast<std::size_t>(j)]) continue;
                const auto tj = touches(j), tm = touches(m);
                const bool shared = std::any_of(tj.begin(), tj.end(), [&](Index b) {
                    return std::find(tm.begin(), tm.end(), b) != tm.end();
                });
                if (shared) {
                    EXPECT_TRUE(before(m, j)) << slabs << " slabs: block " << j << " may run beside " << m;
                }
            }
        for (Index j = 0; j < count; ++j) {
            const auto [first, last] = blocks.completed_after(j);
            for (Index k = first; k < last; ++k)
                for (Index m = 0; m < count; ++m) {
                    const auto tm = touches(m);
                    if (std::find(tm.begin(), tm.end(), k) != tm.end()) {
                        EXPECT_TRUE(before(m, j)) << slabs << " slabs: block " << k << ", completed after block " << j
                                                  << ", is still touched by block " << m;
                    }
                }
        }
    }
}
