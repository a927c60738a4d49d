// Triangle-mesh walls for grains (3D): grain-triangle contact on faces, edges and corners with the
// system's contact law and a tangential history per contact, triangles binned in a uniform grid
// whatever their size, and prescribed rigid motion (translation and rotation) of each mesh.
//
// A grain near a mesh sees a face contact from each triangle its centre projects into, an edge contact
// from a sharp edge (not inside a flat region) when it projects into no triangle beside that edge, and a
// corner contact when it lies beyond every face and edge at the corner. So a grain on a flat mesh of many
// triangles feels one contact, a grain in a concave corner one per wall, and one at a convex edge one.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "grit/core/types.hpp"
#include "grit/core/vec.hpp"
#include "grit/dem/contact_forces.hpp"
#include "grit/dem/grain_loop.hpp"
#include "grit/dem/grain_set.hpp"
#include "grit/mesh/closest_point.hpp"
#include "grit/mesh/triangle_bins.hpp"
#include "grit/mesh/triangle_mesh.hpp"

namespace grit::dem {

using Vec3 = core::Vec<3>;

/// Prescribed rigid motion: the mesh turns at `angular_velocity` about the axis through `centre`
/// (at t = 0) while that centre moves at `velocity`.
struct MeshMotion {
    Vec3 velocity = Vec3::zero();          ///< [m/s]
    Vec3 angular_velocity = Vec3::zero();  ///< [rad/s]
    Vec3 centre = Vec3::zero();            ///< [m]
    bool moving() const { return core::norm2(velocity) > 0.0 || core::norm2(angular_velocity) > 0.0; }
};

/// A mesh wall: its triangles as placed at t = 0, its contact material (index into the system's grain
/// materials) and its motion.
struct MeshWall {
    std::string name;
    mesh::TriangleMesh mesh;
    std::int32_t material = 0;
    MeshMotion motion;
};

/// One grain-triangle contact of the step.
struct MeshContact {
    std::int32_t triangle = -1;             ///< over all meshes (MeshWalls::locate gives the mesh)
    bool fresh = false;                     ///< began this step (no contact with this triangle or one beside it before)
    Vec3 normal = Vec3::zero();             ///< unit, from the grain's centre to the contact point
    Vec3 relative_velocity = Vec3::zero();  ///< grain minus wall at the contact point [m/s]
    double normal_force = 0.0;              ///< [N]
    double force = 0.0;                     ///< |F| of the contact (normal and tangential) [N]
};

class MeshWalls {
  public:
    /// Contacts a grain may hold with mesh triangles at once (deepest first beyond that).
    static constexpr int slots = 6;

    /// Adds a wall; the first one registers the grains' contact-slot fields (`mesh_contact_<k>`: the
    /// triangle, -1 for none, and `mesh_history_<k>`: the tangential spring), saved in checkpoints.
    void add(MeshWall wall, GrainSet<3>& grains);

    std::size_t size() const noexcept { return walls_.size(); }
    const MeshWall& wall(std::size_t w) const noexcept { return walls_[w]; }
    std::size_t triangle_count() const noexcept { return corners_.size(); }
    /// The mesh of a triangle (over all meshes) and its index in that mesh.
    std::pair<std::size_t, std::size_t> locate(std::int32_t triangle) const;
    /// The corners of every triangle at the last place() (over all meshes).
    const std::vector<std::array<Vec3, 3>>& corners() const noexcept { return corners_; }

    /// Moves the meshes to time t (moving meshes only; the first call places all).
    void place(double time);
    /// Velocity of mesh w's surface at point x, at the last place() [m/s].
    Vec3 surface_velocity(std::size_t w, const Vec3& x) const;

    /// The contacts of the grains with the meshes at their current positions: adds each contact's force
    /// to force[i] and its n x F_t to torque[i] (the grain pair pass's convention: GrainCompletion
    /// multiplies torques by the radius), carries the tangential histories (into a triangle beside the
    /// last one, for a grain sliding over a mesh) and records the contacts (contacts_of). dt = 0 leaves
    /// the histories as they are. Gather form: each grain writes its own data only.
    template <class Law>
    void contact_pass(GrainSet<3>& grains, const PairMaterialTable& materials, const Law& law, double dt);

    /// The contacts of grain i at the last contact_pass (its order at that pass).
    const MeshContact* contacts_of(Index i) const noexcept { return &contacts_[static_cast<std::size_t>(i) * slots]; }
    int contact_count(Index i) const noexcept { return counts_[static_cast<std::size_t>(i)]; }

  private:
    struct Candidate {
        std::int32_t triangle;
        mesh::Feature feature;
        std::int64_t feature_id;  // triangle, edge or vertex, numbered over all meshes
        Vec3 point;
        double distance2;
    };
    void rebuild_bins(double reach);
    /// The candidate contacts of a grain at x of radius r, after the face/edge/corner rules.
    void find_contacts(const Vec3& x, double r, std::vector<Candidate>& out) const;

