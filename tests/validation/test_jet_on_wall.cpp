// A 2D water jet on a rigid wall (first seed paper, Fig. 10 without grains): the centre-line wall
// pressure settles to the stagnation pressure 0.5 rho v^2 within 15 %, and the mass books balance.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>

#include "support/case_fixture.hpp"

using grit::testing::in_memory;
using grit::testing::load_case;

TEST(JetOnWall, StagnationPressure) {
    grit::sim::Simulation<2> sim(load_case("jet_on_wall_2d/case.toml"), in_memory());
    const double stagnation = 0.5 * 1000.0 * 200.0 * 200.0;  // 20 MPa
    sim.advance_to(4e-5);  // the jet reaches the wall at 10 us; the film has spread to the outlets
    double sum = 0.0;
    int samples = 0;
    for (double t = 4.1e-5; t <= 8e-5 + 1e-12; t += 1e-6) {
        sim.advance_to(t);
        sum += sim.probe("p_stagnation");
        ++samples;
        const auto d = grit::analysis::compute_diagnostics(sim.particles());
        ASSERT_NEAR(d.mass + sim.mass_out(), sim.mass_in(), 1e-12 * sim.mass_in());
    }
    const double mean = sum / samples;
    std::printf("mean centre-line wall pressure %.4g MPa over %d samples (0.5 rho v^2 = %.4g MPa)\n", mean / 1e6,
                samples, stagnation / 1e6);
    EXPECT_NEAR(mean, stagnation, 0.15 * stagnation);
}

// A 2 mm jet at 200 m/s on a plate given as an STL surface of zero thickness, its wall particles laid
// behind it (cases/jet_on_thin_plate_3d, issue 13): no water particle passes the plate's surface by more
// than half a spacing (into the first layer of wall particles) at any step to 30 us, two thirds of it
// after the impact, and the water's mass books (in = inside + out).
TEST(JetOnWall, NoWaterThroughAThinStlPlate) {
    auto spec = load_case("jet_on_thin_plate_3d/case.toml");
    grit::sim::Simulation<3> sim(spec, in_memory());
    const double dx = spec.particle_spacing;
    double lowest = 1.0;
    sim.advance_to(spec.end_time, [&] {
        const auto& ps = sim.particles();
        for (grit::Index i = 0; i < ps.size(); ++i)
            if (ps.phase()[i] == 0) lowest = std::min(lowest, ps.position()[i][2]);
    });
    std::printf("lowest water particle: z = %.3g m (%.2f spacings); stagnation pressure %.3g Pa\n", lowest, lowest / dx,
                sim.probe("p_stagnation"));
    EXPECT_GT(lowest, -0.5 * dx);
    EXPECT_GT(sim.mass_in(), 0.0);
    double inside = -1.0;
    for (const auto& v : sim.output_values())
        if (v.name == "mass_total") inside = v.value;
    EXPECT_NEAR(inside + sim.mass_out(), sim.mass_in(), 1e-9 * sim.mass_in());
}
