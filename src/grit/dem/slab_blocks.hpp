// Blocks of whole cell slabs for the grain pair pass, coloured so that the blocks of one colour add to
// disjoint grains: the pair pass then adds each pair's force straight into both grains' sums, in
// parallel, without atomic adds (atomic flags only order the blocks) and without per-block scratch rows,
// in an order the lists fix.
//
// Grains are numbered by cell with x slowest (GrainNeighborList), so a slab of cells along x is a run of
// consecutive grains, and a grain's partners of higher index lie in its own slab or the next one, or,
// across a periodic x boundary, the first slab's in the last. Block j is slab j (the last block takes the
// slabs left over); it adds to its own grains and the next block's, and block 0 to the last block's
// too. With a multiple of three blocks, colour j % 3 leaves a gap of two blocks between any two blocks of
// one colour, so no grain receives from two blocks at once. The blocks depend on the lists alone, never
// on the thread count: 1 and N threads give bit-identical sums.
//
// In parallel there is no barrier between the colours: the threads take the blocks in the serial order
// (the colours one after the other), and each block waits only for the blocks of earlier colours that
// add to the same grains as it does (its neighbours, and block 0 for the last two). Every grain then
// receives its blocks' shares in the serial order, so the sums are those of one thread, bit for bit; and
// a thread that finishes its share of a colour goes on with the next instead of waiting for the other.
#pragma once

#include <algorithm>
#include <array>
#include <atomic>
#include <cstdint>
#include <memory>
#include <thread>
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

    /// The blocks whose grains no block after j (in for_each_block's serial order; in parallel, no block that
    /// may still run when j ends) adds to or reads, and that no block before j has completed: [first, last).
    /// Block 0's grains receive from block 0 alone (it evaluates the pairs across a periodic x boundary);
    /// block j > 0's from blocks j - 1 and j (and the last block's from block 0), so block j completes itself
    /// when its colour is the later of the two (j % 3 = 1, 2) and block j + 1 when j % 3 = 2 (block j + 1 of
    /// colour 0 ran before it).
    std::pair<Index, Index> completed_after(Index j) const noexcept {
        const Index blocks = count();
        if (blocks < colours) return {0, blocks};  // one block
        if (j == 0) return {0, 1};
        if (j % colours == 1) return {j, j + 1};
        if (j % colours == 2) return {j, std::min(j + 2, blocks)};
        return {j, j};
    }

    /// Calls run(j) for every block: the colours one after the other, the blocks of a colour in parallel
    /// (in block order on one thread, or when the grains are few). In parallel a block starts as soon as
    /// the blocks of earlier colours that add to its grains' or its partners' sums are done (file comment).
    template <class Run>
    void for_each_block(Index grains, Run&& run) const {
        const Index blocks = count();
        if (blocks < colours || grains < parallel::serial_below) {
            for (Index q = 0; q < blocks; ++q) run(in_serial_order(q));
            return;
        }
        std::atomic<Index> next{0};
        const auto done = std::make_unique<std::atomic<std::uint8_t>[]>(static_cast<std::size_t>(blocks));
        for (Index j = 0; j < blocks; ++j) done[static_cast<std::size_t>(j)].store(0, std::memory_order_relaxed);
        // A wait is short: the block waited for was taken earlier and is running (a block is about a hundred
        // microseconds at 50k grains). After a thousand spins (some tens of microseconds) the partner has
        // likely lost its core, and the waiter gives its own up.
        auto wait_for = [&](Index k) {
            const std::atomic<std::uint8_t>& flag = done[static_cast<std::size_t>(k)];
            for (int spin = 0; flag.load(std::memory_order_acquire) == 0; ++spin) {
                if (spin < 1024) spin_pause();
                else std::this_thread::yield();
            }
        };
#pragma omp parallel
        for (Index q = next.fetch_add(1, std::memory_order_relaxed); q < blocks;
             q = next.fetch_add(1, std::memory_order_relaxed)) {
            const Index j = in_serial_order(q);
            for (const Index k : earlier_neighbours(j))
                if (k >= 0) wait_for(k);
            run(j);
            done[static_cast<std::size_t>(j)].store(1, std::memory_order_release);
        }
    }

    /// The block at place q of the serial order: colour 0's blocks in block order, then colour 1's, then 2's.
    Index in_serial_order(Index q) const noexcept {
        const Index blocks = count();
        Index colour = 0;
        for (; colour + 1 < colours; ++colour) {
            const Index of_colour = (blocks - colour + colours - 1) / colours;  // blocks j = colour mod 3
            if (q < of_colour) break;
            q -= of_colour;
        }
        return colour + colours * q;
    }

    /// The blocks of earlier colours than block j's that add to the grains block j adds to (j - 1 and j + 1,
    /// and across a periodic x boundary block 0 for the last two blocks), -1 where there is none: block j
    /// must not start before they are done. Blocks of later colours wait for j in turn.
    std::array<Index, 3> earlier_neighbours(Index j) const noexcept {
        const Index blocks = count();
        std::array<Index, 3> out{-1, -1, -1};
        const auto earlier = [&](Index k) { return k >= 0 && k < blocks && k % colours < j % colours; };
        if (earlier(j - 1)) out[0] = j - 1;
        if (earlier(j + 1)) out[1] = j + 1;
        if (j >= blocks - 2 && j > 1 && earlier(0)) out[2] = 0;
        return out;
    }

private:
    static void spin_pause() noexcept {
#if defined(__x86_64__) || defined(__i386__)
        __builtin_ia32_pause();
#endif
    }

    std::vector<Index> begin_{0, 0};
};

}  // namespace grit::dem
