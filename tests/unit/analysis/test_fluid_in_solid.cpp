// Fluid enclosed by a solid: counted when a solid closes every side of it, not when it rests on a surface
// or at the bottom of a pit open to the jet.
#include <gtest/gtest.h>

#include <array>
#include <vector>

#include "grit/analysis/fluid_in_solid.hpp"

namespace {

using grit::Index;
using grit::Phase;
using grit::analysis::count_fluid_in_solids;

constexpr double dx = 1e-4;
constexpr double reach = 2.5 * dx;  // the cubic spline's support at h = 1.25 dx

/// A 2D block of solid particles on a dx lattice, x in [0, 10) dx, y in [-10, 0) dx, less the lattice
/// points in `holes`, with fluid particles at `fluid`.
grit::particles::SphParticles<2> block(const std::vector<std::array<int, 2>>& holes,
                                       const std::vector<std::array<double, 2>>& fluid) {
    grit::particles::SphParticles<2> ps;
    for (int i = 0; i < 10; ++i)
        for (int j = -10; j < 0; ++j) {
            bool hole = false;
            for (const auto& h : holes) hole |= h[0] == i && h[1] == j;
            if (hole) continue;
            const Index a = ps.append(1);
            ps.position()[a] = {{(i + 0.5) * dx, (j + 0.5) * dx}};
            ps.phase()[a] = static_cast<std::int32_t>(Phase::solid);
        }
    for (const auto& f : fluid) {
        const Index a = ps.append(1);
        ps.position()[a] = {{f[0] * dx, f[1] * dx}};
        ps.phase()[a] = static_cast<std::int32_t>(Phase::fluid);
    }
    return ps;
}

}  // namespace

TEST(FluidInSolid, WaterOnTheSurfaceIsNotInside) {
    // A layer of water one spacing above the block, and a particle touching its top.
    EXPECT_EQ(count_fluid_in_solids(block({}, {{2.5, 0.5}, {3.5, 0.5}, {5.0, 0.1}}), reach), 0);
}

TEST(FluidInSolid, WaterWedgedBetweenTwoRowsIsInside) {
    // Half a spacing between the first and second rows (as in the demo at 03c9108), and one in a hole
    // deep in the block: both enclosed. One more on the surface is not.
    const auto ps = block({{5, -6}}, {{4.5, -1.0}, {5.5, -5.5}, {7.5, 0.5}});
    EXPECT_EQ(count_fluid_in_solids(ps, reach), 2);
}

TEST(FluidInSolid, WaterAtTheBottomOfAnOpenPitIsNotInside) {
    // A pit three spacings wide and three deep, open upwards: the water at its bottom has a free side.
    std::vector<std::array<int, 2>> pit;
    for (int i = 4; i <= 6; ++i)
        for (int j = -3; j <= -1; ++j) pit.push_back({i, j});
    EXPECT_EQ(count_fluid_in_solids(block(pit, {{5.5, -2.5}, {5.5, -1.5}, {5.5, -0.5}}), reach), 0);
}

TEST(FluidInSolid, ThreeDimensionsNeedAllSixSides) {
    grit::particles::SphParticles<3> ps;
    for (int i = -3; i <= 3; ++i)
        for (int j = -3; j <= 3; ++j)
            for (int k = -3; k <= 0; ++k) {  // a slab with its top at z = 0
                const Index a = ps.append(1);
                ps.position()[a] = {{i * dx, j * dx, k * dx}};
                ps.phase()[a] = static_cast<std::int32_t>(Phase::solid);
            }
    const Index inside = ps.append(2);
    ps.position()[inside] = {{0.5 * dx, 0.5 * dx, -1.5 * dx}};  // between lattice points, below the top
    ps.position()[inside + 1] = {{0.0, 0.0, 1.0 * dx}};          // on the top face: +z is free
    ps.phase()[inside] = ps.phase()[inside + 1] = static_cast<std::int32_t>(Phase::fluid);
    EXPECT_EQ(count_fluid_in_solids(ps, reach), 1);
}
