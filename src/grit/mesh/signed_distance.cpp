// Signed distance by closest point and pseudo-normals.
#include "grit/mesh/signed_distance.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "grit/mesh/closest_point.hpp"

namespace grit::mesh {

SignedDistance::SignedDistance(const TriangleMesh& mesh, bool closed) : mesh_(mesh) {
    const auto& v = mesh.vertices();
    const auto& tri = mesh.triangles();
    face_normal_.resize(tri.size());
    edge_normal_.assign(mesh.edge_count(), Vec3::zero());
    vertex_normal_.assign(mesh.vertex_count(), Vec3::zero());
    double signed_volume = 0.0;
    for (std::size_t t = 0; t < tri.size(); ++t) {
        const Vec3 n = mesh.normal(t);
        face_normal_[t] = n;
        for (std::size_t k = 0; k < 3; ++k) {
            edge_normal_[static_cast<std::size_t>(mesh.triangle_edges(t)[k])] += n;
            // The corner's angle weights the face's normal at that vertex.
            const Vec3& p = v[static_cast<std::size_t>(tri[t][k])];
            const Vec3 a = v[static_cast<std::size_t>(tri[t][(k + 1) % 3])] - p,
                       b = v[static_cast<std::size_t>(tri[t][(k + 2) % 3])] - p;
            const double angle = std::acos(std::clamp(core::dot(a, b) / (core::norm(a) * core::norm(b)), -1.0, 1.0));
            vertex_normal_[static_cast<std::size_t>(tri[t][k])] += n * angle;
        }
        const Vec3& p0 = v[static_cast<std::size_t>(tri[t][0])];
        signed_volume +=
            core::dot(p0, core::cross(v[static_cast<std::size_t>(tri[t][1])], v[static_cast<std::size_t>(tri[t][2])])) /
            6.0;
        Vec3 lo = p0, hi = p0;
        for (const auto c : tri[t])
            for (int k = 0; k < 3; ++k)
                lo[k] = std::min(lo[k], v[static_cast<std::size_t>(c)][k]),
                hi[k] = std::max(hi[k], v[static_cast<std::size_t>(c)][k]);
        box_low_.push_back(lo);
        box_high_.push_back(hi);
    }
    orientation_ = closed && signed_volume < 0.0 ? -1.0 : 1.0;
    rim_vertex_.assign(mesh.vertex_count(), 0);
    for (std::size_t e = 0; e < mesh.edge_count(); ++e)
        if (mesh.edge_triangles(e)[1] < 0)
            for (const auto corner : mesh.edge_vertices(e))
                rim_vertex_[static_cast<std::size_t>(corner)] = 1;
    volume_ = std::abs(signed_volume);
}

void SignedDistance::consider(std::size_t t, const Vec3& p, double& best, Vec3& closest, Vec3& normal,
                              bool& rim) const {
    const auto& v = mesh_.vertices();
    const auto& tri = mesh_.triangles();
    // A triangle whose box is farther than the best so far cannot be closer.
    double gap2 = 0.0;
    for (int k = 0; k < 3; ++k) {
        const double g = std::max({box_low_[t][k] - p[k], 0.0, p[k] - box_high_[t][k]});
        gap2 += g * g;
    }
    if (gap2 >= best) return;
    const ClosestPoint q =
        closest_point_on_triangle(p, v[static_cast<std::size_t>(tri[t][0])], v[static_cast<std::size_t>(tri[t][1])],
                                  v[static_cast<std::size_t>(tri[t][2])]);
    const double d2 = core::norm2(p - q.point);
    if (d2 >= best) return;
    best = d2;
    closest = q.point;
    rim = false;
    if (q.feature == Feature::face) {
        normal = face_normal_[t];
    } else if (q.feature == Feature::edge) {
        const auto e = static_cast<std::size_t>(mesh_.triangle_edges(t)[static_cast<std::size_t>(q.index)]);
        normal = edge_normal_[e];
        rim = mesh_.edge_triangles(e)[1] < 0;
    } else {
        const auto c = static_cast<std::size_t>(tri[t][static_cast<std::size_t>(q.index)]);
        normal = vertex_normal_[c];
        rim = rim_vertex_[c] != 0;
    }
}

SignedDistance::Query SignedDistance::answer(const Vec3& p, double best, const Vec3& closest, const Vec3& normal,
                                             bool rim) const {
    const double distance = std::sqrt(best);
    const double length = core::norm(normal);
    // An edge between two facets folded flat onto each other (a knife edge) has no pseudo-normal.
    const Vec3 unit = length > 1e-9 ? normal * (orientation_ / length) : Vec3::zero();
    return {core::dot(p - closest, normal) * orientation_ >= 0.0 ? distance : -distance, rim, unit};
}

SignedDistance::Query SignedDistance::query(const Vec3& p) const {
    double best = std::numeric_limits<double>::infinity();
    Vec3 normal = Vec3::zero(), closest = p;
    bool rim = false;
    for (std::size_t t = 0; t < mesh_.triangles().size(); ++t)
        consider(t, p, best, closest, normal, rim);
    return answer(p, best, closest, normal, rim);
}

void SignedDistance::bin(double reach, double cell_factor) {
    std::vector<std::array<Vec3, 3>> corners;
    corners.reserve(mesh_.triangles().size());
    for (const auto& t : mesh_.triangles())
        corners.push_back({mesh_.vertices()[static_cast<std::size_t>(t[0])],
                           mesh_.vertices()[static_cast<std::size_t>(t[1])],
                           mesh_.vertices()[static_cast<std::size_t>(t[2])]});
    bins_.build(corners, reach, cell_factor);
}

SignedDistance::Query SignedDistance::query_near(const Vec3& p) const {
    const double reach = bins_.reach();
    // The nearest corner among the candidates bounds the distance from above; with that bound the box
    // test skips most closest-point computations (a cell near a fine mesh lists hundreds of triangles).
    const auto& v = mesh_.vertices();
    double corner2 = reach * reach;
    bins_.for_each_candidate(p, [&](std::int32_t t) {
        for (const auto c : mesh_.triangles()[static_cast<std::size_t>(t)])
            corner2 = std::min(corner2, core::norm2(v[static_cast<std::size_t>(c)] - p));
    });
    double best = corner2 * (1.0 + 1e-9);  // slack: the closest point at a corner comes out of rounded arithmetic
    Vec3 normal = Vec3::zero(), closest = p;
    bool rim = false;
    bins_.for_each_candidate(
        p, [&](std::int32_t t) { consider(static_cast<std::size_t>(t), p, best, closest, normal, rim); });
    if (!(best < reach * reach)) return {std::numeric_limits<double>::infinity(), false, Vec3::zero()};
    return answer(p, best, closest, normal, rim);
}

Vec3 SignedDistance::face_behind(const Vec3& p, double sign) const {
    const auto& v = mesh_.vertices();
    const auto& tri = mesh_.triangles();
    const double reach = bins_.reach();
    double best = reach * reach;
    Vec3 found = Vec3::zero();
    bins_.for_each_candidate(p, [&](std::int32_t ti) {
        const auto t = static_cast<std::size_t>(ti);
        const ClosestPoint q =
            closest_point_on_triangle(p, v[static_cast<std::size_t>(tri[t][0])], v[static_cast<std::size_t>(tri[t][1])],
                                      v[static_cast<std::size_t>(tri[t][2])]);
        if (q.feature != Feature::face) return;
        const Vec3 n = face_normal_[t] * (orientation_ * sign);
        const double d2 = core::norm2(p - q.point);
        if (d2 >= best || core::dot(p - q.point, n) >= 0.0) return;
        best = d2;
        found = n;
    });
    return found;
}

}  // namespace grit::mesh
