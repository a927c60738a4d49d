// Blocks of whole cell slabs for the grain pair pass, coloured so that the blocks of one colour add to
// disjoint grains: the pair pass then adds each pair's force straight into both grains' sums, in
// parallel, without atomics and without per-block scratch rows, in an order the lists fix.
//
// Grains are numbered by cell with x slowest (GrainNeighborList), so a slab of cells along x is a run of
// consecutive grains, and a grain's partners of higher index lie in its own slab or the next one, or,
// across a periodic x boundary, the first slab's in the last. Block j is slab j (the last block takes the
// slabs left over); it adds to its own grains and the next block's, and block 0 to the last block's
// too. With a multiple of three blocks, colour j % 3 leaves a gap of two blocks between any two blocks of
// one colour, so no grain receives from two blocks at once. The blocks depend on the lists alone, never
// on the thread count: 1 and N threads give bit-identical sums.
#pragma once

#include <algorithm>
#include <utility>
#include <vector>

#include "grit/core/types.hpp"
#include "grit/parallel/parallel.hpp"

namespace grit::dem {

class SlabBlocks {
public:
    static constexpr int colours = 3;

    /// Blocks over slabs whose first grains are slab_starts (one more for the end): one block per slab,
    /// the last ones merged to a multiple of three; a single block when there are fewer than three slabs.
    void assign(const std::vector<Index>& slab_starts) {
        const auto slabs = static_cast<Index>(slab_starts.size()) - 1;
        begin_.clear();
        if (slabs < colours) {
            begin_ = {slab_starts.front(), slab_starts.back()};
            return;
        }
        const Index blocks = slabs - slabs % colours;
        begin_.assign(slab_starts.begin(), slab_starts.begin() + blocks);
        begin_.push_back(slab_starts.back());
    }

    Index count() const noexcept { return static_cast<Index>(begin_.size()) - 1; }
    Index begin(Index j) const noexcept { return begin_[static_cast<std::size_t>(j)]; }
    Index end(Index j) const noexcept { return begin_[static_cast<std::size_t>(j) + 1]; }

    /// The blocks whose grains no block after j (in for_each_block's order) adds to, and that no block before
    /// j has completed: [first, last). Block 0's grains receive from block 0 alone (it evaluates the pairs
    /// across a periodic x boundary); block j > 0's from blocks j - 1 and j (and the last block's from block
    /// 0), so block j completes itself when its colour is the later of the two (j % 3 = 1, 2) and block
    /// j + 1 when j % 3 = 2 (block j + 1 of colour 0 ran before it).
    std::pair<Index, Index> completed_after(Index j) const noexcept {
        const Index blocks = count();
        if (blocks < colours) return {0, blocks};  // one block
        if (j == 0) return {0, 1};
        if (j % colours == 1) return {j, j + 1};
        if (j % colours == 2) return {j, std::min(j + 2, blocks)};
        return {j, j};
    }

    /// Calls run(j) for every block: the colours one after the other, the blocks of a colour in parallel
    /// (in block order on one thread, or when the grains are few).
    template <class Run>
    void for_each_block(Index grains, Run&& run) const {
        const Index blocks = count();
        if (blocks < colours || grains < parallel::serial_below) {
            for (int c = 0; c < std::min<Index>(colours, blocks); ++c)
                for (Index j = c; j < blocks; j += colours) run(j);
            return;
        }
#pragma omp parallel
        for (int c = 0; c < colours; ++c) {
#pragma omp for schedule(dynamic, 1)
            for (Index j = c; j < blocks; j += colours) run(j);
        }
    }

private:
    std::vector<Index> begin_{0, 0};
};

}  // namespace grit::dem
