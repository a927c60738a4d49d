// Each pair once, summed in an order the lists fix, not the threads.
//
// A gather loop (each particle sums over its full list) evaluates every pair twice. A pair loop that
// evaluates a pair once must add to both particles, which races across threads unless the second
// particle's share goes elsewhere. Here the particles of one phase are cut into blocks of consecutive
// indices, sized by their pair counts (never by the thread count); a block's pairs are evaluated by one
// thread in index order, shares for particles of the block go straight to them, shares for later
// particles to the block's own spill rows, and a last pass adds each particle's spill rows in block
// order. The sums then do not depend on the thread count or the schedule: 1 and N threads give
// bit-identical results, and no atomics are needed. The particles are sorted by cell before every list
// build, so a block's neighbours of higher index lie within a cell row or two: spills stay small.
#pragma once

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <type_traits>
#include <vector>

#include "grit/core/types.hpp"
#include "grit/parallel/parallel.hpp"

namespace grit::neighbors {

/// For each particle of one phase: its neighbours of the same phase and higher index (each same-phase
/// pair once) and its neighbours of other phases (one-sided), cut from full neighbour lists, with the
/// blocks that sum the pairs deterministically (sum_pairs_once).
class HalfLists {
  public:
    /// Brings the lists up to date with the full lists (offsets: n + 1 row starts; indices) of list
    /// version `version` (NeighborList::version()): unchanged lists, phases and phase are not cut again.
    void update(const Index* offsets, const Index* indices, Index n, std::uint64_t version, const std::int32_t* phase,
                std::int32_t own_phase);
    /// The same for lists whose particles are all of one phase (the grains): no neighbours of other phases.
    void update(const Index* offsets, const Index* indices, Index n, std::uint64_t version);

    /// Same-phase neighbours of higher index of particle a: upper()[upper_begin(a) .. upper_end(a)).
    Index upper_begin(Index a) const noexcept { return upper_offsets_[static_cast<std::size_t>(a)]; }
    Index upper_end(Index a) const noexcept { return upper_offsets_[static_cast<std::size_t>(a) + 1]; }
    const Index* upper() const noexcept { return upper_.data(); }
    std::size_t upper_size() const noexcept { return upper_.size(); }
    /// Neighbours of other phases of particle a: other()[other_begin(a) .. other_end(a)).
    Index other_begin(Index a) const noexcept { return other_offsets_[static_cast<std::size_t>(a)]; }
    Index other_end(Index a) const noexcept { return other_offsets_[static_cast<std::size_t>(a) + 1]; }
    const Index* other() const noexcept { return other_.data(); }
    std::size_t other_size() const noexcept { return other_.size(); }
    /// The longest same-phase row (for per-row scratch).
    Index longest_upper() const noexcept { return longest_upper_; }

    Index particle_count() const noexcept { return n_; }
    /// How often the lists were cut (once per change of the full lists or the phases).
    long cuts() const noexcept { return cuts_; }
    /// Whether particle i is of the lists' phase.
    bool member(Index i) const noexcept { return phase_[static_cast<std::size_t>(i)] == own_phase_; }
    std::int32_t phase() const noexcept { return own_phase_; }

    /// Blocks: particles [block_begin(j), block_begin(j + 1)); shares for particles from block_begin(j + 1)
    /// up to spill_end(j) go to block j's spill rows, from spill_offset(j) on.
    Index block_count() const noexcept { return static_cast<Index>(block_begin_.size()) - 1; }
    Index block_begin(Index j) const noexcept { return block_begin_[static_cast<std::size_t>(j)]; }
    Index spill_end(Index j) const noexcept { return spill_end_[static_cast<std::size_t>(j)]; }
    std::size_t spill_offset(Index j) const noexcept { return spill_offset_[static_cast<std::size_t>(j)]; }
    std::size_t spill_rows() const noexcept { return spill_offset_.back(); }
    /// The first block whose spill reaches into block j (j itself when none does).
    Index first_spiller(Index j) const noexcept { return first_spiller_[static_cast<std::size_t>(j)]; }

    /// How the particles are cut into blocks: a block's pairs (both kinds) are a `blocks_target`-th of
    /// all, within [min_block_pairs, max_block_pairs]. Set by the lists alone, never by the thread count.
    struct Blocking {
        std::int64_t blocks_target, min_block_pairs, max_block_pairs;
    };
    /// The SPH sums' blocks: a 64th of all pairs, 1024 to 16384. Enough blocks for the threads to share a
    /// small set (an AWJ's water is a few thousand pairs), few enough that a block's spill (a cell row or
    /// two ahead in 2D) stays small beside it.
    static constexpr Blocking sph_blocking{64, 1024, 16384};

