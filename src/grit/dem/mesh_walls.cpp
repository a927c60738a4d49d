// MeshWalls: placement and motion, the triangle bins and the face/edge/corner contact rules.
#include "grit/dem/mesh_walls.hpp"

#include <cmath>

#include "grit/core/error.hpp"

namespace grit::dem {

namespace {

/// v rotated by the rotation vector phi (Rodrigues).
Vec3 rotate(const Vec3& v, const Vec3& phi) {
    const double angle = core::norm(phi);
    if (angle == 0.0) return v;
    const Vec3 k = phi * (1.0 / angle);
    const double c = std::cos(angle), s = std::sin(angle);
    return v * c + core::cross(k, v) * s + k * (core::dot(k, v) * (1.0 - c));
}

}  // namespace

void MeshWalls::add(MeshWall wall, GrainSet<3>& grains) {
    if (walls_.empty())
        for (int k = 0; k < slots; ++k) {
            grains.fields().template add<std::int32_t>("mesh_contact_" + std::to_string(k), -1, false);
            grains.fields().template add<Vec3>("mesh_history_" + std::to_string(k), Vec3::zero(), false);
        }
    const std::size_t wall_index = walls_.size();
    triangle_offset_.push_back(corners_.size());
    edge_offset_.push_back(walls_.empty() ? 0 : edge_offset_.back() + walls_.back().mesh.edge_count());
    vertex_offset_.push_back(walls_.empty() ? 0 : vertex_offset_.back() + walls_.back().mesh.vertex_count());
    const auto& vertices = wall.mesh.vertices();
    for (const auto& t : wall.mesh.triangles()) {
        corners_.push_back({vertices[static_cast<std::size_t>(t[0])], vertices[static_cast<std::size_t>(t[1])],
                            vertices[static_cast<std::size_t>(t[2])]});
        triangle_wall_.push_back(static_cast<std::int32_t>(wall_index));
    }
    centre_now_.push_back(wall.motion.centre);
    walls_.push_back(std::move(wall));
    placed_ = false;
    bins_dirty_ = true;
}

std::pair<std::size_t, std::size_t> MeshWalls::locate(std::int32_t triangle) const {
    const auto w = static_cast<std::size_t>(triangle_wall_[static_cast<std::size_t>(triangle)]);
    return {w, static_cast<std::size_t>(triangle) - triangle_offset_[w]};
}

void MeshWalls::place(double time) {
    for (std::size_t w = 0; w < walls_.size(); ++w) {
        const MeshMotion& m = walls_[w].motion;
        if (placed_ && !m.moving()) continue;
        centre_now_[w] = m.centre + m.velocity * time;
        const Vec3 phi = m.angular_velocity * time;
        const auto& vertices = walls_[w].mesh.vertices();
        const auto& triangles = walls_[w].mesh.triangles();
        for (std::size_t t = 0; t < triangles.size(); ++t)
            for (std::size_t c = 0; c < 3; ++c)
                corners_[triangle_offset_[w] + t][c] =
                    centre_now_[w] + rotate(vertices[static_cast<std::size_t>(triangles[t][c])] - m.centre, phi);
        if (m.moving() || !placed_) bins_dirty_ = true;
    }
    placed_ = true;
    placed_time_ = time;
}

Vec3 MeshWalls::surface_velocity(std::size_t w, const Vec3& x) const {
    const MeshMotion& m = walls_[w].motion;
    return m.velocity + core::cross(m.angular_velocity, x - centre_now_[w]);
}

void MeshWalls::rebuild_bins(double reach) {
    if (!placed_) place(0.0);
    // Cells of twice the largest radius (coarser if the grid would pass 2 million cells).
    bins_.build(corners_, reach);
    bins_dirty_ = false;
}

void MeshWalls::find_contacts(const Vec3& x, double r, std::vector<Candidate>& out) const {
    out.clear();
    const double r2 = r * r;
    bins_.for_each_candidate(x, [&](const std::int32_t t) {
        const auto& p = corners_[static_cast<std::size_t>(t)];
        const mesh::ClosestPoint q = mesh::closest_point_on_triangle(x, p[0], p[1], p[2]);
        const double d2 = core::norm2(q.point - x);
        if (d2 >= r2) return;
        const auto [w, local] = locate(t);
        const mesh::TriangleMesh& m = walls_[w].mesh;
        std::int64_t id = t;
        if (q.feature == mesh::Feature::edge) {
            const auto e = static_cast<std::size_t>(m.triangle_edges(local)[static_cast<std::size_t>(q.index)]);
            if (!m.edge_active(e)) return;  // inside a flat region: the triangle beside it gives a face contact
            id = static_cast<std::int64_t>(edge_offset_[w] + e);
        } else if (q.feature == mesh::Feature::vertex) {
            const auto v = static_cast<std::size_t>(m.triangles()[local][static_cast<std::size_t>(q.index)]);
            if (!m.vertex_active(v)) return;
            id = static_cast<std::int64_t>(vertex_offset_[w] + v);
        }
        out.push_back({t, q.feature, id, q.point, d2});
    });
    // Faces first, then edges, then corners; nearest first within each.
    std::sort(out.begin(), out.end(), [](const Candidate& a, const Candidate& b) {
        if (a.feature != b.feature) return a.feature < b.feature;
        if (a.distance2 != b.distance2) return a.distance2 < b.distance2;
        return a.triangle < b.triangle;
    });
    std::size_t kept = 0;
    for (std::size_t k = 0; k < out.size(); ++k) {
        const Candidate hit = out[k];
        const auto [w, local] = locate(hit.triangle);
        const mesh::TriangleMesh& m = walls_[w].mesh;
        bool drop = false;
        for (std::size_t j = 0; j < kept && !drop; ++j) {
            const Candidate& o = out[j];
            if (hit.feature == mesh::Feature::face) {
                // The same point seen by two triangles of a flat region (a centre right above their edge).
                drop = core::norm2(o.point - hit.point) <= 1e-20 * r2;
            } else if (hit.feature == o.feature) {
                drop = hit.feature_id == o.feature_id;  // the edge or corner again, from its other triangles
            } else if (locate(o.triangle).first == w) {
                // An edge or corner of a face, or a corner of an edge, already in contact.
                const std::size_t olocal = locate(o.triangle).second;
                if (hit.feature == mesh::Feature::edge) {
                    const auto e = static_cast<std::size_t>(hit.feature_id) - edge_offset_[w];
                    const auto& two = m.edge_triangles(e);
                    drop = static_cast<std::int32_t>(olocal) == two[0] || static_cast<std::int32_t>(olocal) == two[1];
                } else {
                    const auto vtx =
                        static_cast<std::int32_t>(static_cast<std::size_t>(hit.feature_id) - vertex_offset_[w]);
                    if (o.feature == mesh::Feature::face) {
                        for (const std::int32_t q : m.triangles()[olocal])
                            drop = drop || q == vtx;
                    } else {
                        const auto& ends = m.edge_vertices(static_cast<std::size_t>(o.feature_id) - edge_offset_[w]);
                        drop = ends[0] == vtx || ends[1] == vtx;
                    }
                }
            }
        }
        if (!drop) out[kept++] = hit;
    }
    out.resize(kept);
    // Deepest first, so the slots keep the strongest contacts if there are more than they hold.
    std::stable_sort(out.begin(), out.end(),
                     [](const Candidate& a, const Candidate& b) { return a.distance2 < b.distance2; });
}

}  // namespace grit::dem
