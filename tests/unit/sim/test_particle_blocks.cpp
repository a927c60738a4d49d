// The starting particles of a case's blocks: the shipped 2D tank (a 0.4 x 0.3 m hydrostatic water box in
// a three-layer tank, dx = 1 cm) against the values its case file asks for.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "grit/io/case_reader.hpp"
#include "grit/material/equation_of_state.hpp"
#include "grit/sim/particle_blocks.hpp"

namespace {

TEST(ParticleBlocks, HydrostaticTankStartsAtRhoGDepthWithItsEquationOfStateDensity) {
    const auto file = std::filesystem::path(GRIT_SOURCE_DIR) / "cases" / "hydrostatic_2d" / "case.toml";
    const grit::io::CaseSpec spec = grit::io::read_case(file);
    const double dx = spec.particle_spacing;
    ASSERT_DOUBLE_EQ(dx, 0.01);
    grit::particles::SphParticles<2> ps;
    grit::sim::add_particle_blocks<2>(spec, dx, ps);

    const auto& water = spec.materials[static_cast<std::size_t>(spec.fluids[0].material)];
    const double rho0 = water.reference_density(), g = 9.81, surface = 0.3;  // top row at 0.295 m
    int fluid = 0, wall = 0;
    for (grit::Index i = 0; i < ps.size(); ++i) {
        const auto phase = static_cast<grit::Phase>(ps.phase()[i]);
        EXPECT_DOUBLE_EQ(ps.mass()[i], rho0 * dx * dx);
        EXPECT_EQ(grit::core::norm(ps.velocity()[i]), 0.0);
        if (phase == grit::Phase::wall) {
            ++wall;
            EXPECT_EQ(ps.pressure()[i], 0.0);
            continue;
        }
        ASSERT_EQ(phase, grit::Phase::fluid);
        ++fluid;
        const double y = ps.position()[i][1];
        EXPECT_NEAR(ps.pressure()[i], rho0 * g * (surface - y), 1e-9 * rho0 * g * surface) << "y = " << y;
        EXPECT_DOUBLE_EQ(ps.density()[i], grit::material::density_from_pressure(water.eos, ps.pressure()[i]));
        EXPECT_DOUBLE_EQ(ps.density_half()[i], ps.density()[i]);
    }
    EXPECT_EQ(fluid, 40 * 30);
    // Three layers round the 0.4 x 0.4 m inner box, open at the top (the default): 46 x 43 - 40 x 40.
    EXPECT_EQ(wall, 46 * 43 - 40 * 40);
}

}  // namespace