    std::vector<MeshWall> walls_;
    std::vector<std::size_t> triangle_offset_, edge_offset_, vertex_offset_;  // per wall, over all meshes
    std::vector<std::array<Vec3, 3>> corners_;
    std::vector<std::int32_t> triangle_wall_;
    std::vector<Vec3> centre_now_;  // each wall's rotation centre at the last place()
    bool placed_ = false;
    double placed_time_ = 0.0;
    mesh::TriangleBins bins_;  // over the placed triangles, for the largest grain radius
    bool bins_dirty_ = true;
    // Per grain, the contacts of the last pass.
    std::vector<MeshContact> contacts_;
    std::vector<int> counts_;
    std::vector<std::vector<std::int32_t>*> slot_triangle_;
    std::vector<std::vector<Vec3>*> slot_history_;
};

template <class Law>
void MeshWalls::contact_pass(GrainSet<3>& grains, const PairMaterialTable& materials, const Law& law, double dt) {
    const Index n = grains.size();
    contacts_.assign(static_cast<std::size_t>(n) * slots, MeshContact{});
    counts_.assign(static_cast<std::size_t>(n), 0);
    if (n == 0 || walls_.empty()) return;
    const double rmax = max_over_grains(n, 0.0, [&](Index i) { return grains.radius()[i]; });
    if (bins_dirty_ || rmax > bins_.reach()) rebuild_bins(rmax);

    std::array<std::int32_t*, slots> slot_triangle{};
    std::array<Vec3*, slots> slot_history{};
    for (int k = 0; k < slots; ++k) {
        slot_triangle[static_cast<std::size_t>(k)] =
            grains.fields().template get<std::int32_t>("mesh_contact_" + std::to_string(k)).data();
        slot_history[static_cast<std::size_t>(k)] =
            grains.fields().template get<Vec3>("mesh_history_" + std::to_string(k)).data();
    }
    const Vec3* x = std::as_const(grains).position();
    const Vec3* v = std::as_const(grains).velocity();
    const Vec3* w = std::as_const(grains).angular_velocity();
    const double* radius = std::as_const(grains).radius();
    const double* mass = std::as_const(grains).mass();
    const std::int32_t* material = std::as_const(grains).material();
    Vec3* force = grains.force();
    Vec3* torque = grains.torque();
    constexpr double infinite = std::numeric_limits<double>::infinity();

    for_each_grain(n, [&](Index i) {
        thread_local std::vector<Candidate> found;
        find_contacts(x[i], radius[i], found);
        // The previous contacts of the grain, to carry their histories.
        std::array<std::int32_t, slots> old_triangle{};
        std::array<Vec3, slots> old_history{};
        std::array<bool, slots> claimed{};
        for (int k = 0; k < slots; ++k) {
            old_triangle[static_cast<std::size_t>(k)] = slot_triangle[static_cast<std::size_t>(k)][i];
            old_history[static_cast<std::size_t>(k)] = slot_history[static_cast<std::size_t>(k)][i];
        }
        const int count = std::min<int>(slots, static_cast<int>(found.size()));
        MeshContact* out = &contacts_[static_cast<std::size_t>(i) * slots];
        Vec3 f = Vec3::zero(), t = Vec3::zero();
        for (int c = 0; c < count; ++c) {
            const Candidate& hit = found[static_cast<std::size_t>(c)];
            // History: the same triangle's, else that of a triangle beside it no other contact took.
            int from = -1;
            for (int k = 0; k < slots && from < 0; ++k)
                if (old_triangle[static_cast<std::size_t>(k)] == hit.triangle) from = k;
            for (int k = 0; k < slots && from < 0; ++k) {
                const std::int32_t o = old_triangle[static_cast<std::size_t>(k)];
                if (o < 0 || claimed[static_cast<std::size_t>(k)] ||
                    triangle_wall_[static_cast<std::size_t>(o)] !=
                        triangle_wall_[static_cast<std::size_t>(hit.triangle)])
                    continue;
                const auto [wall, a] = locate(o);
                if (walls_[wall].mesh.adjacent(a, locate(hit.triangle).second)) from = k;
            }
            Vec3 history = Vec3::zero();
            if (from >= 0) {
                claimed[static_cast<std::size_t>(from)] = true;
                history = old_history[static_cast<std::size_t>(from)];
            }
            const double distance = std::sqrt(hit.distance2);
            const std::size_t wall = static_cast<std::size_t>(triangle_wall_[static_cast<std::size_t>(hit.triangle)]);
            // n from the grain (a) to the wall (b); a centre on the triangle takes the face normal.
            const Vec3 normal = distance > 0.0 ? (hit.point - x[i]) * (1.0 / distance)
                                               : -walls_[wall].mesh.normal(locate(hit.triangle).second);
            const Vec3 relative = v[i] + core::cross(w[i], normal * radius[i]) - surface_velocity(wall, hit.point);
            const ContactKinematics kinematics{radius[i] - distance, 0.0, radius[i], infinite, mass[i], infinite};
            const ContactResponse<3> response = contact_response<3>(
                law, materials.at(material[i], walls_[wall].material), normal, relative, kinematics, history, dt, 1.0);
            f += response.force;
            t += response.lever_moment;
            slot_triangle[static_cast<std::size_t>(c)][i] = hit.triangle;
            slot_history[static_cast<std::size_t>(c)][i] = response.history;
            const double fn = -core::dot(response.force, normal);
            out[c] = {hit.triangle, from < 0,
                      normal,       v[i] - surface_velocity(wall, hit.point),
                      fn,           core::norm(response.force)};
        }
        for (int k = count; k < slots; ++k) {
            slot_triangle[static_cast<std::size_t>(k)][i] = -1;
            slot_history[static_cast<std::size_t>(k)][i] = Vec3::zero();
        }
        counts_[static_cast<std::size_t>(i)] = count;
        force[i] += f;
        torque[i] += t;
    });
}

}  // namespace grit::dem
