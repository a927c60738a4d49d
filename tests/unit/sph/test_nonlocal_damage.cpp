// Non-local damage (sph/nonlocal_damage.hpp): the average of the local increments of eq. (36) over a
// material's damage length. A uniform or linear field is kept (the weights are symmetric and
// normalised), a point increment spreads over the length and keeps its volume integral in the bulk,
// the average is over the particle's own material only, images carry their sources' increments, and
// the result does not depend on when the pair list was built.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "grit/sph/nonlocal_damage.hpp"

using grit::Index;
using grit::Phase;
using Vec2 = grit::core::Vec<2>;

namespace {

constexpr double dx = 1e-4;

/// An n x n lattice of solid particles of material 0 (copper's density), centred on the origin.
struct Block {
    static constexpr int n = 21;
    grit::particles::SphParticles<2> ps;
    explicit Block(std::int32_t material = 0) {
        ps.append(n * n);
        for (Index i = 0; i < n * n; ++i)
            ps.start(i, Vec2{(i % n - n / 2) * dx, (i / n - n / 2) * dx}, Vec2::zero(), 8960.0, 8960.0 * dx * dx,
                     Phase::solid, material);
    }
    static Index at(int i, int j) { return (j + n / 2) * n + (i + n / 2); }
};

std::vector<double> averaged(grit::sph::NonlocalDamage<2>& nl, const grit::particles::SphParticles<2>& ps,
                             const std::vector<double>& local) {
    std::vector<double> out(local.size(), -1.0);
    nl.average(ps, local.data(), out.data());
    return out;
}

}  // namespace

TEST(NonlocalDamage, KeepsAUniformFieldEverywhereAndALinearOneInTheBulk) {
    Block b;
    grit::sph::NonlocalDamage<2> nl({3e-4}, {});
    ASSERT_TRUE(nl.active());
    const auto size = static_cast<std::size_t>(b.ps.size());
    const auto uniform = averaged(nl, b.ps, std::vector<double>(size, 0.01));
    for (const double d : uniform) EXPECT_NEAR(d, 0.01, 1e-15);  // the surface's too (normalised)
    std::vector<double> linear(size);
    for (std::size_t i = 0; i < size; ++i) linear[i] = 0.01 + 20.0 * b.ps.position()[i][0] - 7.0 * b.ps.position()[i][1];
    const auto avg = averaged(nl, b.ps, linear);
    for (int j = -7; j <= 7; ++j)
        for (int i = -7; i <= 7; ++i) {
            const auto k = static_cast<std::size_t>(Block::at(i, j));
            EXPECT_NEAR(avg[k], linear[k], 1e-15) << i << ", " << j;
        }
    // On a free edge the average leans towards the inside (the surface particle averages over the solid
    // side only): the edge at x = +1 mm, where the field grows with x, gets less than its own value.
    const auto edge = static_cast<std::size_t>(Block::at(Block::n / 2, 0));
    EXPECT_LT(avg[edge], linear[edge]);
}

TEST(NonlocalDamage, SpreadsAPointIncrementOverTheLengthAndKeepsItsIntegralInTheBulk) {
    Block b;
    const double length = 3e-4;
    grit::sph::NonlocalDamage<2> nl({length}, {});
    std::vector<double> local(static_cast<std::size_t>(b.ps.size()), 0.0);
    local[static_cast<std::size_t>(Block::at(0, 0))] = 1.0;
    const auto avg = averaged(nl, b.ps, local);
    double integral = 0.0;
    for (Index i = 0; i < b.ps.size(); ++i) {
        const double r = std::sqrt(grit::core::norm2(b.ps.position()[i]));
        const double d = avg[static_cast<std::size_t>(i)];
        if (r >= length) EXPECT_EQ(d, 0.0) << "at r = " << r;
        else EXPECT_GT(d, 0.0) << "at r = " << r;
        integral += d;
    }
    EXPECT_NEAR(integral, 1.0, 1e-12);  // every particle within l of the source has the same normaliser
    // The bell falls with the distance: (1 - r^2/l^2)^2 relative to the source's own share.
    const double centre = avg[static_cast<std::size_t>(Block::at(0, 0))];
    const double q = 1.0 - dx * dx / (length * length);
    EXPECT_NEAR(avg[static_cast<std::size_t>(Block::at(1, 0))] / centre, q * q, 1e-12);
    EXPECT_NEAR(centre, 3.0 * dx * dx / (3.14159265 * length * length), 0.01);  // 1 / (sum of w): pi l^2 / 3 dx^2
}

TEST(NonlocalDamage, AveragesOverItsOwnMaterialAndLeavesLocalMaterialsAlone) {
    Block b;
    // The right half is material 1 (local: length 0), one column of it fluid.
    for (Index i = 0; i < b.ps.size(); ++i)
        if (b.ps.position()[i][0] > 0.5 * dx) b.ps.material()[i] = 1;
    for (int j = -10; j <= 10; ++j) b.ps.phase()[Block::at(-10, j)] = static_cast<std::int32_t>(Phase::fluid);
    grit::sph::NonlocalDamage<2> nl({3e-4, 0.0}, {});
    std::vector<double> local(static_cast<std::size_t>(b.ps.size()), 0.0);
    for (Index i = 0; i < b.ps.size(); ++i)
        if (b.ps.material()[i] == 1 || b.ps.phase()[i] != 1) local[static_cast<std::size_t>(i)] = 5.0;
    const auto avg = averaged(nl, b.ps, local);
    for (Index i = 0; i < b.ps.size(); ++i) {
        const auto k = static_cast<std::size_t>(i);
        if (b.ps.material()[i] == 1 || b.ps.phase()[i] != 1) EXPECT_EQ(avg[k], -1.0);  // left as it was
        else EXPECT_EQ(avg[k], 0.0);  // the neighbours across the material line do not count
    }
}

