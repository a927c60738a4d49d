// mesh::mirror_partners: each triangle's mirror image across x = 0 among a set of triangles, against
// the pairs a symmetric plate is built with.
#include <gtest/gtest.h>

#include <vector>

#include "grit/mesh/mirror_partners.hpp"

namespace {

using grit::mesh::Corners;
using Vec3 = grit::core::Vec<3>;

Corners mirrored(const Corners& t) {  // corners mirrored, the order turned (the normal kept)
    Corners m = {t[0], t[2], t[1]};
    for (auto& c : m) c[0] = -c[0];
    return m;
}

}  // namespace

// A plate of 2 x 3 cells on each side of x = 0, each cell's diagonal the mirror of its twin's; the x < 0
// half listed in another order, and one triangle standing across the plane, symmetric about it.
TEST(MirrorPartners, PairsEachTriangleWithItsMirrorImage) {
    std::vector<Corners> right;
    for (int i = 0; i < 2; ++i)
        for (int j = 0; j < 3; ++j) {
            const double x0 = 1e-3 * i, x1 = x0 + 1e-3, y0 = 1e-3 * j, y1 = y0 + 1e-3;
            right.push_back({Vec3{{x0, y0, 0.0}}, Vec3{{x1, y0, 0.0}}, Vec3{{x1, y1, 0.0}}});
            right.push_back({Vec3{{x0, y0, 0.0}}, Vec3{{x1, y1, 0.0}}, Vec3{{x0, y1, 0.0}}});
        }
    std::vector<Corners> all = right;
    for (std::size_t k = right.size(); k-- > 0;) all.push_back(mirrored(right[k]));
    // Across the plane: an isosceles triangle with its apex on it.
    all.push_back({Vec3{{-1e-3, 5e-3, 0.0}}, Vec3{{1e-3, 5e-3, 0.0}}, Vec3{{0.0, 6e-3, 0.0}}});
    // An STL's single precision: the mirror image off by 1e-9 m.
    all.back()[1][0] += 1e-9;
    const auto partner = grit::mesh::mirror_partners(all, 0, 1e-8);
    ASSERT_EQ(partner.size(), all.size());
    const std::size_t n = right.size();
    for (std::size_t k = 0; k < n; ++k) {
        EXPECT_EQ(partner[k], static_cast<std::int64_t>(2 * n - 1 - k)) << "triangle " << k;
        EXPECT_EQ(partner[2 * n - 1 - k], static_cast<std::int64_t>(k)) << "triangle " << 2 * n - 1 - k;
    }
    EXPECT_EQ(partner.back(), static_cast<std::int64_t>(all.size() - 1));
    // A tolerance below the error finds no partner for it.
    EXPECT_EQ(grit::mesh::mirror_partners(all, 0, 1e-10).back(), -1);
}

// A triangle whose mirror image is missing, or only near (a corner 2 tolerances off), has no partner; the
// right half alone pairs nothing but triangles symmetric about the plane (none here).
TEST(MirrorPartners, MissingOrMovedImagesHaveNoPartner) {
    const Corners t = {Vec3{{1e-3, 0.0, 0.0}}, Vec3{{2e-3, 0.0, 0.0}}, Vec3{{2e-3, 1e-3, 0.0}}};
    Corners moved = mirrored(t);
    moved[2][1] += 2e-8;
    const auto partner = grit::mesh::mirror_partners({t, moved}, 0, 1e-8);
    EXPECT_EQ(partner[0], -1);
    EXPECT_EQ(partner[1], -1);
    EXPECT_EQ(grit::mesh::mirror_partners({t}, 0, 1e-8)[0], -1);
    // Along y instead: the plane y = 0.
    Corners in_y = t;
    for (auto& c : in_y) c[1] = -c[1];
    const auto by_y = grit::mesh::mirror_partners({t, in_y}, 1, 1e-8);
    EXPECT_EQ(by_y[0], 1);
    EXPECT_EQ(by_y[1], 0);
}
