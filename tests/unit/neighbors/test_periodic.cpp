// Periodic axes: the PeriodicBox (wrap, nearest image), and the SPH neighbour lists and the cross-set
// pair list over a periodic box against a brute-force nearest-image search, in 2D and 3D, with particles
// crowded at the faces and boxes as short as three list radii, and shorter (down to two).
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <set>
#include <vector>

#include "grit/neighbors/cell_grid.hpp"
#include "grit/neighbors/cross_pairs.hpp"
#include "grit/neighbors/neighbor_list.hpp"
#include "grit/neighbors/periodic_box.hpp"
#include "grit/parallel/parallel.hpp"

using grit::Index;
using grit::neighbors::PeriodicBox;

namespace {

template <int Dim>
using Vec = grit::core::Vec<Dim>;

template <int Dim>
PeriodicBox<Dim> make_box(const std::array<bool, Dim>& axes, double lo, double hi) {
    return PeriodicBox<Dim>::make(axes, Vec<Dim>::filled(lo), Vec<Dim>::filled(hi));
}

/// n points inside `box` along its periodic axes (open axes: a wider range), a third of them within
/// `radius` of a face of a periodic axis.
template <int Dim>
std::vector<Vec<Dim>> points_in(const PeriodicBox<Dim>& box, Index n, double radius, unsigned seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    std::vector<Vec<Dim>> x(static_cast<std::size_t>(n));
    for (std::size_t i = 0; i < x.size(); ++i)
        for (int k = 0; k < Dim; ++k) {
            const double lo = box.lower[k], hi = box.upper[k];
            if (!box.periodic[k]) {
                x[i][k] = lo - 0.3 + (hi - lo + 0.6) * u(rng);
            } else if (i % 3 == 0) {  // near a face: within radius of lo or of hi
                const double s = radius * u(rng);
                x[i][k] = u(rng) < 0.5 ? lo + s : hi - s;
            } else {
                x[i][k] = lo + (hi - lo) * u(rng);
            }
            if (box.periodic[k] && x[i][k] >= hi) x[i][k] = lo;
        }
    return x;
}

template <int Dim>
void check_lists(const PeriodicBox<Dim>& box, Index n, double radius, unsigned seed) {
    auto x = points_in(box, n, radius, seed);
    auto grid = grit::neighbors::CellGrid<Dim>::over_box(box.periodic, box.lower, box.upper, x.data(), n, radius);
    std::vector<Index> order, cell_start;
    grit::neighbors::sort_by_cell(grid, x.data(), n, order, cell_start);
    std::vector<Vec<Dim>> sorted(x.size());
    for (std::size_t i = 0; i < x.size(); ++i) sorted[i] = x[static_cast<std::size_t>(order[i])];

    grit::neighbors::NeighborList<Dim> list;
    list.build(grid, cell_start, sorted.data(), n, radius, nullptr, box);
    std::size_t across = 0;
    for (Index i = 0; i < n; ++i) {
        std::set<Index> expected;
        for (Index j = 0; j < n; ++j) {
            const auto d = sorted[static_cast<std::size_t>(i)] - sorted[static_cast<std::size_t>(j)];
            if (j != i && grit::core::norm2(box.nearest_image(d)) < radius * radius) {
                expected.insert(j);
                across += grit::core::norm2(d) >= radius * radius;  // found only through a face
            }
        }
        const std::vector<Index> row(list.indices() + list.begin(i), list.indices() + list.end(i));
        const std::set<Index> found(row.begin(), row.end());
        ASSERT_EQ(found.size(), row.size()) << "particle " << i << " lists a neighbour twice";
        ASSERT_EQ(found, expected) << "particle " << i;
    }
    EXPECT_GT(across, 0u) << "no pair across a periodic face: the test proves nothing";
    EXPECT_EQ(list.max_displacement2(sorted.data(), n, box), 0.0);
}

}  // namespace