    HalfLists() = default;
    explicit HalfLists(Blocking blocking) : blocking_(blocking) {}

  private:
    Blocking blocking_ = sph_blocking;
    long cuts_ = 0;
    std::uint64_t version_ = 0;
    Index n_ = 0;
    std::int32_t own_phase_ = -1;
    std::vector<std::int32_t> phase_;  // the phases the lists were cut with
    std::vector<std::int32_t> one_phase_;  // phase 0 for every particle, for the one-phase update
    std::vector<Index> upper_offsets_{0}, upper_, other_offsets_{0}, other_;
    Index longest_upper_ = 0;
    std::vector<Index> block_begin_{0}, spill_end_, first_spiller_;
    std::vector<std::size_t> spill_offset_{0};
};

/// Sums over every pair of `lists` once, into `Sum` per particle (zero-initialised by `Sum{}`, added with
/// +=). `visit(a, sum_a, share)` is called for each particle a of the lists' phase, in index order within
/// a block (blocks run in parallel): it adds a's own terms to sum_a, and the share of each same-phase
/// neighbour b to `share(b)` (b > a: later in the block, or a spill row). `finish(i, total)` is then
/// called once for each particle of the phase, in parallel, with its total. `own` and `spill` are
/// scratch the caller keeps between calls.
template <class Sum, class Visit, class Finish>
void sum_pairs_once(const HalfLists& lists, std::vector<Sum>& own, std::vector<Sum>& spill, Visit&& visit,
                    Finish&& finish) {
    const Index n = lists.particle_count();
    own.resize(static_cast<std::size_t>(n));
    spill.resize(lists.spill_rows());
    const Index blocks = lists.block_count();
    // Clearing the rows is a store-bound loop of several stores per row (a grain's sum is 56 bytes); a
    // sum whose zero is all zero bits is cleared with memset instead.
    static const bool zero_is_zero_bytes = [] {
        if constexpr (!std::is_trivially_copyable_v<Sum>) {
            return false;
        } else {
            const Sum zero{};
            unsigned char bytes[sizeof(Sum)];
            std::memcpy(bytes, &zero, sizeof(Sum));
            return std::all_of(bytes, bytes + sizeof(Sum), [](unsigned char c) { return c == 0; });
        }
    }();
    auto clear = [&](Sum* first, Sum* last) {
        if constexpr (std::is_trivially_copyable_v<Sum>) {
            if (zero_is_zero_bytes) {
                if (last > first) std::memset(static_cast<void*>(first), 0, static_cast<std::size_t>(last - first) * sizeof(Sum));
                return;
            }
        }
        std::fill(first, last, Sum{});
    };
    // Blocks (about 64, more on large sets) go one at a time to whichever thread is free: the order of every sum is
    // fixed inside the block, so the schedule changes no result.
    auto run_block = [&](Index j) {
        const Index begin = lists.block_begin(j), end = lists.block_begin(j + 1);
        clear(own.data() + begin, own.data() + end);
        Sum* rows = spill.data() + lists.spill_offset(j);
        clear(rows, spill.data() + lists.spill_offset(j + 1));
        Sum* own_rows = own.data();
        auto share = [&](Index b) -> Sum& { return b < end ? own_rows[b] : rows[b - end]; };
        for (Index a = begin; a < end; ++a)
            if (lists.member(a)) visit(a, own_rows[a], share);
    };
    auto finish_block = [&](Index j) {
        const Index begin = lists.block_begin(j), end = lists.block_begin(j + 1);
        const Index first = lists.first_spiller(j);
        for (Index i = begin; i < end; ++i) {
            if (!lists.member(i)) continue;
            Sum total = own[static_cast<std::size_t>(i)];
            for (Index s = first; s < j; ++s)
                if (i < lists.spill_end(s))
                    total += spill[lists.spill_offset(s) + static_cast<std::size_t>(i - lists.block_begin(s + 1))];
            finish(i, total);
        }
    };
    if (blocks == 1) {  // no parallel region for small sets
        run_block(0);
        finish_block(0);
        return;
    }
#pragma omp parallel
    {
#pragma omp for schedule(dynamic, 1)
        for (Index j = 0; j < blocks; ++j)
            run_block(j);
#pragma omp for schedule(dynamic, 1)
        for (Index j = 0; j < blocks; ++j)
            finish_block(j);
    }
}

}  // namespace grit::neighbors
