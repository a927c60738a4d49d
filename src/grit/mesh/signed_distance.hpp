// Signed distance to a closed triangle mesh, positive outside: the distance to the closest point, with
// the sign of (p - q) . N, N the angle-weighted pseudo-normal of the feature q lies on (the face normal, the
// sum of an edge's two face normals, the angle-weighted sum at a corner; Baerentzen & Aanaes, IEEE TVCG 11,
// 2005), which gives the right sign at edges and corners too. Used to lay wall particles along a mesh.
#pragma once

#include <cstdint>
#include <vector>

#include "grit/mesh/triangle_mesh.hpp"

namespace grit::mesh {

class SignedDistance {
  public:
    /// For a `closed` mesh (watertight, consistently oriented) the sign is outside/inside: a mesh whose
    /// normals point inwards (negative enclosed volume) has its sign flipped. For an open mesh it is the
    /// side its facet normals point to (> 0) or away from (< 0).
    explicit SignedDistance(const TriangleMesh& mesh, bool closed = true);

    struct Query {
        double distance;  ///< signed [m]
        bool on_rim;      ///< the closest point is on an open edge or one of its corners (beyond the rim)
    };
    Query query(const Vec3& p) const;
    /// Signed distance of p [m]: > 0 outside the closed surface (in front of an open one), < 0 inside.
    double operator()(const Vec3& p) const { return query(p).distance; }
    /// The volume the mesh encloses [m^3] (positive whatever its orientation).
    double volume() const noexcept { return volume_; }

  private:
    const TriangleMesh& mesh_;
    std::vector<Vec3> face_normal_, edge_normal_, vertex_normal_;
    std::vector<Vec3> box_low_, box_high_;  // per triangle
    std::vector<std::uint8_t> rim_vertex_;  // corners of open edges
    double orientation_ = 1.0, volume_ = 0.0;
};

}  // namespace grit::mesh