TEST(PeriodicBox, WrapsIntoTheHalfOpenBox) {
    const auto box = PeriodicBox<2>::make({true, false}, Vec<2>{{-1.0, 0.0}}, Vec<2>{{2.0, 1.0}});
    EXPECT_TRUE(box.any());
    EXPECT_EQ(box.length(0), 3.0);
    EXPECT_EQ(box.length(1), 0.0);
    EXPECT_EQ(box.wrap(Vec<2>{{0.5, 7.0}})[0], 0.5);  // inside: unchanged, bit for bit
    EXPECT_EQ(box.wrap(Vec<2>{{0.5, 7.0}})[1], 7.0);  // open axis: untouched
    EXPECT_EQ(box.wrap(Vec<2>{{2.0, 0.0}})[0], -1.0);  // the upper face is the lower one
    EXPECT_DOUBLE_EQ(box.wrap(Vec<2>{{2.25, 0.0}})[0], -0.75);
    EXPECT_DOUBLE_EQ(box.wrap(Vec<2>{{-1.5, 0.0}})[0], 1.5);
    EXPECT_DOUBLE_EQ(box.wrap(Vec<2>{{9.5, 0.0}})[0], 0.5);
    // Just below the lower face: x + L rounds onto the upper face, which is not in the box.
    const double below = std::nextafter(-1.0, -2.0) - 1e-17;
    const double w = box.wrap(Vec<2>{{below, 0.0}})[0];
    EXPECT_GE(w, -1.0);
    EXPECT_LT(w, 2.0);
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<double> u(-40.0, 40.0);
    for (int i = 0; i < 100000; ++i) {
        const double v = box.wrap(Vec<2>{{u(rng), 0.0}})[0];
        ASSERT_TRUE(v >= -1.0 && v < 2.0) << v;
    }
}

TEST(PeriodicBox, NearestImage) {
    const auto box = PeriodicBox<3>::make({true, false, true}, Vec<3>::zero(), Vec<3>{{1.0, 1.0, 2.0}});
    const auto d = box.nearest_image(Vec<3>{{0.9, 0.9, -1.5}});
    EXPECT_DOUBLE_EQ(d[0], -0.1);
    EXPECT_EQ(d[1], 0.9);  // open
    EXPECT_DOUBLE_EQ(d[2], 0.5);
    const auto e = box.nearest_image(Vec<3>{{0.2, -0.7, 0.3}});
    EXPECT_EQ(e[0], 0.2);  // already the nearest: unchanged
    EXPECT_EQ(e[2], 0.3);
    // Without periodic axes, the identity.
    const PeriodicBox<3> open{};
    EXPECT_FALSE(open.any());
    const Vec<3> f{{3.0, -4.0, 1e9}};
    EXPECT_EQ(open.nearest_image(f)[0], 3.0);
    EXPECT_EQ(open.wrap(f)[2], 1e9);
    // The image functor of the pair loops agrees with the box.
    const grit::neighbors::PeriodicImage<3> image(box);
    for (double t : {-2.7, -0.51, -0.2, 0.49, 0.51, 1.3, 3.9}) {
        const Vec<3> v{{t, t, t}};
        for (int k = 0; k < 3; ++k) EXPECT_EQ(image(v)[k], box.nearest_image(v)[k]);
    }
}

TEST(PeriodicNeighborList, MatchesBruteForceNearestImage2D) {
    check_lists<2>(make_box<2>({true, false}, 0.0, 1.0), 1500, 0.07, 11);
    check_lists<2>(make_box<2>({false, true}, 0.0, 1.0), 1500, 0.07, 12);
    check_lists<2>(make_box<2>({true, true}, -0.5, 0.5), 1500, 0.07, 13);
}

TEST(PeriodicNeighborList, MatchesBruteForceNearestImage3D) {
    check_lists<3>(make_box<3>({true, false, false}, 0.0, 1.0), 2000, 0.15, 21);
    check_lists<3>(make_box<3>({true, false, true}, 0.0, 1.0), 2000, 0.15, 22);
    check_lists<3>(make_box<3>({true, true, true}, 0.0, 1.0), 2000, 0.15, 23);
}

// Three cells exactly along the periodic axes: every cell is a neighbour of every other, and none may
// be scanned twice.
TEST(PeriodicNeighborList, ShortestBoxOfThreeCells) {
    check_lists<2>(make_box<2>({true, true}, 0.0, 0.31), 400, 0.1, 31);
    check_lists<3>(make_box<3>({true, true, false}, 0.0, 0.31), 600, 0.1, 32);
}

