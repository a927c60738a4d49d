// Triangles binned in a uniform grid whatever their size: each triangle sits in every cell its box,
// widened by the reach, overlaps, so every triangle within the reach of a point is among the candidates
// of that point's one cell. Used by the grains' mesh walls and by the thin walls' side normals.
#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

#include "grit/core/vec.hpp"

namespace grit::mesh {

class TriangleBins {
  public:
    using Vec3 = core::Vec<3>;

    /// Bins `corners` (one triangle each) for points within `reach` of them, in cells of
    /// `cell_factor` x reach, coarser (x 1.5 at a time) while the grid would pass `max_cells` or its lists
    /// 16 million entries.
    void build(const std::vector<std::array<Vec3, 3>>& corners, double reach, double cell_factor = 2.0,
               std::int64_t max_cells = 2'000'000);

    /// Calls f(triangle) for the candidates of x, in ascending triangle order; none off the grid.
    template <class F>
    void for_each_candidate(const Vec3& x, F&& f) const {
        std::array<std::int64_t, 3> at{};
        for (int k = 0; k < 3; ++k) {
            const double u = std::floor((x[k] - low_[k]) / cell_);
            if (!(u >= 0.0) || u >= static_cast<double>(cells_[static_cast<std::size_t>(k)])) return;
            at[static_cast<std::size_t>(k)] = static_cast<std::int64_t>(u);
        }
        const auto cell = static_cast<std::size_t>((at[0] * cells_[1] + at[1]) * cells_[2] + at[2]);
        for (std::int64_t s = start_[cell]; s < start_[cell + 1]; ++s)
            f(items_[static_cast<std::size_t>(s)]);
    }

    /// The reach the bins were built for (< 0 before the first build).
    double reach() const noexcept { return reach_; }

  private:
    Vec3 low_ = Vec3::zero();
    double cell_ = 0.0, reach_ = -1.0;
    std::array<std::int64_t, 3> cells_{};
    std::vector<std::int64_t> start_;
    std::vector<std::int32_t> items_;
};

}  // namespace grit::mesh
