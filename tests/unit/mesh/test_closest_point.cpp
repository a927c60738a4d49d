// Closest point on a triangle: the face, each edge and each corner region.
#include <gtest/gtest.h>

#include "grit/mesh/closest_point.hpp"

using namespace grit::mesh;
using V = grit::core::Vec<3>;

TEST(ClosestPoint, RegionsOfTheUnitTriangle) {
    const V a{{0, 0, 0}}, b{{1, 0, 0}}, c{{0, 1, 0}};
    struct Case {
        V p;
        Feature feature;
        int index;
        V point;
    };
    const Case cases[] = {
        {V{{0.2, 0.3, 0.7}}, Feature::face, 0, V{{0.2, 0.3, 0.0}}},
        {V{{0.5, 0.5, -1.0}}, Feature::face, 0, V{{0.5, 0.5, 0.0}}},  // right above edge bc: a face point
        {V{{0.5, -0.4, 0.1}}, Feature::edge, 0, V{{0.5, 0.0, 0.0}}},
        {V{{1.0, 1.0, 0.3}}, Feature::edge, 1, V{{0.5, 0.5, 0.0}}},
        {V{{-0.3, 0.6, 0.0}}, Feature::edge, 2, V{{0.0, 0.6, 0.0}}},
        {V{{-1.0, -1.0, 0.5}}, Feature::vertex, 0, a},
        {V{{2.0, -0.1, 0.0}}, Feature::vertex, 1, b},
        {V{{-0.1, 3.0, -2.0}}, Feature::vertex, 2, c},
    };
    for (const Case& k : cases) {
        const ClosestPoint q = closest_point_on_triangle(k.p, a, b, c);
        EXPECT_EQ(q.feature, k.feature);
        EXPECT_EQ(q.index, k.index);
        for (int d = 0; d < 3; ++d)
            EXPECT_NEAR(q.point[d], k.point[d], 1e-14);
    }
}
