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
