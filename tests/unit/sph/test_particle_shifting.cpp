// Particle shifting (Lind et al. 2012): a regular lattice stays as it is, a displaced particle moves
// back towards its site, a free-surface particle moves only along the surface, and a velocity
// gradient carries the velocity to the particle's new place.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "grit/neighbors/particle_neighbors.hpp"
#include "grit/sph/particle_shifting.hpp"

using grit::Index;
using Vec2 = grit::core::Vec<2>;

namespace {

/// A 2D lattice of n x n fluid particles of spacing dx, moving at 1 m/s along x (so D = A h |v| dt
/// is the same for all), lists at 2h + skin.
struct Lattice {
    static constexpr double dx = 0.01, h = 1.25 * dx;
    static constexpr int n = 15;
    grit::particles::SphParticles<2> ps;
    grit::neighbors::ParticleNeighbors<2> nb;
    grit::sph::Kernel<2> kernel = grit::sph::CubicSpline<2>(h);
    grit::sph::ShiftingSettings<2> settings;
    std::vector<std::int32_t> surface;
    std::vector<Vec2> shift;

    Lattice() {
        ps.append(n * n);
        for (Index i = 0; i < n * n; ++i) {
            ps.position()[i] = Vec2{(i % n + 0.5) * dx, (i / n + 0.5) * dx};
            ps.velocity()[i] = ps.velocity_half()[i] = Vec2{1.0, 0.0};
            ps.density()[i] = 1000.0;
            ps.mass()[i] = 1000.0 * dx * dx;
            ps.phase()[i] = 0;
        }
        surface.assign(static_cast<std::size_t>(n * n), 0);
        settings.spacing = dx;
    }
    static Index at(int i, int j) { return j * n + i; }
    void run() {
        nb.update(ps, 2.0 * h + 0.2 * dx, 0.2 * dx, true);
        grit::sph::shift_particles(ps, nb.list(), kernel, settings, 0.2 * dx, surface.data(), shift);
    }
};

}  // namespace

TEST(ParticleShifting, RegularLatticeStaysInPlace) {
    Lattice l;
    const Index centre = Lattice::at(7, 7);
    const Vec2 before = l.ps.position()[centre];
    l.run();
    EXPECT_LT(std::sqrt(grit::core::norm2(l.shift[centre])), 1e-12 * Lattice::dx);
    EXPECT_NEAR(l.ps.position()[centre][0], before[0], 1e-15);
    EXPECT_NEAR(l.ps.velocity()[centre][0], 1.0, 1e-12);
}

TEST(ParticleShifting, DisplacedParticleMovesBackTowardsItsSite) {
    Lattice l;
    const Index centre = Lattice::at(7, 7);
    const double site = l.ps.position()[centre][0];
    l.ps.position()[centre][0] += 0.3 * Lattice::dx;  // crowds its right neighbour
    l.run();
    const Vec2 dr = l.shift[centre];
    EXPECT_LT(dr[0], 0.0) << "shift " << dr[0];
    EXPECT_NEAR(dr[1], 0.0, 1e-12 * Lattice::dx);  // the lattice is symmetric about its row
    EXPECT_LE(std::abs(dr[0]), 0.2 * Lattice::dx * (1.0 + 1e-12));
    EXPECT_LT(std::abs(l.ps.position()[centre][0] - site), 0.3 * Lattice::dx);
}

TEST(ParticleShifting, FreeSurfaceParticleMovesOnlyAlongTheSurface) {
    Lattice l;
    // The top row is the free surface; one of its particles is displaced along it and downwards.
    for (int i = 0; i < Lattice::n; ++i)
        l.surface[static_cast<std::size_t>(Lattice::at(i, Lattice::n - 1))] = 1;
    const Index top = Lattice::at(7, Lattice::n - 1);
    l.ps.position()[top] += Vec2{0.3 * Lattice::dx, 0.0};
    l.run();
    const Vec2 dr = l.shift[top];
    EXPECT_LT(dr[0], 0.0) << "moves back along the surface";
    // Its truncated kernel pulls it into the fluid (grad C points down); only the part along the
    // surface remains: normal to its inward normal sum_b V_b grad W_ab (tilted by the displacement).
    auto normal = Vec2::zero();
    const auto& k = std::get<grit::sph::CubicSpline<2>>(l.kernel);
    const Vec2 xa = l.ps.position()[top] - dr;  // where the sums were taken
    for (Index b = 0; b < Lattice::n * Lattice::n; ++b) {
        if (b == top) continue;
        const Vec2 xab = xa - (l.ps.position()[b] - l.shift[b]);
        const double r = std::sqrt(grit::core::norm2(xab));
        if (r < k.support()) normal += xab * (k.gradient_factor(r) * Lattice::dx * Lattice::dx);
    }
    EXPECT_LT(normal[1], 0.0) << "the inward normal points into the fluid";
    EXPECT_NEAR(grit::core::dot(dr, normal), 0.0, 1e-9 * std::sqrt(grit::core::norm2(dr) * grit::core::norm2(normal)));
    // A particle a row below the surface is within a kernel of it: tangential only too.
    const Index below = Lattice::at(3, Lattice::n - 2);
    EXPECT_LT(std::abs(l.shift[below][1]), 1e-12 * Lattice::dx);
}

TEST(ParticleShifting, VelocityFollowsTheShiftToFirstOrder) {
    Lattice l;
    // Shear flow v_x = S y: a particle shifted by dy takes v_x + S dy.
    const double shear = 50.0;
    for (Index i = 0; i < Lattice::n * Lattice::n; ++i)
        l.ps.velocity()[i] = Vec2{1.0 + shear * l.ps.position()[i][1], 0.0};
    const Index centre = Lattice::at(7, 7);
    l.ps.position()[centre][1] += 0.3 * Lattice::dx;
    const double v_before = l.ps.velocity()[centre][0];
    l.run();
    const double dy = l.shift[centre][1];
    ASSERT_LT(dy, 0.0);
    EXPECT_NEAR(l.ps.velocity()[centre][0] - v_before, shear * dy, 0.1 * shear * std::abs(dy));
}
