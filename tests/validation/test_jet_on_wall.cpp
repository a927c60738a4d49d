// A 2D water jet on a rigid wall (first seed paper, Fig. 10 without grains): the centre-line wall
// pressure settles to the stagnation pressure 0.5 rho v^2 within 15 %, and the mass books balance.
#include <gtest/gtest.h>

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
