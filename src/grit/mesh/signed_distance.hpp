// Signed distance to a closed triangle mesh, positive outside: the distance to the closest point, with
// the sign of (p - q) . N, N the angle-weighted pseudo-normal of the feature q lies on (the face normal, the
// sum of an edge's two face normals, the angle-weighted sum at a corner; Baerentzen & Aanaes, IEEE TVCG 11,
// 2005), which gives the right sign at edges and corners too. Used to lay wall particles along a mesh.
#pragma once

#include <cstdint>
#include <vector>

#include "grit/mesh/triangle_bins.hpp"
#include "grit/mesh/triangle_mesh.hpp"

namespace grit::mesh {

class SignedDistance {
  public:
    /// For a `closed` mesh (watertight, consistently oriented) the sign is outside/inside: a mesh whose
    /// normals point inwards (negative enclosed volume) has its sign flipped. For an open mesh it is the
    /// side its facet normals point to (> 0) or away from (< 0).
    explicit SignedDistance(const TriangleMesh& mesh, bool closed = true);

    struct Query {
        double distance;  ///< signed [m]; +infinity from query_near when no triangle is within the reach
        bool on_rim;      ///< the closest point is on an open edge or one of its corners (beyond the rim)
        Vec3 normal;      ///< unit pseudo-normal of the closest feature, towards > 0 (zero where it cancels)
    };
    Query query(const Vec3& p) const;
    /// Restricts query_near and face_behind to the triangles within `reach` (binned, in cells of
    /// cell_factor x reach): far cheaper for many points near a large mesh.
    void bin(double reach, double cell_factor = 2.0);
    /// As query, over the triangles within the binned reach of p only (bin() first).
    Query query_near(const Vec3& p) const;
    /// With n the facets' unit normals times `sign`: the n of the nearest triangle within the binned reach
    /// that p lies behind (the side n points away from) and projects into (its face region), if any:
    /// where a sheet folds back on itself (a splitter edge) a point in front of one part of the sheet
    /// can lie just behind another; zero if none.
    Vec3 face_behind(const Vec3& p, double sign = 1.0) const;
    /// Signed distance of p [m]: > 0 outside the closed surface (in front of an open one), < 0 inside.
    double operator()(const Vec3& p) const { return query(p).distance; }
    /// The volume the mesh encloses [m^3] (positive whatever its orientation).
    double volume() const noexcept { return volume_; }

  private:
    /// Brings triangle t into the search for the point closest to p (best: squared distance so far).
    void consider(std::size_t t, const Vec3& p, double& best, Vec3& closest, Vec3& normal, bool& rim) const;
    Query answer(const Vec3& p, double best, const Vec3& closest, const Vec3& normal, bool rim) const;

    const TriangleMesh& mesh_;
    std::vector<Vec3> face_normal_, edge_normal_, vertex_normal_;
    std::vector<Vec3> box_low_, box_high_;  // per triangle
    std::vector<std::uint8_t> rim_vertex_;  // corners of open edges
    double orientation_ = 1.0, volume_ = 0.0;
    TriangleBins bins_;
};

}  // namespace grit::mesh
