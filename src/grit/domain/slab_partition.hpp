// A static partition of space into slabs along one axis, one per rank: which rank owns a point, and how far
// a point is from another rank's slab (what that rank's ghosts must copy). The cost-weighted partition that
// follows the jet will replace it behind the same two questions.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

#include "grit/core/vec.hpp"

namespace grit::domain {

template <int Dim>
struct SlabPartition {
    int axis = 0;
    /// Ascending; rank r owns [cuts[r-1], cuts[r]) along `axis` (rank 0 from -infinity, the last rank to
    /// +infinity, so that no particle is ever outside every slab).
    std::vector<double> cuts;

    int size() const noexcept { return static_cast<int>(cuts.size()) + 1; }
    /// The rank whose slab holds x.
    int owner(const core::Vec<Dim>& x) const {
        return static_cast<int>(std::upper_bound(cuts.begin(), cuts.end(), x[axis]) - cuts.begin());
    }
    /// How far x is from rank r's slab along the axis (0 inside it).
    double distance(const core::Vec<Dim>& x, int r) const {
        const double inf = std::numeric_limits<double>::infinity();
        const double lower = r > 0 ? cuts[static_cast<std::size_t>(r - 1)] : -inf;
        const double upper = r < static_cast<int>(cuts.size()) ? cuts[static_cast<std::size_t>(r)] : inf;
        return std::max({lower - x[axis], x[axis] - upper, 0.0});
    }
    /// Throws std::logic_error unless the cuts ascend and the partition has `ranks` slabs.
    void check(int ranks) const {
        if (size() != ranks) throw std::logic_error("slab partition of " + std::to_string(size()) + " slabs for " +
                                                    std::to_string(ranks) + " ranks");
        if (!std::is_sorted(cuts.begin(), cuts.end())) throw std::logic_error("slab cuts out of order");
    }
};

}  // namespace grit::domain
