// The second paper's single-particle drag (eqs. 18-19): the dimensionally consistent law grit uses and
// the printed form a case may ask for to compare with the paper's pictures, against hand values.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "grit/coupling/drag_laws.hpp"

using namespace grit::coupling;

namespace {

/// A 1 mm quartz grain in water (the sloshing tank's coarse sand), slipping at `speed`.
DragInput sand_in_water(double speed) {
    DragInput in;
    in.relative_speed = speed;
    in.diameter = 1e-3;
    in.volume = std::numbers::pi / 6.0 * 1e-9;
    in.fluid_density = 1000.0;
    in.viscosity = 1e-3;
    return in;
}

}  // namespace

// Eq. 19 with the velocity factor: |F| = pi/4 d^2 rho |u|^2 (1.84 Re^-0.31 + 0.293 Re^0.06)^3.45. At 0.1 m/s,
// Re = 100: f = 1.84 * 100^-0.31 + 0.293 * 100^0.06 = 0.8276, f^3.45 = 0.5206, a drag coefficient
// C_d = 2 f^3.45 = 1.04 (the standard sphere's is about 1.09 at Re = 100).
TEST(DragLaws, SingleParticleHandValue) {
    const auto in = sand_in_water(0.1);
    const double f = 1.84 * std::pow(100.0, -0.31) + 0.293 * std::pow(100.0, 0.06);
    const double force = std::numbers::pi / 4.0 * 1e-6 * 1000.0 * 0.1 * 0.1 * std::pow(f, 3.45);
    EXPECT_NEAR(single_particle_coefficient(in) * 0.1, force, 1e-12 * force);
    EXPECT_NEAR(std::pow(f, 3.45), 0.5206, 0.0001);
    // Stokes below Re = 0.01: 3 pi mu d u.
    const auto creeping = sand_in_water(5e-6);
    EXPECT_NEAR(single_particle_coefficient(creeping), 3.0 * std::numbers::pi * 1e-3 * 1e-3, 1e-15);
}

// As printed, eq. 19 has one velocity factor fewer: the coefficient is the law's divided by |u| in m/s, so
// below 1 m/s of slip it drags harder (10x at 0.1 m/s), and the same at 1 m/s.
TEST(DragLaws, AsPrintedLacksOneVelocityFactor) {
    for (const double u : {0.01, 0.1, 1.0, 3.0}) {
        const auto in = sand_in_water(u);
        EXPECT_NEAR(drag_coefficient(DragLaw::single_particle_as_printed, in),
                    drag_coefficient(DragLaw::single_particle, in) / u, 1e-12 * drag_coefficient(DragLaw::single_particle, in) / u)
            << u;
    }
    EXPECT_EQ(make_drag_law("single_particle_as_printed"), DragLaw::single_particle_as_printed);
    const auto creeping = sand_in_water(5e-6);
    EXPECT_EQ(single_particle_as_printed_coefficient(creeping), single_particle_coefficient(creeping));
}
