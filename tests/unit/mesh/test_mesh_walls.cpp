// Grain-mesh contact: one contact on a flat mesh of many triangles (also right above a shared edge), one
// at a convex edge, one per wall in a concave corner, the history carried across triangles, the same
// bounce as a plane wall, and a moving mesh's surface velocity.
#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "grit/dem/dem_system.hpp"
#include "unit/mesh/test_support.hpp"

using namespace grit::dem;
using namespace grit::mesh::testing;
using grit::mesh::TriangleMesh;

namespace {

const GrainMaterial quartz{"sand", 2650.0, 70e9, 0.17, 0.4, 0.6, 0.0};
/// Soft grains (LIGGGHTS' chute tutorial modulus) for the runs: long contacts, few steps.
const GrainMaterial soft{"soft", 2500.0, 5e6, 0.45, 0.5, 0.3, 0.0};

DemSystem<3> system_with(const std::vector<grit::mesh::Facet>& facets, double gravity = -9.81,
                         const GrainMaterial& material = quartz) {
    DemParameters<3> p;
    p.contact_law = "hertz";
    p.gravity = V{{0.0, 0.0, gravity}};
    DemSystem<3> s(p, {material});
    MeshWall w;
    w.name = "wall";
    w.mesh = TriangleMesh::from_facets(facets, {}, "test.stl", false);
    s.add_mesh(std::move(w));
    return s;
}

}  // namespace

// A grain pressed onto a flat plate of 2 x 4 x 4 triangles feels one contact wherever it sits: inside a
// triangle, right above the diagonal two triangles share, above a grid edge, above a grid corner.
TEST(MeshWalls, OneContactOnAFlatMeshWherever) {
    const double r = 0.01;
    for (const V at :
         {V{{0.13, 0.31, 0.0}}, V{{0.25, 0.25, 0.0}}, V{{0.5, 0.2, 0.0}}, V{{0.5, 0.5, 0.0}}, V{{0.0, 0.0, 0.0}}}) {
        auto s = system_with(plate_facets(1.0, 4), 0.0);
        s.add_grain(at + V{{0.0, 0.0, r - 1e-5}}, r, 0);
        s.compute_forces(0.0, 0.0);
        EXPECT_EQ(s.meshes()->contact_count(0), 1) << at[0] << " " << at[1];
        const V f = s.grains().force()[0];
        EXPECT_GT(f[2], 0.0);
        EXPECT_NEAR(f[0], 0.0, 1e-12 * f[2]);
        EXPECT_NEAR(f[1], 0.0, 1e-12 * f[2]);
    }
}

// At a convex edge of a box the grain touches the edge once; in a concave corner (inside a box) each
// of the three walls once.
TEST(MeshWalls, ConvexEdgeOnceConcaveCornerThrice) {
    const double r = 0.01;
    {
        auto s = system_with(box_facets(V{{0, 0, 0}}, V{{1, 1, 1}}), 0.0);
        const double d = (r - 1e-5) / std::sqrt(2.0);
        s.add_grain(V{{0.5, 1.0 + d, 1.0 + d}}, r, 0);  // beyond the edge y = z = 1
        s.compute_forces(0.0, 0.0);
        ASSERT_EQ(s.meshes()->contact_count(0), 1);
        const V f = s.grains().force()[0];
        EXPECT_NEAR(f[1], f[2], 1e-9 * f[2]);  // along the diagonal away from the edge
        EXPECT_GT(f[2], 0.0);
    }
    {
        auto s = system_with(box_facets(V{{0, 0, 0}}, V{{1, 1, 1}}), 0.0);
        const double d = r - 1e-5;
        s.add_grain(V{{d, d, d}}, r, 0);  // in the corner at the origin, inside
        s.compute_forces(0.0, 0.0);
        EXPECT_EQ(s.meshes()->contact_count(0), 3);
        const V f = s.grains().force()[0];
        EXPECT_GT(f[0], 0.0);
        EXPECT_NEAR(f[0], f[1], 1e-9 * f[0]);
        EXPECT_NEAR(f[1], f[2], 1e-9 * f[0]);
    }
}