// Periods shorter than three list radii but longer than two: the axis is one cell, whose particles are all
// candidates once (along x, the row's own span; along y and z, the cell around).
TEST(PeriodicNeighborList, ShortBoxesOfOneCell) {
    check_lists<2>(make_box<2>({true, false}, 0.0, 0.25), 300, 0.1, 41);
    check_lists<2>(make_box<2>({true, true}, 0.0, 0.21), 300, 0.1, 42);
    check_lists<3>(make_box<3>({false, true, true}, 0.0, 0.25), 400, 0.1, 43);
    check_lists<3>(make_box<3>({true, true, true}, 0.0, 0.29), 400, 0.1, 44);
}

// A particle wrapped across a face has moved by its step, not by the period: the lists stay valid.
TEST(PeriodicNeighborList, DisplacementAcrossAFaceIsTheStep) {
    const auto box = make_box<2>({true, false}, 0.0, 1.0);
    std::vector<Vec<2>> x = {Vec<2>{{0.995, 0.5}}, Vec<2>{{0.5, 0.5}}, Vec<2>{{0.01, 0.5}}};
    const auto grid = grit::neighbors::CellGrid<2>::over_box(box.periodic, box.lower, box.upper, x.data(), 3, 0.1);
    std::vector<Index> order, cell_start;
    grit::neighbors::sort_by_cell(grid, x.data(), 3, order, cell_start);
    std::vector<Vec<2>> sorted;
    for (Index i : order) sorted.push_back(x[static_cast<std::size_t>(i)]);
    grit::neighbors::NeighborList<2> list;
    list.build(grid, cell_start, sorted.data(), 3, 0.1, nullptr, box);
    for (auto& p : sorted) p = box.wrap(p + Vec<2>{{0.01, 0.0}});
    EXPECT_NEAR(list.max_displacement2(sorted.data(), 3, box), 1e-4, 1e-15);
    EXPECT_GT(list.max_displacement2(sorted.data(), 3), 0.9);  // without the box: the period
}

// Grains (bodies) near and a little beyond the faces of the periodic box, points inside it.
TEST(PeriodicCrossPairs, MatchBruteForceNearestImage) {
    for (int variant = 0; variant < 2; ++variant) {
        const auto box = variant == 0 ? make_box<3>({true, true, false}, 0.0, 1.0) : make_box<3>({true, false, true}, 0.0, 1.0);
        std::mt19937_64 rng(41 + static_cast<unsigned>(variant));
        std::uniform_real_distribution<double> u(0.0, 1.0);
        const Index na = 3000, nb = 120;
        const double reach = 0.03;
        auto a = points_in(box, na, 0.1, 43);
        std::vector<Vec<3>> b(static_cast<std::size_t>(nb));
        std::vector<double> radius(static_cast<std::size_t>(nb));
        for (std::size_t i = 0; i < b.size(); ++i) {
            for (int k = 0; k < 3; ++k) b[i][k] = -0.02 + 1.04 * u(rng);  // up to 0.02 beyond the faces
            radius[i] = 0.03 + 0.05 * u(rng);
        }
        auto keep = [](Index i) { return i % 4 != 3; };
        for (int threads : {1, 2}) {
            grit::parallel::set_threads(threads);
            grit::neighbors::CrossPairList<3> list;
            list.build(a.data(), na, keep, b.data(), radius.data(), nb, reach, box);
            std::size_t across = 0;
            for (Index i = 0; i < na; ++i) {
                std::vector<Index> expected;
                if (keep(i))
                    for (Index j = 0; j < nb; ++j) {
                        const double r = radius[static_cast<std::size_t>(j)] + reach;
                        const auto d = a[static_cast<std::size_t>(i)] - b[static_cast<std::size_t>(j)];
                        if (grit::core::norm2(box.nearest_image(d)) < r * r) {
                            expected.push_back(j);
                            across += grit::core::norm2(d) >= r * r;
                        }
                    }
                const std::vector<Index> got(list.indices() + list.begin(i), list.indices() + list.end(i));
                ASSERT_EQ(got, expected) << "point " << i;
            }
            EXPECT_GT(across, 0u);
        }
    }
    grit::parallel::set_threads(2);
}
