#include "grit/neighbors/half_lists.hpp"

namespace grit::neighbors {

void HalfLists::update(const Index* offsets, const Index* indices, Index n, std::uint64_t version,
                       const std::int32_t* phase, std::int32_t own_phase) {
    if (cuts_ > 0 && version == version_ && n == n_ && own_phase == own_phase_ &&
        std::equal(phase, phase + n, phase_.begin()))
        return;
    ++cuts_;
    version_ = version;
    n_ = n;
    own_phase_ = own_phase;
    phase_.assign(phase, phase + n);

    const auto rows = static_cast<std::size_t>(n) + 1;
    upper_offsets_.assign(rows, 0);
    other_offsets_.assign(rows, 0);
    parallel::for_each(n, [&](Index a) {
        if (phase[a] != own_phase) return;
        Index up = 0, other = 0;
        for (Index k = offsets[a]; k < offsets[a + 1]; ++k) {
            const Index b = indices[k];
            if (phase[b] != own_phase)
                ++other;
            else if (b > a)
                ++up;
        }
        upper_offsets_[static_cast<std::size_t>(a) + 1] = up;
        other_offsets_[static_cast<std::size_t>(a) + 1] = other;
    });
    longest_upper_ = 0;
    for (std::size_t a = 1; a < rows; ++a) {
        longest_upper_ = std::max(longest_upper_, upper_offsets_[a]);
        upper_offsets_[a] += upper_offsets_[a - 1];
        other_offsets_[a] += other_offsets_[a - 1];
    }
    upper_.resize(static_cast<std::size_t>(upper_offsets_.back()));
    other_.resize(static_cast<std::size_t>(other_offsets_.back()));
    parallel::for_each(n, [&](Index a) {
        if (phase[a] != own_phase) return;
        Index up = upper_offsets_[static_cast<std::size_t>(a)], other = other_offsets_[static_cast<std::size_t>(a)];
        for (Index k = offsets[a]; k < offsets[a + 1]; ++k) {
            const Index b = indices[k];
            if (phase[b] != own_phase)
                other_[static_cast<std::size_t>(other++)] = b;
            else if (b > a)
                upper_[static_cast<std::size_t>(up++)] = b;
        }
    });

    // Blocks of about block_pairs pairs (both kinds: both cost a pair evaluation), each spilling to the
    // particles of higher index its same-phase pairs reach.
    const std::int64_t block_pairs = std::clamp<std::int64_t>(
        (static_cast<std::int64_t>(upper_.size()) + static_cast<std::int64_t>(other_.size())) /
            blocking_.blocks_target,
        blocking_.min_block_pairs, blocking_.max_block_pairs);
    block_begin_.assign(1, 0);
    spill_end_.clear();
    std::int64_t work = 0;
    Index reach = 0;
    for (Index a = 0; a < n; ++a) {
        const auto s = static_cast<std::size_t>(a);
        work += (upper_offsets_[s + 1] - upper_offsets_[s]) + (other_offsets_[s + 1] - other_offsets_[s]);
        for (Index k = upper_offsets_[s]; k < upper_offsets_[s + 1]; ++k)
            reach = std::max(reach, upper_[static_cast<std::size_t>(k)] + 1);
        if (work >= block_pairs || a + 1 == n) {
            block_begin_.push_back(a + 1);
            spill_end_.push_back(std::max(reach, a + 1));
            work = 0;
            reach = 0;
        }
    }
    if (n == 0) {  // one empty block
        block_begin_.push_back(0);
        spill_end_.push_back(0);
    }
    const Index blocks = block_count();
    spill_offset_.assign(1, 0);
    first_spiller_.assign(static_cast<std::size_t>(blocks), 0);
    for (Index j = 0; j < blocks; ++j)
        spill_offset_.push_back(spill_offset_.back() + static_cast<std::size_t>(spill_end(j) - block_begin(j + 1)));
    for (Index j = 0; j < blocks; ++j) {
        Index first = j;
        for (Index s = 0; s < j; ++s)
            if (spill_end(s) > block_begin(j)) {
                first = s;
                break;
            }
        first_spiller_[static_cast<std::size_t>(j)] = first;
    }
}

void HalfLists::update(const Index* offsets, const Index* indices, Index n, std::uint64_t version) {
    one_phase_.assign(static_cast<std::size_t>(n), 0);
    update(offsets, indices, n, version, one_phase_.data(), 0);
}

}  // namespace grit::neighbors
