// TriangleBins: a counting sort of the triangles into the cells their widened boxes overlap.
#include "grit/mesh/triangle_bins.hpp"

#include <algorithm>

namespace grit::mesh {

void TriangleBins::build(const std::vector<std::array<Vec3, 3>>& corners, double reach, double cell_factor,
                         std::int64_t max_cells) {
    start_.assign(1, 0);
    items_.clear();
    reach_ = reach;
    cells_ = {0, 0, 0};
    if (corners.empty()) return;
    Vec3 lo = corners.front()[0], hi = lo;
    for (const auto& t : corners)
        for (const Vec3& p : t)
            for (int k = 0; k < 3; ++k)
                lo[k] = std::min(lo[k], p[k]), hi[k] = std::max(hi[k], p[k]);
    for (int k = 0; k < 3; ++k)
        lo[k] -= reach, hi[k] += reach;
    cell_ = std::max(cell_factor * reach, 1e-12);
    auto count = [&](double c) {
        std::int64_t total = 1;
        for (int k = 0; k < 3; ++k)
            total *= static_cast<std::int64_t>(std::floor((hi[k] - lo[k]) / c)) + 1;
        return total;
    };
    // Each triangle is listed in every cell its widened box overlaps: fine cells over a large mesh would
    // list it thousands of times, so the lists are capped too (16 million entries, 64 MB).
    auto entries = [&](double c) {
        double total = 0.0;
        for (const auto& t : corners) {
            double cells = 1.0;
            for (int k = 0; k < 3; ++k) {
                const double extent = std::max({t[0][k], t[1][k], t[2][k]}) - std::min({t[0][k], t[1][k], t[2][k]});
                cells *= std::floor((extent + 2.0 * reach) / c) + 2.0;
            }
            total += cells;
        }
        return total;
    };
    while (count(cell_) > max_cells || entries(cell_) > 16.0e6)
        cell_ *= 1.5;
    low_ = lo;
    for (int k = 0; k < 3; ++k)
        cells_[static_cast<std::size_t>(k)] = static_cast<std::int64_t>(std::floor((hi[k] - lo[k]) / cell_)) + 1;
    const std::int64_t total = cells_[0] * cells_[1] * cells_[2];
    // A point within the reach of a triangle lies in its box widened by the reach.
    auto cell_range = [&](const std::array<Vec3, 3>& t, std::array<std::int64_t, 3>& a,
                          std::array<std::int64_t, 3>& b) {
        for (int k = 0; k < 3; ++k) {
            const double l = std::min({t[0][k], t[1][k], t[2][k]}) - reach,
                         h = std::max({t[0][k], t[1][k], t[2][k]}) + reach;
            const auto K = static_cast<std::size_t>(k);
            a[K] =
                std::clamp<std::int64_t>(static_cast<std::int64_t>(std::floor((l - lo[k]) / cell_)), 0, cells_[K] - 1);
            b[K] =
                std::clamp<std::int64_t>(static_cast<std::int64_t>(std::floor((h - lo[k]) / cell_)), 0, cells_[K] - 1);
        }
    };
    auto cell_of = [&](std::int64_t i, std::int64_t j, std::int64_t k) {
        return static_cast<std::size_t>((i * cells_[1] + j) * cells_[2] + k);
    };
    start_.assign(static_cast<std::size_t>(total) + 1, 0);
    std::array<std::int64_t, 3> a{}, b{};
    for (const auto& t : corners) {
        cell_range(t, a, b);
        for (std::int64_t i = a[0]; i <= b[0]; ++i)
            for (std::int64_t j = a[1]; j <= b[1]; ++j)
                for (std::int64_t k = a[2]; k <= b[2]; ++k)
                    ++start_[cell_of(i, j, k) + 1];
    }
    for (std::size_t c = 0; c < static_cast<std::size_t>(total); ++c)
        start_[c + 1] += start_[c];
    items_.assign(static_cast<std::size_t>(start_.back()), 0);
    std::vector<std::int64_t> next(start_.begin(), start_.end() - 1);
    for (std::size_t t = 0; t < corners.size(); ++t) {
        cell_range(corners[t], a, b);
        for (std::int64_t i = a[0]; i <= b[0]; ++i)
            for (std::int64_t j = a[1]; j <= b[1]; ++j)
                for (std::int64_t k = a[2]; k <= b[2]; ++k)
                    items_[static_cast<std::size_t>(next[cell_of(i, j, k)]++)] = static_cast<std::int32_t>(t);
    }
}

}  // namespace grit::mesh
