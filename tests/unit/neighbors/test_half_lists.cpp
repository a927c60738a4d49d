// Half lists cut from full lists: each same-phase pair once, every other-phase neighbour listed, cut again
// only when the lists change; sums over pairs once equal the gather sums and do not depend on threads.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <set>
#include <utility>
#include <vector>

#include "grit/neighbors/cell_grid.hpp"
#include "grit/neighbors/half_lists.hpp"
#include "grit/neighbors/neighbor_list.hpp"

using grit::Index;

namespace {

struct Lists {
    std::vector<grit::core::Vec<2>> x;
    std::vector<std::int32_t> phase;
    grit::neighbors::NeighborList<2> full;

    Lists(Index n, double radius, unsigned seed) {
        std::mt19937 rng(seed);
        std::uniform_real_distribution<double> u(0.0, 1.0);
        std::vector<grit::core::Vec<2>> raw(static_cast<std::size_t>(n));
        for (auto& p : raw)
            p = {u(rng), u(rng)};
        auto grid = grit::neighbors::CellGrid<2>::covering(raw.data(), n, radius);
        std::vector<Index> order, cell_start;
        grit::neighbors::sort_by_cell(grid, raw.data(), n, order, cell_start);
        for (Index i = 0; i < n; ++i) {
            x.push_back(raw[static_cast<std::size_t>(order[static_cast<std::size_t>(i)])]);
            phase.push_back(x.back()[1] < 0.1 ? 2 : 0);  // a strip of "walls" along the bottom
        }
        full.build(grid, cell_start, x.data(), n, radius);
    }
};

}  // namespace

TEST(HalfLists, EachSamePhasePairOnceAndEveryOtherNeighbour) {
    Lists l(3000, 0.05, 11);
    grit::neighbors::HalfLists half;
    half.update(l.full.offsets(), l.full.indices(), l.full.particle_count(), l.full.version(), l.phase.data(), 0);
    std::set<std::pair<Index, Index>> same, other;
    for (Index a = 0; a < 3000; ++a) {
        if (l.phase[static_cast<std::size_t>(a)] != 0) continue;
        for (Index k = l.full.begin(a); k < l.full.end(a); ++k) {
            const Index b = l.full.indices()[k];
            if (l.phase[static_cast<std::size_t>(b)] == 0)
                same.insert({std::min(a, b), std::max(a, b)});
            else
                other.insert({a, b});
        }
    }
    std::set<std::pair<Index, Index>> same_found, other_found;
    std::size_t same_entries = 0;
    for (Index a = 0; a < 3000; ++a) {
        for (Index k = half.upper_begin(a); k < half.upper_end(a); ++k) {
            const Index b = half.upper()[k];
            EXPECT_GT(b, a);
            same_found.insert({a, b});
            ++same_entries;
        }
        for (Index k = half.other_begin(a); k < half.other_end(a); ++k)
            other_found.insert({a, half.other()[k]});
    }
    EXPECT_EQ(same_found, same);
    EXPECT_EQ(same_entries, same.size());  // no pair twice
    EXPECT_EQ(other_found, other);
    // Blocks cover the particles in order; spills start where their block ends.
    EXPECT_EQ(half.block_begin(0), 0);
    EXPECT_EQ(half.block_begin(half.block_count()), 3000);
    for (Index j = 0; j < half.block_count(); ++j)
        EXPECT_GE(half.spill_end(j), half.block_begin(j + 1));
}

