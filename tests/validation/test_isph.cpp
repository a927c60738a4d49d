// Incompressible SPH (fluid.solver = "isph"): the hydrostatic tank's pressure and its smoothness, the
// 2D dam break's surge front against Martin & Moyce (1952), and a solve that cannot converge is an
// error naming the step and the keys.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "grit/core/error.hpp"
#include "grit/modules/probes_table.hpp"
#include "support/case_fixture.hpp"
#include "support/martin_moyce.hpp"

using grit::testing::in_memory;
using grit::testing::load_case;

namespace {
constexpr double rho0 = 1000.0, g = 9.81;
}  // namespace

// The tank of cases/hydrostatic_2d (0.3 m of water, dx 1 cm): every probe's mean over 0.5-1.5 s
// (21 samples) within 3 % of rho g depth (issue 14's figure). ISPH's pressure swings slowly about
// it (-5 % to +4 % at the shallowest probe over 2 s, docs/validation.md), so a single instant is
// not the measure. At 1.5 s: a smooth field (the particles' pressure below the top 3 cm within
// 0.5 % of rho g H, RMS, of its own straight line in depth), at rest, no particle out of the tank.
TEST(Isph, HydrostaticTankPressure) {
    grit::sim::Simulation<2> sim(load_case("hydrostatic_2d/case.toml", {"fluid.solver=isph"}), in_memory());
    const double surface = 0.3;
    const auto& probes = sim.spec().module_spec<grit::modules::ProbesSpec>(grit::modules::ProbesSpec::key)->probes;
    std::vector<double> mean(probes.size(), 0.0), low(probes.size(), 1e30), high(probes.size(), -1e30);
    const int samples = 21;
    for (int s = 0; s < samples; ++s) {
        sim.advance_to(0.5 + 0.05 * s);
        for (std::size_t k = 0; k < probes.size(); ++k) {
            mean[k] += sim.probe(k) / samples;
            low[k] = std::min(low[k], sim.probe(k));
            high[k] = std::max(high[k], sim.probe(k));
        }
    }
    for (std::size_t k = 0; k < probes.size(); ++k) {
        const double depth = surface - probes[k].position[1];
        const double expected = rho0 * g * depth;
        std::printf("ISPH tank: %s mean = %.1f Pa (%+.1f %%), range %+.1f %% .. %+.1f %% of rho g depth = %.1f Pa\n",
                    probes[k].name.c_str(), mean[k], 100.0 * (mean[k] - expected) / expected,
                    100.0 * (low[k] - expected) / expected, 100.0 * (high[k] - expected) / expected, expected);
        EXPECT_NEAR(mean[k], expected, 0.03 * expected) << probes[k].name << " at depth " << depth;
    }
    // Least-squares line p = c0 + c1 y through the particles below the top 3 cm; the RMS about it.
    auto& ps = sim.particles();
    double n = 0.0, sy = 0.0, syy = 0.0, sp = 0.0, syp = 0.0;
    for (grit::Index i = 0; i < ps.size(); ++i) {
        if (ps.phase()[i] != 0) continue;
        const auto& x = ps.position()[i];
        ASSERT_GE(x[0], 0.0) << "fluid particle " << i << " left through a wall";
        ASSERT_LE(x[0], 0.4) << "fluid particle " << i;
        ASSERT_GE(x[1], 0.0) << "fluid particle " << i;
        if (x[1] > surface - 0.03) continue;
        const double p = ps.pressure()[i];
        n += 1.0, sy += x[1], syy += x[1] * x[1], sp += p, syp += x[1] * p;
    }
    const double c1 = (n * syp - sy * sp) / (n * syy - sy * sy), c0 = (sp - c1 * sy) / n;
    double sum2 = 0.0;
    for (grit::Index i = 0; i < ps.size(); ++i) {
        const auto& x = ps.position()[i];
        if (ps.phase()[i] != 0 || x[1] > surface - 0.03) continue;
        const double d = ps.pressure()[i] - (c0 + c1 * x[1]);
        sum2 += d * d;
    }
    const double rms = std::sqrt(sum2 / n);
    std::printf("ISPH tank: pressure RMS about its line = %.2f Pa, slope = %.0f Pa/m (rho g = %.0f)\n", rms, -c1,
                rho0 * g);
    EXPECT_LT(rms, 0.005 * rho0 * g * surface);
    EXPECT_LT(grit::analysis::compute_diagnostics(ps).max_velocity, 0.05) << "the tank is not at rest";
}

// As DamBreak.Front2DAgainstMartinMoyce (test_dambreak.cpp) with the incompressible solver: Z = z/L
// within 10 % of the data for 1.5 <= T <= 2.5 (issue 14's figure), dx 5 mm.
TEST(Isph, DamBreakFrontAgainstMartinMoyce) {
    auto data = grit::testing::martin_moyce();
    std::sort(data.begin(), data.end(), [](auto l, auto r) { return l.T < r.T; });
    ASSERT_GE(data.size(), 8u);
    const double L = 0.2, scale = std::sqrt(2.0 * g / L);
    grit::sim::Simulation<2> sim(
        load_case("dambreak_2d/case.toml", {"fluid.solver=isph", "numerics.particle_spacing=0.005"}), in_memory());
    int checked = 0;
    for (const auto& [T, Z_exp] : data) {  // FrontPoint {T, Z}
        if (T < 1.5 || T > 2.5) continue;
        sim.advance_to(T / scale);
        const double Z = sim.probe("front") / L;
        const double error = (Z - Z_exp) / Z_exp;
        std::printf("ISPH: T = %.3f  Z_exp = %.3f  Z_sim = %.3f  error = %+.1f %%\n", T, Z_exp, Z, 100.0 * error);
        EXPECT_LT(std::abs(error), 0.10) << "T = " << T;
        ++checked;
    }
    EXPECT_GE(checked, 3);
}

TEST(Isph, UnconvergedSolveIsAnErrorNamingTheStep) {
    grit::sim::Simulation<2> sim(
        load_case("hydrostatic_2d/case.toml", {"fluid.solver=isph", "isph.max_iterations=1", "isph.tolerance=1e-12"}),
        in_memory());
    try {
        sim.advance_to(0.05);
        FAIL() << "expected a failed solve";
    } catch (const grit::core::BlowUpError& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("at step 0 "), std::string::npos) << what;
        EXPECT_NE(what.find("pressure Poisson solve did not converge"), std::string::npos) << what;
        EXPECT_NE(what.find("isph.max_iterations = 1"), std::string::npos) << what;
    }
}
