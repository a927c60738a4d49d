// Signed distance to a closed mesh: sign and size inside, outside, beyond edges and corners, and for a
// mesh whose normals point inwards.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "grit/mesh/signed_distance.hpp"
#include "unit/mesh/test_support.hpp"

using namespace grit::mesh;
using namespace grit::mesh::testing;

TEST(SignedDistance, UnitBoxInsideOutsideEdgesAndCorners) {
    const auto m = TriangleMesh::from_facets(box_facets(V{{0, 0, 0}}, V{{1, 1, 1}}), {}, "box.stl", true);
    const SignedDistance d(m);
    EXPECT_NEAR(d.volume(), 1.0, 1e-12);
    EXPECT_NEAR(d(V{{0.5, 0.5, 0.5}}), -0.5, 1e-12);
    EXPECT_NEAR(d(V{{0.5, 0.2, 0.9}}), -0.1, 1e-12);
    EXPECT_NEAR(d(V{{0.5, 0.5, 1.3}}), 0.3, 1e-12);
    // Beyond an edge and beyond a corner, where a face normal alone could give either sign.
    EXPECT_NEAR(d(V{{1.3, 0.5, 1.4}}), 0.5, 1e-12);
    EXPECT_NEAR(d(V{{-0.1, -0.2, -0.2}}), 0.3, 1e-12);
    // Points on the diagonal planes inside, close to an edge.
    EXPECT_NEAR(d(V{{0.99, 0.5, 0.99}}), -0.01, 1e-12);
    // A lattice: the sign is the point's side of the box everywhere.
    for (double x = -0.25; x < 1.3; x += 0.1)
        for (double y = -0.25; y < 1.3; y += 0.1)
            for (double z = -0.25; z < 1.3; z += 0.1) {
                const bool inside = x > 0 && x < 1 && y > 0 && y < 1 && z > 0 && z < 1;
                EXPECT_EQ(d(V{{x, y, z}}) < 0.0, inside) << x << " " << y << " " << z;
            }
}

TEST(SignedDistance, InwardNormalsAreFlipped) {
    auto facets = box_facets(V{{0, 0, 0}}, V{{2, 1, 1}});
    for (auto& f : facets)
        std::swap(f[1], f[2]);
    const auto m = TriangleMesh::from_facets(facets, {}, "inverted.stl", true);
    const SignedDistance d(m);
    EXPECT_NEAR(d.volume(), 2.0, 1e-12);
    EXPECT_LT(d(V{{1.0, 0.5, 0.5}}), 0.0);
    EXPECT_GT(d(V{{3.0, 0.5, 0.5}}), 0.0);
}

TEST(SignedDistance, BinnedQueryAgreesWithTheFullOneWithinReachAndIsEmptyBeyond) {
    const auto m = TriangleMesh::from_facets(box_facets(V{{0, 0, 0}}, V{{1, 1, 1}}), {}, "box.stl", true);
    SignedDistance d(m);
    d.bin(0.3);
    for (double x = -0.45; x < 1.5; x += 0.1)
        for (double y = -0.45; y < 1.5; y += 0.1)
            for (double z = -0.45; z < 1.5; z += 0.1) {
                const V p{{x, y, z}};
                const auto full = d.query(p), near = d.query_near(p);
                if (std::abs(full.distance) < 0.3) {
                    EXPECT_EQ(near.distance, full.distance) << x << " " << y << " " << z;
                    EXPECT_NEAR(grit::core::norm(near.normal), 1.0, 1e-12);
                } else {
                    EXPECT_TRUE(std::isinf(near.distance)) << x << " " << y << " " << z;
                }
            }
    // The unit pseudo-normal: a face's normal, the bisector at an edge.
    const auto face = d.query_near(V{{0.5, 0.5, 1.1}});
    EXPECT_NEAR(face.normal[2], 1.0, 1e-12);
    const auto edge = d.query_near(V{{1.1, 0.5, 1.1}});
    EXPECT_NEAR(edge.normal[0], std::sqrt(0.5), 1e-12);
    EXPECT_NEAR(edge.normal[2], std::sqrt(0.5), 1e-12);
}

TEST(SignedDistance, FaceBehindFindsTheFarSideOfASheetFoldedBack) {
    // A sheet folded into a thin wedge along the x axis: two faces meeting at the ridge z = 1, their
    // feet at y = -0.05 and +0.05 (z = 0), normals outwards (-y and +y). A point just right of the
    // right face is in front of the sheet, yet behind the left face within the reach: the far side's wall.
    const V a{{0, -0.05, 0}}, b{{1, -0.05, 0}}, r0{{0, 0, 1}}, r1{{1, 0, 1}}, c{{0, 0.05, 0}}, e{{1, 0.05, 0}};
    std::vector<Facet> f = {{a, b, r1}, {a, r1, r0}, {c, r1, e}, {c, r0, r1}};
    const auto m = TriangleMesh::from_facets(f, {}, "wedge.stl", false);
    SignedDistance d(m, false);
    ASSERT_LT(m.normal(0)[1], 0.0);
    ASSERT_GT(m.normal(2)[1], 0.0);
    d.bin(0.2);
    const V right{{0.5, 0.08, 0.6}};  // right of the right face (y = 0.02 at z = 0.6)
    EXPECT_GT(d.query(right).distance, 0.0);
    const V n = d.face_behind(right);
    EXPECT_LT(n[1], -0.99);  // the left face's normal
    // Far from the left face: nothing behind within the reach.
    EXPECT_EQ(grit::core::norm2(d.face_behind(V{{0.5, 0.4, 0.6}})), 0.0);
    // With the sign flipped, "behind" is in front: the right face, which the point is in front of.
    EXPECT_GT(d.face_behind(right, -1.0)[1], -1.0);
    EXPECT_LT(d.face_behind(right, -1.0)[1], -0.99);
}
