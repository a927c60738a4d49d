// Crater profile, depth C_d and width C_w of a 2D solid surface on a lattice, with pits of known size
// and with a column whose top particles have moved into the neighbour bin (the spike of 2026-11-27: a
// bin that lost its column's top reported the top of a particle four rows down, C_d 0.41 mm for 0.12).
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <vector>

#include "grit/analysis/crater.hpp"

namespace {

using grit::Index;
using grit::Phase;
using grit::analysis::analyse_crater;

constexpr double dx = 1e-4;

struct Site {
    int column, row;       // lattice indices: x = (column + 0.5) dx, y = (row + 0.5) dx, row < 0
    double shift = 0.0;    // moved along x by this many spacings
};

/// A block 40 columns wide and 10 rows deep below y = 0, less the sites in `holes`, with the sites in
/// `moved` displaced along x.
grit::particles::SphParticles<2> block(const std::vector<std::array<int, 2>>& holes, const std::vector<Site>& moved = {}) {
    grit::particles::SphParticles<2> ps;
    for (int i = 0; i < 40; ++i)
        for (int j = -10; j < 0; ++j) {
            bool hole = false;
            for (const auto& h : holes) hole |= h[0] == i && h[1] == j;
            if (hole) continue;
            double shift = 0.0;
            for (const auto& m : moved)
                if (m.column == i && m.row == j) shift = m.shift;
            const Index a = ps.append(1);
            ps.position()[a] = {{(i + 0.5 + shift) * dx, (j + 0.5) * dx}};
            ps.phase()[a] = static_cast<std::int32_t>(Phase::solid);
        }
    return ps;
}

std::vector<std::array<int, 2>> pit(int first_column, int columns, int rows) {
    std::vector<std::array<int, 2>> holes;
    for (int i = first_column; i < first_column + columns; ++i)
        for (int j = -rows; j < 0; ++j) holes.push_back({i, j});
    return holes;
}

const grit::analysis::CraterRegion region{0.0, 0.0, 40 * dx};

}  // namespace

TEST(Crater, FlatSurfaceHasNoCrater) {
    const auto c = analyse_crater(block({}), region, dx);
    ASSERT_EQ(c.surface.size(), 40u);
    for (const double s : c.surface) EXPECT_NEAR(s, 0.0, 1e-15);
    EXPECT_NEAR(c.depth, 0.0, 1e-15);
    EXPECT_EQ(c.width, 0.0);
}

TEST(Crater, RectangularPitGivesItsDepthAndWidth) {
    // Six columns, three rows deep. C_w is where the profile, linear between bin centres, crosses
    // y0 - dx/2: 2.5/3 of a bin outside each edge bin, so 5 + 2 (2.5/3) = 6.667 spacings.
    const auto c = analyse_crater(block(pit(17, 6, 3)), region, dx);
    EXPECT_NEAR(c.depth, 3.0 * dx, 1e-12);
    EXPECT_NEAR(c.width, (5.0 + 5.0 / 3.0) * dx, 1e-12);
}

// The section's area and the shape factor area / (C_d C_w) of pits whose shape is known.
TEST(Crater, BoxPitHasItsAreaAndAShapeFactorNearOne) {
    // Six columns, three rows deep: 18 cells. C_w = 6.667 spacings (above): 18 / (3 x 6.667) = 0.9.
    const auto c = analyse_crater(block(pit(17, 6, 3)), region, dx);
    EXPECT_NEAR(c.area, 18.0 * dx * dx, 1e-18);
    EXPECT_NEAR(c.shape_factor, 18.0 / (3.0 * (5.0 + 5.0 / 3.0)), 1e-12);
}

TEST(Crater, VPitHasAShapeFactorNearAHalf) {
    // A staircase V: the column k from the axis is eroded n - |k| rows deep (n = 8). Its area is n^2
    // cells, C_d n spacings, C_w (2n - 1) spacings (the profile crosses y0 - dx/2 halfway between the
    // last one-row column and the intact one): n / (2n - 1) = 0.533, a triangle's 0.5 as n grows.
    constexpr int n = 8;
    std::vector<std::array<int, 2>> holes;
    for (int k = -(n - 1); k <= n - 1; ++k)
        for (int j = -(n - std::abs(k)); j < 0; ++j) holes.push_back({20 + k, j});
    const auto c = analyse_crater(block(holes), region, dx);
    EXPECT_NEAR(c.depth, n * dx, 1e-12);
    EXPECT_NEAR(c.width, (2 * n - 1) * dx, 1e-12);
    EXPECT_NEAR(c.area, n * n * dx * dx, 1e-18);
    EXPECT_NEAR(c.shape_factor, n / (2.0 * n - 1.0), 1e-12);
    EXPECT_LT(c.shape_factor, 0.55);
}

