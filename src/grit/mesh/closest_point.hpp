// The point of a triangle closest to a point, and the feature it lies on (the face's inside, an edge, a
// corner): grain-triangle contacts are told apart by that feature (face, edge, vertex contacts).
#pragma once

#include <cstdint>

#include "grit/core/vec.hpp"

namespace grit::mesh {

/// Where the closest point lies: inside the face, on edge k (corners k and k+1 mod 3) or at corner k.
enum class Feature : std::uint8_t { face, edge, vertex };

struct ClosestPoint {
    core::Vec<3> point;
    Feature feature = Feature::face;
    std::int32_t index = 0;  ///< the edge's or corner's k (0 for the face)
};

/// The closest point of triangle (a, b, c) to p. A point whose projection onto the plane lies inside the
/// triangle, or on its boundary within a relative 1e-12 of the barycentric coordinates, is a face point,
/// so that a point exactly above an edge between two triangles of a flat region is the face point of
/// both (the caller keeps one) rather than an edge point of either. Outside, the region tests on the
/// corners' and edges' outer normals (Ericson, Real-Time Collision Detection, 2005, sec. 5.1.5).
inline ClosestPoint closest_point_on_triangle(const core::Vec<3>& p, const core::Vec<3>& a, const core::Vec<3>& b,
                                              const core::Vec<3>& c) {
    using core::dot;
    const core::Vec<3> ab = b - a, ac = c - a, ap = p - a;
    // Barycentric coordinates of the projection (Cramer on the 2x2 normal equations).
    const double d00 = dot(ab, ab), d01 = dot(ab, ac), d11 = dot(ac, ac);
    const double d20 = dot(ap, ab), d21 = dot(ap, ac);
    const double denominator = d00 * d11 - d01 * d01;
    const double v = (d11 * d20 - d01 * d21) / denominator;
    const double w = (d00 * d21 - d01 * d20) / denominator;
    constexpr double tolerance = 1e-12;
    if (v >= -tolerance && w >= -tolerance && v + w <= 1.0 + tolerance) return {a + ab * v + ac * w, Feature::face, 0};

    // Outside: the corner regions, then the edge regions.
    const double d1 = dot(ab, ap), d2 = dot(ac, ap);
    if (d1 <= 0.0 && d2 <= 0.0) return {a, Feature::vertex, 0};
    const core::Vec<3> bp = p - b;
    const double d3 = dot(ab, bp), d4 = dot(ac, bp);
    if (d3 >= 0.0 && d4 <= d3) return {b, Feature::vertex, 1};
    const core::Vec<3> cp = p - c;
    const double d5 = dot(ab, cp), d6 = dot(ac, cp);
    if (d6 >= 0.0 && d5 <= d6) return {c, Feature::vertex, 2};
    const double vc = d1 * d4 - d3 * d2;
    if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) return {a + ab * (d1 / (d1 - d3)), Feature::edge, 0};
    const double va = d3 * d6 - d5 * d4;
    if (va <= 0.0 && d4 - d3 >= 0.0 && d5 - d6 >= 0.0)
        return {b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6))), Feature::edge, 1};
    // What is left outside is edge ca's region.
    return {a + ac * (d2 / (d2 - d6)), Feature::edge, 2};
}

}  // namespace grit::mesh
