// TriangleMesh: welding, placement, topology and checks.
#include "grit/mesh/triangle_mesh.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <utility>

#include "grit/core/error.hpp"

namespace grit::mesh {

Vec3 Placement::apply(const Vec3& x) const {
    Vec3 y = x * scale;
    for (int axis = 0; axis < 3; ++axis) {
        const double a = rotate[axis] * std::numbers::pi / 180.0;
        if (a == 0.0) continue;
        const double c = std::cos(a), s = std::sin(a);
        const int i = (axis + 1) % 3, j = (axis + 2) % 3;  // the plane the rotation turns
        const double yi = c * y[i] - s * y[j], yj = s * y[i] + c * y[j];
        y[i] = yi;
        y[j] = yj;
    }
    return y + translate;
}

TriangleMesh TriangleMesh::from_facets(const std::vector<Facet>& facets, const Placement& placement,
                                       const std::string& file, bool watertight) {
    TriangleMesh m;
    std::map<std::array<double, 3>, std::int32_t> index;
    for (const Facet& f : facets) {
        std::array<std::int32_t, 3> t{};
        for (std::size_t c = 0; c < 3; ++c) {
            const std::array<double, 3> key{f[c][0], f[c][1], f[c][2]};
            auto [it, fresh] = index.try_emplace(key, static_cast<std::int32_t>(m.vertices_.size()));
            if (fresh) m.vertices_.push_back(placement.apply(f[c]));
            t[c] = it->second;
        }
        m.triangles_.push_back(t);
    }
    // Degenerate: repeated corners, or an area below 1e-12 of the squared extent (a sliver no contact
    // normal can be taken from).
    Vec3 lo = m.vertices_.front(), hi = lo;
    for (const Vec3& v : m.vertices_)
        for (int k = 0; k < 3; ++k)
            lo[k] = std::min(lo[k], v[k]), hi[k] = std::max(hi[k], v[k]);
    const double extent2 = core::norm2(hi - lo);
    for (std::size_t t = 0; t < m.triangles_.size(); ++t) {
        const auto& c = m.triangles_[t];
        if (c[0] == c[1] || c[1] == c[2] || c[2] == c[0] || !(m.area(t) > 1e-12 * extent2))
            throw core::InputError(fmt::format(
                "mesh file '{}': facet {} is degenerate (zero area: corners ({}), ({}), ({})); remove it or repair "
                "the mesh",
                file, t + 1, fmt::join(facets[t][0].c, ", "), fmt::join(facets[t][1].c, ", "),
                fmt::join(facets[t][2].c, ", ")));
    }
    // Edges by their sorted vertex pair.
    std::map<std::pair<std::int32_t, std::int32_t>, std::int32_t> edges;
    m.triangle_edges_.resize(m.triangles_.size());
    for (std::size_t t = 0; t < m.triangles_.size(); ++t)
        for (std::size_t k = 0; k < 3; ++k) {
            std::int32_t a = m.triangles_[t][k], b = m.triangles_[t][(k + 1) % 3];
            if (a > b) std::swap(a, b);
            auto [it, fresh] = edges.try_emplace({a, b}, static_cast<std::int32_t>(m.edge_vertices_.size()));
            const std::int32_t e = it->second;
            if (fresh) {
                m.edge_vertices_.push_back({a, b});
                m.edge_triangles_.push_back({static_cast<std::int32_t>(t), -1});
            } else if (m.edge_triangles_[static_cast<std::size_t>(e)][1] < 0) {
                m.edge_triangles_[static_cast<std::size_t>(e)][1] = static_cast<std::int32_t>(t);
            } else {
                throw core::InputError(fmt::format(
                    "mesh file '{}': the edge ({}) - ({}) is shared by more than two facets ({}, {} and {}): the "
                    "mesh is not manifold",
                    file, fmt::join(m.vertices_[static_cast<std::size_t>(a)].c, ", "),
                    fmt::join(m.vertices_[static_cast<std::size_t>(b)].c, ", "),
                    m.edge_triangles_[static_cast<std::size_t>(e)][0] + 1,
                    m.edge_triangles_[static_cast<std::size_t>(e)][1] + 1, t + 1));
            }
            m.triangle_edges_[t][k] = e;
        }
    // Flat edges: the far corner of the second triangle lies in the first one's plane.
    m.edge_active_.assign(m.edge_vertices_.size(), 1);
    m.vertex_active_.assign(m.vertices_.size(), 0);
    std::size_t first_open = m.edge_vertices_.size();
    for (std::size_t e = 0; e < m.edge_vertices_.size(); ++e) {
        const auto [s, t] = m.edge_triangles_[e];
        if (t < 0) {
            ++m.open_edges_;
            first_open = std::min(first_open, e);
        } else {
            const auto& ct = m.triangles_[static_cast<std::size_t>(t)];
            std::int32_t far = ct[0];
            for (const std::int32_t v : ct)
                if (v != m.edge_vertices_[e][0] && v != m.edge_vertices_[e][1]) far = v;
            const Vec3& origin = m.vertices_[static_cast<std::size_t>(m.edge_vertices_[e][0])];
            const double height = std::abs(
                core::dot(m.normal(static_cast<std::size_t>(s)), m.vertices_[static_cast<std::size_t>(far)] - origin));
            const double length = core::norm(m.vertices_[static_cast<std::size_t>(m.edge_vertices_[e][1])] - origin);
            if (height <= 1e-9 * length) m.edge_active_[e] = 0;
        }
        if (m.edge_active_[e])
            for (const std::int32_t v : m.edge_vertices_[e])
                m.vertex_active_[static_cast<std::size_t>(v)] = 1;
    }
    if (watertight && m.open_edges_ > 0) {
        const auto& ev = m.edge_vertices_[first_open];
        throw core::InputError(fmt::format(
            "mesh file '{}': {} open edges (an edge of one facet only; the first joins ({}) and ({})), but the "
            "mesh must be watertight",
            file, m.open_edges_, fmt::join(m.vertices_[static_cast<std::size_t>(ev[0])].c, ", "),
            fmt::join(m.vertices_[static_cast<std::size_t>(ev[1])].c, ", ")));
    }
    return m;
}

Vec3 TriangleMesh::normal(std::size_t t) const {
    const auto& c = triangles_[t];
    const Vec3 n = core::cross(vertices_[static_cast<std::size_t>(c[1])] - vertices_[static_cast<std::size_t>(c[0])],
                               vertices_[static_cast<std::size_t>(c[2])] - vertices_[static_cast<std::size_t>(c[0])]);
    return n * (1.0 / core::norm(n));
}

double TriangleMesh::area(std::size_t t) const {
    const auto& c = triangles_[t];
    return 0.5 * core::norm(core::cross(
                     vertices_[static_cast<std::size_t>(c[1])] - vertices_[static_cast<std::size_t>(c[0])],
                     vertices_[static_cast<std::size_t>(c[2])] - vertices_[static_cast<std::size_t>(c[0])]));
}

bool TriangleMesh::adjacent(std::size_t s, std::size_t t) const {
    for (const std::int32_t a : triangles_[s])
        for (const std::int32_t b : triangles_[t])
            if (a == b) return true;
    return false;
}

}  // namespace grit::mesh