TEST(Crater, SemicircularPitHasAShapeFactorNearAQuarterPi) {
    // The lattice sites within a radius of 9 spacings of the surface point above column 20's left edge
    // (a semicircle of area pi R^2 / 2 on the lattice): the shape factor is pi / 4 = 0.785 to within the
    // staircase's error, well apart from the V's 0.5 and the box's 0.9 above.
    constexpr double radius = 9.0;
    std::vector<std::array<int, 2>> holes;
    for (int i = 0; i < 40; ++i)
        for (int j = -10; j < 0; ++j)
            if (std::hypot(i + 0.5 - 20.0, j + 0.5) < radius) holes.push_back({i, j});
    const auto c = analyse_crater(block(holes), region, dx);
    EXPECT_NEAR(c.area, static_cast<double>(holes.size()) * dx * dx, 1e-18);
    EXPECT_NEAR(c.shape_factor, std::acos(-1.0) / 4.0, 0.05);
}

TEST(Crater, PitOneColumnWideIsResolved) {
    // Bins centred on the columns: the neighbour columns are a spacing from the pit bin's centre,
    // outside its widened edges (3/4 of a spacing).
    const auto c = analyse_crater(block(pit(20, 1, 2)), region, dx);
    EXPECT_NEAR(c.depth, 2.0 * dx, 1e-12);
    EXPECT_GT(c.width, 1.0 * dx);
}

TEST(Crater, PitTwoColumnsWideIsResolved) {
    const auto c = analyse_crater(block(pit(20, 2, 2)), region, dx);
    EXPECT_NEAR(c.depth, 2.0 * dx, 1e-12);
    EXPECT_GT(c.width, 2.0 * dx);
}

TEST(Crater, ColumnSlippingIntoTheNextBinIsNoPit) {
    // Column 20's top four particles moved 0.55 spacings left, into bin 19: counted in their own bin
    // only, bin 20's highest particle would be the fifth row's, 4 spacings down. The surface itself is
    // flat, and a quarter spacing's margin keeps it so.
    std::vector<Site> moved;
    for (int j = -4; j < 0; ++j) moved.push_back({20, j, -0.55});
    const auto c = analyse_crater(block({}, moved), region, dx);
    EXPECT_NEAR(c.depth, 0.0, 1e-15);
    EXPECT_EQ(c.width, 0.0);
}

TEST(Crater, BinWithNoSolidIsSkipped) {
    // Column 5 eroded through: its bin has no surface (NaN) and is not a depth; the rest is flat.
    const auto c = analyse_crater(block(pit(5, 1, 10)), region, dx);
    EXPECT_TRUE(std::isnan(c.surface[5]));
    EXPECT_NEAR(c.depth, 0.0, 1e-15);
}

// A symmetry plane at x = 0: the half block from x = 0 with a pit at its left edge (the plane), profiled
// with `mirror`, is the whole block's profile of a pit centred on x = 0; images are left out.
TEST(Crater, MirroredHalfIsTheWholeCrater) {
    const auto half = block(pit(0, 3, 4));  // x from 0 to 40 dx: a pit 6 columns wide across the plane
    auto with_images = half;
    const Index n = with_images.size();
    const Index first = with_images.append_images(3);  // images of some pit-edge and surface particles
    for (Index k = 0; k < 3; ++k) {
        with_images.fields().mirror_copy(k, first + k, 0);
        with_images.id()[first + k] = grit::particles::SphParticles<2>::image_id(with_images.id()[k]);
    }
    ASSERT_EQ(with_images.image_count(), 3);
    ASSERT_EQ(with_images.size(), n + 3);
    grit::analysis::CraterRegion mirrored{0.0, -40 * dx, 40 * dx, true};
    const grit::particles::SphParticles<2>* sets[] = {&half, &with_images};
    for (const auto* ps : sets) {
        const auto c = analyse_crater(*ps, mirrored, dx);
        ASSERT_EQ(c.surface.size(), 80u);
        for (std::size_t b = 0; b < 40; ++b) EXPECT_EQ(c.surface[b], c.surface[79 - b]) << b;
        EXPECT_NEAR(c.depth, 4.0 * dx, 1e-12);
        // Six columns four rows deep: the profile crosses y0 - dx/2 at 3.5/4 of a bin outside each edge bin.
        EXPECT_NEAR(c.width, (5.0 + 2.0 * 3.5 / 4.0) * dx, 1e-12);
    }
    // Unmirrored, the half sees half a pit: its edge bin at the region's end.
    const auto c = analyse_crater(half, region, dx);
    EXPECT_LT(c.width, 4.0 * dx);
}

