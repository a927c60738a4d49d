// A triangle mesh with its topology: vertices welded from an STL soup, each edge with the triangles on
// its two sides, and which edges and vertices can be touched as such (not inside a flat region). The
// checks a user needs before a mesh is trusted (degenerate triangles, edges of more than two triangles,
// open edges) are here, with messages that name the file and the first bad element.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "grit/core/vec.hpp"
#include "grit/mesh/stl_file.hpp"

namespace grit::mesh {

using Vec3 = core::Vec<3>;

/// Where a mesh is placed: x = translate + R (scale x_file), R the rotations about x, then y, then z by
/// rotate[0..2] degrees.
struct Placement {
    double scale = 1.0;
    Vec3 rotate = Vec3::zero();     ///< [deg] about x, y, z, applied in that order
    Vec3 translate = Vec3::zero();  ///< [m]
    Vec3 apply(const Vec3& x) const;
};

class TriangleMesh {
  public:
    /// Welds the soup's corners that are bit-identical in the file (STL writers repeat a shared corner
    /// exactly), places the vertices and builds the topology. `file` names the source in messages.
    /// Throws core::InputError: a degenerate triangle (zero area, named with its facet number), an edge
    /// shared by more than two triangles (non-manifold), and, if `watertight`, any open edge (with the
    /// count and the first one).
    static TriangleMesh from_facets(const std::vector<Facet>& facets, const Placement& placement,
                                    const std::string& file, bool watertight);

    std::size_t triangle_count() const noexcept { return triangles_.size(); }
    std::size_t vertex_count() const noexcept { return vertices_.size(); }
    const std::vector<Vec3>& vertices() const noexcept { return vertices_; }
    const std::vector<std::array<std::int32_t, 3>>& triangles() const noexcept { return triangles_; }
    /// Edge k of triangle t joins its corners k and k+1 (mod 3).
    const std::array<std::int32_t, 3>& triangle_edges(std::size_t t) const noexcept { return triangle_edges_[t]; }
    const std::array<std::int32_t, 2>& edge_triangles(std::size_t e) const noexcept { return edge_triangles_[e]; }
    const std::array<std::int32_t, 2>& edge_vertices(std::size_t e) const noexcept { return edge_vertices_[e]; }
    std::size_t edge_count() const noexcept { return edge_vertices_.size(); }
    /// An edge is touched as an edge unless its two triangles are coplanar (then the triangle beside it
    /// gives the contact as a face); a vertex unless every edge at it is inside a flat region.
    bool edge_active(std::size_t e) const noexcept { return edge_active_[e] != 0; }
    bool vertex_active(std::size_t v) const noexcept { return vertex_active_[v] != 0; }
    /// Edges with one triangle only.
    std::size_t open_edge_count() const noexcept { return open_edges_; }

    /// Unit normal of triangle t by its corners' order (right hand).
    Vec3 normal(std::size_t t) const;
    double area(std::size_t t) const;
    /// Do triangles s and t share a corner?
    bool adjacent(std::size_t s, std::size_t t) const;

  private:
    std::vector<Vec3> vertices_;
    std::vector<std::array<std::int32_t, 3>> triangles_;
    std::vector<std::array<std::int32_t, 3>> triangle_edges_;
    std::vector<std::array<std::int32_t, 2>> edge_vertices_;
    std::vector<std::array<std::int32_t, 2>> edge_triangles_;  // second is -1 for an open edge
    std::vector<std::uint8_t> edge_active_, vertex_active_;
    std::size_t open_edges_ = 0;
};

}  // namespace grit::mesh