TEST(NonlocalDamage, ImagesCarryTheirSourcesIncrements) {
    // The x >= 0 half of the block with the images of its particles within 0.5 mm of x = 0 (as the
    // symmetry plane makes them): the average of the half equals the whole block's, whatever the images'
    // own (stale) increments are.
    Block whole;
    grit::sph::NonlocalDamage<2> nl_whole({3e-4}, {});
    std::vector<double> field(static_cast<std::size_t>(whole.ps.size()));
    auto value = [](const Vec2& x) { return 0.02 + 40.0 * x[0] * x[0] + 3.0 * x[1]; };  // even in x
    for (Index i = 0; i < whole.ps.size(); ++i) field[static_cast<std::size_t>(i)] = value(whole.ps.position()[i]);
    const auto expected = averaged(nl_whole, whole.ps, field);

    grit::particles::SphParticles<2> half;
    std::vector<Index> from_whole;
    for (Index i = 0; i < whole.ps.size(); ++i)
        if (whole.ps.position()[i][0] >= 0.0) {
            const Index k = half.append(1);
            half.start(k, whole.ps.position()[i], Vec2::zero(), 8960.0, 8960.0 * dx * dx, Phase::solid, 0);
            from_whole.push_back(i);
        }
    const Index sources = half.size();
    for (Index s = 0; s < sources; ++s) {
        const Vec2 x = half.position()[s];
        if (x[0] <= 0.0 || x[0] > 5e-4) continue;
        const Index k = half.append_images(1);
        half.start(k, Vec2{-x[0], x[1]}, Vec2::zero(), 8960.0, 8960.0 * dx * dx, Phase::solid, 0);
        half.id()[k] = grit::particles::SphParticles<2>::image_id(half.id()[s]);
    }
    std::vector<double> local(static_cast<std::size_t>(half.size()), 123.0);  // images: stale
    for (Index s = 0; s < sources; ++s) local[static_cast<std::size_t>(s)] = value(half.position()[s]);
    grit::sph::NonlocalDamage<2> nl_half({3e-4}, {});
    const auto avg = averaged(nl_half, half, local);
    for (Index s = 0; s < sources; ++s)
        EXPECT_NEAR(avg[static_cast<std::size_t>(s)], expected[static_cast<std::size_t>(from_whole[static_cast<std::size_t>(s)])],
                    1e-15);
    for (Index k = sources; k < half.size(); ++k) EXPECT_EQ(avg[static_cast<std::size_t>(k)], -1.0);  // images: left
}

TEST(NonlocalDamage, DoesNotDependOnWhenThePairsWereListed) {
    // A list built at the start and kept (members moved less than half its skin), one rebuilt after a
    // move of more than that, kept through removals and a reordering, and a fresh one: the same averages
    // bit for bit.
    Block b;
    std::vector<double> local(static_cast<std::size_t>(b.ps.size()));
    for (Index i = 0; i < b.ps.size(); ++i) local[static_cast<std::size_t>(i)] = 1e-3 * static_cast<double>((i * 37) % 11);
    grit::sph::NonlocalDamage<2> kept({3e-4}, {});
    averaged(kept, b.ps, local);
    auto compare = [&](const char* what) {
        grit::sph::NonlocalDamage<2> fresh({3e-4}, {});
        const auto a = averaged(kept, b.ps, local);
        const auto f = averaged(fresh, b.ps, local);
        for (std::size_t k = 0; k < a.size(); ++k) ASSERT_EQ(a[k], f[k]) << what << ", particle " << k;
    };
    for (const double shear : {2e-6, 6e-5}) {  // skin: 0.25 l = 75 um; rebuilt past 37.5 um
        for (Index i = 0; i < b.ps.size(); ++i) b.ps.position()[i][0] += shear * b.ps.position()[i][1] / 1e-3;
        compare(shear < 1e-5 ? "kept" : "rebuilt");
        // Particles removed (as erosion does): the kept list is compacted, twice in a row.
        for (const int every : {7, 5}) {
            std::vector<Index> keep;
            std::vector<double> left;
            for (Index i = 0; i < b.ps.size(); ++i)
                if (i % every != 3) {
                    keep.push_back(i);
                    left.push_back(local[static_cast<std::size_t>(i)]);
                }
            b.ps.remove(keep);
            local = left;
            compare("compacted");
        }
        // Reordered (as the neighbour lists' sort by cell does): the members are found again by id.
        std::vector<Index> reversed;
        std::vector<double> reordered;
        for (Index i = b.ps.size() - 1; i >= 0; --i) {
            reversed.push_back(i);
            reordered.push_back(local[static_cast<std::size_t>(i)]);
        }
        b.ps.gather(reversed);
        local = reordered;
        compare("reordered");
    }
}

TEST(NonlocalDamage, InactiveWithoutALength) {
    grit::sph::NonlocalDamage<2> nl({0.0, 0.0}, {});
    EXPECT_FALSE(nl.active());
}
