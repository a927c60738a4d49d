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

SignedDistance::Query SignedDistance::query(const Vec3& p) const {
    const auto& v = mesh_.vertices();
    const auto& tri = mesh_.triangles();
    double best = std::numeric_limits<double>::infinity();
    Vec3 normal = Vec3::zero(), closest = p;
    bool rim = false;
    for (std::size_t t = 0; t < tri.size(); ++t) {
        // A triangle whose box is farther than the best so far cannot be closer.
        double gap2 = 0.0;
        for (int k = 0; k < 3; ++k) {
            const double g = std::max({box_low_[t][k] - p[k], 0.0, p[k] - box_high_[t][k]});
            gap2 += g * g;
        }
        if (gap2 >= best) continue;
        const ClosestPoint q =
            closest_point_on_triangle(p, v[static_cast<std::size_t>(tri[t][0])], v[static_cast<std::size_t>(tri[t][1])],
                                      v[static_cast<std::size_t>(tri[t][2])]);
        const double d2 = core::norm2(p - q.point);
        if (d2 >= best) continue;
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
    const double distance = std::sqrt(best);
    return {core::dot(p - closest, normal) * orientation_ >= 0.0 ? distance : -distance, rim};
}

}  // namespace grit::mesh