namespace {

/// Piles `rows` rows on top of column `column` (rows > 0), the lattice continued upwards.
void pile(grit::particles::SphParticles<2>& ps, int column, int rows) {
    for (int j = 0; j < rows; ++j) {
        const Index a = ps.append(1);
        ps.position()[a] = {{(column + 0.5) * dx, (j + 0.5) * dx}};
        ps.phase()[a] = static_cast<std::int32_t>(Phase::solid);
    }
}

}  // namespace

// Lips: a pit 6 columns wide, 3 rows deep, with 2 rows piled on columns 13-15 and 24-26. Each lip's top
// is a plateau three bins wide; its crest is the plateau's middle (columns 14 and 25), so the rim width
// is 11 spacings, and the lips stand 2 spacings high.
TEST(Crater, LipsPiledUpEitherSideGiveTheRimWidth) {
    auto ps = block(pit(17, 6, 3));
    for (const int i : {13, 14, 15, 24, 25, 26}) pile(ps, i, 2);
    const auto c = analyse_crater(ps, region, dx);
    EXPECT_NEAR(c.depth, 3.0 * dx, 1e-12);
    EXPECT_NEAR(c.width, (5.0 + 5.0 / 3.0) * dx, 1e-12);
    EXPECT_NEAR(c.rim_width, 11.0 * dx, 1e-12);
    EXPECT_NEAR(c.lip_height, 2.0 * dx, 1e-12);
}

// No lip (a brittle crater, or a dent): the rim width is C_w. A bump farther from the crater's edge
// than half its width is not its lip.
TEST(Crater, WithoutLipsTheRimWidthIsTheWidth) {
    const auto plain = analyse_crater(block(pit(17, 6, 3)), region, dx);
    EXPECT_EQ(plain.rim_width, plain.width);
    EXPECT_EQ(plain.lip_height, 0.0);
    auto bumped = block(pit(17, 6, 3));
    pile(bumped, 30, 2);  // 7.2 spacings beyond the right edge, C_w / 2 = 3.3
    const auto far = analyse_crater(bumped, region, dx);
    EXPECT_EQ(far.rim_width, far.width);
    EXPECT_EQ(far.lip_height, 0.0);
}

// A lip ends where the profile falls a spacing below its crest: a higher bump beyond a trench is not
// the lip. Pit 12 columns wide (14-25, C_w / 2 = 6.3 spacings), lip 2 rows on columns 27-28, a trench
// 2 rows deep at 29, 3 rows on column 30; only the left side (no lip there) and the lip at 27-28 count.
TEST(Crater, LipEndsWhereTheProfileFallsASpacingBelowItsCrest) {
    auto holes = pit(14, 12, 3);
    for (const auto& h : pit(29, 1, 2)) holes.push_back(h);
    auto ps = block(holes);
    pile(ps, 27, 2);
    pile(ps, 28, 2);
    pile(ps, 30, 3);
    const auto c = analyse_crater(ps, region, dx);
    const double left_edge = (14.5 - 2.5 / 3.0) * dx;  // the left crossing, where no lip stands
    EXPECT_NEAR(c.rim_width, 28.0 * dx - left_edge, 1e-12);
    EXPECT_NEAR(c.lip_height, 0.5 * 2.0 * dx, 1e-12);
}

namespace {

/// 3D: a block 40 x 20 columns (x, y) and 10 rows deep below z = 0, less the sites of the box
/// [i0, i0 + ni) x [j0, j0 + nj) `rows` rows deep.
grit::particles::SphParticles<3> block3(int i0, int ni, int j0, int nj, int rows) {
    grit::particles::SphParticles<3> ps;
    for (int i = 0; i < 40; ++i)
        for (int j = 0; j < 20; ++j)
            for (int k = -10; k < 0; ++k) {
                if (i >= i0 && i < i0 + ni && j >= j0 && j < j0 + nj && k >= -rows) continue;
                const Index a = ps.append(1);
                ps.position()[a] = {{(i + 0.5) * dx, (j + 0.5) * dx, (k + 0.5) * dx}};
                ps.phase()[a] = static_cast<std::int32_t>(Phase::solid);
            }
    return ps;
}

const grit::analysis::CraterRegion region3{0.0, 0.0, 40 * dx, false, 0.0, 20 * dx};

}  // namespace

