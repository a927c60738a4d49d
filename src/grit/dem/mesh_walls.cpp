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
    Vec3 lo = corners_.front()[0], hi = lo;
    for (const auto& t : corners_)
        for (const Vec3& p : t)
            for (int k = 0; k < 3; ++k)
                lo[k] = std::min(lo[k], p[k]), hi[k] = std::max(hi[k], p[k]);
    for (int k = 0; k < 3; ++k)
        lo[k] -= reach, hi[k] += reach;
    // Cells of twice the largest radius, coarser if the grid would pass 2 million cells.
    cell_ = std::max(2.0 * reach, 1e-12);
    auto count = [&](double c) {
        std::int64_t total = 1;
        for (int k = 0; k < 3; ++k)
            total *= static_cast<std::int64_t>(std::floor((hi[k] - lo[k]) / c)) + 1;
        return total;
    };
    while (count(cell_) > 2'000'000)
        cell_ *= 1.5;
    grid_low_ = lo;
    for (int k = 0; k < 3; ++k)
        cells_[static_cast<std::size_t>(k)] = static_cast<std::int64_t>(std::floor((hi[k] - lo[k]) / cell_)) + 1;
    const std::int64_t total = cells_[0] * cells_[1] * cells_[2];
    // Each triangle goes into every cell its box, widened by the reach, overlaps: a grain touching it has
    // its centre within its radius of the triangle, so in one of those cells.
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
    cell_start_.assign(static_cast<std::size_t>(total) + 1, 0);
    std::array<std::int64_t, 3> a{}, b{};
    for (const auto& t : corners_) {
        cell_range(t, a, b);
        for (std::int64_t i = a[0]; i <= b[0]; ++i)
            for (std::int64_t j = a[1]; j <= b[1]; ++j)
                for (std::int64_t k = a[2]; k <= b[2]; ++k)
                    ++cell_start_[static_cast<std::size_t>((i * cells_[1] + j) * cells_[2] + k) + 1];
    }
    for (std::int64_t c = 0; c < total; ++c)
        cell_start_[static_cast<std::size_t>(c) + 1] += cell_start_[static_cast<std::size_t>(c)];
    cell_items_.assign(static_cast<std::size_t>(cell_start_.back()), 0);
    std::vector<std::int64_t> next(cell_start_.begin(), cell_start_.end() - 1);
    for (std::size_t t = 0; t < corners_.size(); ++t) {
        cell_range(corners_[t], a, b);
        for (std::int64_t i = a[0]; i <= b[0]; ++i)
            for (std::int64_t j = a[1]; j <= b[1]; ++j)
                for (std::int64_t k = a[2]; k <= b[2]; ++k)
                    cell_items_[static_cast<std::size_t>(
                        next[static_cast<std::size_t>((i * cells_[1] + j) * cells_[2] + k)]++)] =
                        static_cast<std::int32_t>(t);
    }
    binned_reach_ = reach;
    bins_dirty_ = false;
}

void MeshWalls::find_contacts(const Vec3& x, double r, std::vector<Candidate>& out) const {
    out.clear();
    std::array<std::int64_t, 3> at{};
    for (int k = 0; k < 3; ++k) {
        const double u = std::floor((x[k] - grid_low_[k]) / cell_);
        if (!(u >= 0.0) || u >= static_cast<double>(cells_[static_cast<std::size_t>(k)])) return;  // off the grid
        at[static_cast<std::size_t>(k)] = static_cast<std::int64_t>(u);
    }
    const auto cell = static_cast<std::size_t>((at[0] * cells_[1] + at[1]) * cells_[2] + at[2]);
    const double r2 = r * r;
    for (std::int64_t s = cell_start_[cell]; s < cell_start_[cell + 1]; ++s) {
        const std::int32_t t = cell_items_[static_cast<std::size_t>(s)];
        const auto& p = corners_[static_cast<std::size_t>(t)];
        const mesh::ClosestPoint q = mesh::closest_point_on_triangle(x, p[0], p[1], p[2]);
        const double d2 = core::norm2(q.point - x);
        if (d2 >= r2) continue;
        const auto [w, local] = locate(t);
        const mesh::TriangleMesh& m = walls_[w].mesh;
        std::int64_t id = t;
        if (q.feature == mesh::Feature::edge) {
            const auto e = static_cast<std::size_t>(m.triangle_edges(local)[static_cast<std::size_t>(q.index)]);
            if (!m.edge_active(e)) continue;  // inside a flat region: the triangle beside it gives a face contact
            id = static_cast<std::int64_t>(edge_offset_[w] + e);
        } else if (q.feature == mesh::Feature::vertex) {
            const auto v = static_cast<std::size_t>(m.triangles()[local][static_cast<std::size_t>(q.index)]);
            if (!m.vertex_active(v)) continue;
            id = static_cast<std::int64_t>(vertex_offset_[w] + v);
        }
        out.push_back({t, q.feature, id, q.point, d2});
    }
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
