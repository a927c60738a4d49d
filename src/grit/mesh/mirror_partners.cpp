// Mirror partners of triangles: centroids binned on a grid of the tolerance, each triangle's mirrored
// centroid looked up in its cell and the cells around it, the corners then compared one by one.
#include "grit/mesh/mirror_partners.hpp"

#include <algorithm>
#include <cmath>
#include <unordered_map>

namespace grit::mesh {

namespace {

using Vec3 = core::Vec<3>;
using Cell = std::array<std::int64_t, 3>;

struct CellHash {
    std::size_t operator()(const Cell& c) const noexcept {
        std::size_t h = 1469598103934665603ull;
        for (const std::int64_t k : c) h = (h ^ static_cast<std::size_t>(k)) * 1099511628211ull;
        return h;
    }
};

Vec3 centroid(const Corners& t) { return (t[0] + t[1] + t[2]) * (1.0 / 3.0); }

Cell cell_of(const Vec3& x, double size) {
    return {static_cast<std::int64_t>(std::floor(x[0] / size)), static_cast<std::int64_t>(std::floor(x[1] / size)),
            static_cast<std::int64_t>(std::floor(x[2] / size))};
}

bool near(const Vec3& a, const Vec3& b, double tolerance) {
    for (int k = 0; k < 3; ++k)
        if (!(std::abs(a[k] - b[k]) <= tolerance)) return false;
    return true;
}

// Every corner of `t` near a corner of `m`, and each of m's corners met once.
bool same_corners(const Corners& t, const Corners& m, double tolerance) {
    std::array<bool, 3> used{};
    for (const Vec3& c : t) {
        bool found = false;
        for (int k = 0; k < 3 && !found; ++k)
            if (!used[static_cast<std::size_t>(k)] && near(c, m[static_cast<std::size_t>(k)], tolerance))
                used[static_cast<std::size_t>(k)] = found = true;
        if (!found) return false;
    }
    return true;
}

}  // namespace

std::vector<std::int64_t> mirror_partners(const std::vector<Corners>& triangles, int axis, double tolerance) {
    const double size = 2.0 * tolerance;  // a centroid within the tolerance lies in this cell or the next
    std::unordered_map<Cell, std::vector<std::int64_t>, CellHash> bins;
    for (std::size_t t = 0; t < triangles.size(); ++t)
        bins[cell_of(centroid(triangles[t]), size)].push_back(static_cast<std::int64_t>(t));
    std::vector<std::int64_t> partner(triangles.size(), -1);
    for (std::size_t t = 0; t < triangles.size(); ++t) {
        Corners mirrored = triangles[t];
        for (Vec3& c : mirrored) c[axis] = -c[axis];
        const Cell home = cell_of(centroid(mirrored), size);
        for (int i = -1; i <= 1 && partner[t] < 0; ++i)
            for (int j = -1; j <= 1 && partner[t] < 0; ++j)
                for (int k = -1; k <= 1 && partner[t] < 0; ++k) {
                    const auto it = bins.find({home[0] + i, home[1] + j, home[2] + k});
                    if (it == bins.end()) continue;
                    for (const std::int64_t m : it->second)
                        if (same_corners(mirrored, triangles[static_cast<std::size_t>(m)], tolerance)) {
                            partner[t] = m;
                            break;
                        }
                }
    }
    return partner;
}

double mirror_tolerance(const std::vector<Corners>& triangles) {
    double extent = 0.0;
    for (const Corners& t : triangles)
        for (const Vec3& c : t)
            for (int k = 0; k < 3; ++k) extent = std::max(extent, std::abs(c[k]));
    return 1e-6 * extent;
}

}  // namespace grit::mesh