TEST(Crater3D, FlatSurfaceHasNoCrater) {
    const auto c = analyse_crater(block3(0, 0, 0, 0, 0), region3, dx);
    ASSERT_EQ(c.x.size(), 40u);
    ASSERT_EQ(c.y.size(), 20u);
    ASSERT_EQ(c.surface.size(), 800u);
    for (const double s : c.surface) EXPECT_NEAR(s, 0.0, 1e-15);
    EXPECT_NEAR(c.depth, 0.0, 1e-15);
    EXPECT_EQ(c.width, 0.0);
    EXPECT_EQ(c.length, 0.0);
}

// A kerf 12 columns long (x) and 6 wide (y), 3 rows deep: across the cut the 2D pit of six columns
// (5 + 2 (2.5/3) spacings at z0 - dx/2), along it 11 + 2 (2.5/3) spacings.
TEST(Crater3D, KerfGivesItsDepthWidthAndLength) {
    const auto c = analyse_crater(block3(10, 12, 7, 6, 3), region3, dx);
    EXPECT_NEAR(c.depth, 3.0 * dx, 1e-12);
    EXPECT_NEAR(c.width, (5.0 + 5.0 / 3.0) * dx, 1e-12);
    EXPECT_NEAR(c.length, (11.0 + 5.0 / 3.0) * dx, 1e-12);
    EXPECT_EQ(c.rim_width, c.width);  // no lips
    EXPECT_EQ(c.lip_height, 0.0);
    EXPECT_NEAR(c.area, 18.0 * dx * dx, 1e-18);  // the section across the cut: 6 columns, 3 rows
    EXPECT_NEAR(c.shape_factor, 18.0 / (3.0 * (5.0 + 5.0 / 3.0)), 1e-12);
    // The map: the cell at (x[15], y[9]) is in the kerf, (x[5], y[9]) and (x[15], y[2]) are not.
    EXPECT_NEAR(c.surface[9 * 40 + 15], -3.0 * dx, 1e-12);
    EXPECT_NEAR(c.surface[9 * 40 + 5], 0.0, 1e-15);
    EXPECT_NEAR(c.surface[2 * 40 + 15], 0.0, 1e-15);
}

// The same pit turned round (long across y): width and length swap, the depth stays.
TEST(Crater3D, WidthIsAcrossTheTraverseAndLengthAlongIt) {
    const auto c = analyse_crater(block3(17, 6, 2, 12, 2), region3, dx);
    EXPECT_NEAR(c.depth, 2.0 * dx, 1e-12);
    EXPECT_NEAR(c.width, (11.0 + 2.0 * 1.5 / 2.0) * dx, 1e-12);
    EXPECT_NEAR(c.length, (5.0 + 2.0 * 1.5 / 2.0) * dx, 1e-12);
}

// Two pits 4 columns long (x) and 3 wide (y), 2 rows deep, one after the other along x at different y
// (columns 10-13 at rows 2-4, columns 14-17 at rows 12-14): as a traversing jet's grains strike within
// its radius. Along the cut they make one kerf 8 columns long (the deepest cell of each x); across it
// the section through the deepest cell crosses one pit.
TEST(Crater3D, PitsAtDifferentYAlongTheCutJoinIntoOneKerf) {
    auto ps = block3(0, 0, 0, 0, 0);
    grit::particles::SphParticles<3> kept;
    for (Index a = 0; a < ps.size(); ++a) {
        const auto& p = ps.position()[a];
        const int i = static_cast<int>(std::floor(p[0] / dx)), j = static_cast<int>(std::floor(p[1] / dx));
        const bool deep = p[2] > -2.0 * dx;
        if (deep && ((i >= 10 && i < 14 && j >= 2 && j < 5) || (i >= 14 && i < 18 && j >= 12 && j < 15))) continue;
        const Index b = kept.append(1);
        kept.position()[b] = p;
        kept.phase()[b] = ps.phase()[a];
    }
    const auto c = analyse_crater(kept, region3, dx);
    EXPECT_NEAR(c.depth, 2.0 * dx, 1e-12);
    EXPECT_NEAR(c.length, (7.0 + 2.0 * 1.5 / 2.0) * dx, 1e-12);
    EXPECT_NEAR(c.width, (2.0 + 2.0 * 1.5 / 2.0) * dx, 1e-12);
}