// A grain dropped on a mesh plate bounces as on the plane wall z = 0: same trajectory to round-off.
TEST(MeshWalls, BouncesAsOnAPlaneWall) {
    const double r = 0.005;
    auto mesh = system_with(plate_facets(0.1, 3), -9.81, soft);
    DemParameters<3> p;
    p.contact_law = "hertz";
    p.gravity = V{{0.0, 0.0, -9.81}};
    DemSystem<3> plane(p, {soft});
    plane.add_wall({V{{0, 0, 0}}, V{{0, 0, 1}}, 0});
    for (auto* s : {&mesh, &plane})
        s->add_grain(V{{0.013, -0.021, 0.03}}, r, 0, V{{0.3, 0.1, 0.0}});
    const double dt = plane.stable_time_step(1.0);
    double lowest = 1.0;
    const int steps = static_cast<int>(0.3 / dt);
    for (int n = 0; n < steps; ++n) {
        mesh.step(dt, n * dt);
        plane.step(dt, n * dt);
        lowest = std::min(lowest, plane.grains().position()[0][2]);
        for (int k = 0; k < 3; ++k)
            ASSERT_NEAR(mesh.grains().position()[0][k], plane.grains().position()[0][k], 1e-12) << n;
    }
    EXPECT_LT(lowest, r);  // it did bounce (and slid on the plate, across its triangles)
}

// A grain sliding over many triangles keeps one contact whose history moves from triangle to triangle:
// no contact after the first is fresh.
TEST(MeshWalls, SlidingAcrossTrianglesIsOneContact) {
    const double r = 0.005;
    auto s = system_with(plate_facets(0.1, 10), -9.81, soft);
    s.add_grain(V{{-0.05, -0.031, r - 2e-6}}, r, 0, V{{2.0, 0.7, 0.0}});
    const double dt = s.stable_time_step(2.0);
    int fresh = 0, steps_in_contact = 0;
    std::set<std::int32_t> triangles;
    const int steps = static_cast<int>(0.04 / dt);
    for (int n = 0; n < steps; ++n) {
        s.step(dt, n * dt);
        const auto* walls = s.meshes();
        for (int c = 0; c < walls->contact_count(0); ++c) {
            fresh += walls->contacts_of(0)[c].fresh;
            triangles.insert(walls->contacts_of(0)[c].triangle);
        }
        steps_in_contact += walls->contact_count(0) > 0;
    }
    EXPECT_EQ(steps_in_contact, steps);
    EXPECT_GT(triangles.size(), 5u);
    EXPECT_LE(fresh, 1);  // the first contact only (it may start resting, then not even that)
}

// A mesh turning about z at w: its corners move on circles and its surface moves at w x (x - c).
TEST(MeshWalls, RotatingMeshPlacement) {
    auto s = system_with(plate_facets(1.0, 1), 0.0);
    MeshWalls walls;
    GrainSet<3> grains;
    MeshWall w;
    w.mesh = TriangleMesh::from_facets(plate_facets(1.0, 1), {}, "plate.stl", false);
    w.motion.angular_velocity = V{{0.0, 0.0, 2.0}};
    w.motion.centre = V{{0.0, 0.0, 0.0}};
    w.motion.velocity = V{{0.0, 0.0, 0.5}};
    walls.add(std::move(w), grains);
    const double t = 0.3;
    walls.place(t);
    const V corner = walls.corners()[0][0];  // (-1, -1, 0) at t = 0
    const double angle = 2.0 * t;
    EXPECT_NEAR(corner[0], -std::cos(angle) + std::sin(angle), 1e-12);
    EXPECT_NEAR(corner[1], -std::sin(angle) - std::cos(angle), 1e-12);
    EXPECT_NEAR(corner[2], 0.5 * t, 1e-12);
    const V u = walls.surface_velocity(0, V{{1.0, 0.0, 0.15}});
    EXPECT_NEAR(u[0], 0.0, 1e-12);
    EXPECT_NEAR(u[1], 2.0, 1e-12);
    EXPECT_NEAR(u[2], 0.5, 1e-12);
}