TEST(HalfLists, SumsOverPairsOnceEqualTheGatherSumsAtOneAndTwoThreads) {
    Lists l(6000, 0.04, 12);
    // An antisymmetric pair term w(a, b) = -w(b, a) and a symmetric one, summed per particle.
    struct Sum {
        double anti = 0.0, sym = 0.0;
        Sum& operator+=(const Sum& o) {
            anti += o.anti;
            sym += o.sym;
            return *this;
        }
    };
    auto anti = [&](Index a, Index b) {
        return l.x[static_cast<std::size_t>(a)][0] - l.x[static_cast<std::size_t>(b)][0];
    };
    auto sym = [&](Index a, Index b) {
        return l.x[static_cast<std::size_t>(a)][1] * l.x[static_cast<std::size_t>(b)][1];
    };
    std::vector<std::vector<Sum>> totals(2, std::vector<Sum>(6000));
    for (int threads : {1, 2}) {
        grit::parallel::set_threads(threads);
        grit::neighbors::HalfLists half;
        half.update(l.full.offsets(), l.full.indices(), l.full.particle_count(), l.full.version(), l.phase.data(), 0);
        EXPECT_GT(half.block_count(), 2);
        std::vector<Sum> own, spill;
        auto& out = totals[static_cast<std::size_t>(threads - 1)];
        grit::neighbors::sum_pairs_once(
            half, own, spill,
            [&](Index a, Sum& sum_a, auto&& share) {
                for (Index k = half.upper_begin(a); k < half.upper_end(a); ++k) {
                    const Index b = half.upper()[k];
                    sum_a += Sum{anti(a, b), sym(a, b)};
                    share(b) += Sum{-anti(a, b), sym(a, b)};
                }
            },
            [&](Index i, const Sum& total) { out[static_cast<std::size_t>(i)] = total; });
    }
    grit::parallel::set_threads(2);
    for (Index a = 0; a < 6000; ++a) {
        const auto i = static_cast<std::size_t>(a);
        EXPECT_EQ(totals[0][i].anti, totals[1][i].anti);
        EXPECT_EQ(totals[0][i].sym, totals[1][i].sym);
        if (l.phase[i] != 0) continue;
        double expected_anti = 0.0, expected_sym = 0.0;
        for (Index k = l.full.begin(a); k < l.full.end(a); ++k) {
            const Index b = l.full.indices()[k];
            if (l.phase[static_cast<std::size_t>(b)] != 0) continue;
            expected_anti += anti(a, b);
            expected_sym += sym(a, b);
        }
        EXPECT_NEAR(totals[0][i].anti, expected_anti, 1e-12);
        EXPECT_NEAR(totals[0][i].sym, expected_sym, 1e-12);
    }
}

TEST(HalfLists, CutAgainOnlyWhenTheListsOrPhasesChange) {
    Lists l(500, 0.1, 13);
    grit::neighbors::HalfLists half;
    half.update(l.full.offsets(), l.full.indices(), l.full.particle_count(), l.full.version(), l.phase.data(), 0);
    const Index pairs = half.upper_end(499);
    // Same lists and phases: nothing is cut again.
    half.update(l.full.offsets(), l.full.indices(), l.full.particle_count(), l.full.version(), l.phase.data(), 0);
    EXPECT_EQ(half.cuts(), 1);
    // A fluid particle turned wall: its pairs leave the half lists.
    const auto fluid = std::find(l.phase.begin(), l.phase.end(), 0);
    ASSERT_NE(fluid, l.phase.end());
    *fluid = 2;
    half.update(l.full.offsets(), l.full.indices(), l.full.particle_count(), l.full.version(), l.phase.data(), 0);
    EXPECT_EQ(half.cuts(), 2);
    EXPECT_LT(half.upper_end(499), pairs);
    // Rebuilt lists have a new version.
    const auto version = l.full.version();
    auto grid = grit::neighbors::CellGrid<2>::covering(l.x.data(), 500, 0.1);
    std::vector<Index> order, cell_start;
    grit::neighbors::sort_by_cell(grid, l.x.data(), 500, order, cell_start);
    l.full.build(grid, cell_start, l.x.data(), 500, 0.1);
    EXPECT_NE(l.full.version(), version);
    half.update(l.full.offsets(), l.full.indices(), l.full.particle_count(), l.full.version(), l.phase.data(), 0);
    EXPECT_EQ(half.cuts(), 3);
}
