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
#include "support/validation_figures.hpp"

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

// The tank's x >= 0 half on a symmetry plane (cases/hydrostatic_2d/half.toml): the mirror images' rows of
// the pressure system read their sources' unknowns, so the half holds the whole tank's pressure. The same
// measure and tolerance as the whole tank (HydrostaticTankPressure), the probes on the plane itself.
TEST(Isph, HalfTankOnASymmetryPlaneHoldsTheHydrostaticPressure) {
    grit::sim::Simulation<2> sim(load_case("hydrostatic_2d/half.toml", {"fluid.solver=isph", "time.end=1.5"}),
                                 in_memory());
    const double surface = 0.3;
    const auto& probes = sim.spec().module_spec<grit::modules::ProbesSpec>(grit::modules::ProbesSpec::key)->probes;
    std::vector<double> mean(probes.size(), 0.0);
    const int samples = 21;
    for (int s = 0; s < samples; ++s) {
        sim.advance_to(0.5 + 0.05 * s);
        for (std::size_t k = 0; k < probes.size(); ++k) mean[k] += sim.probe(k) / samples;
    }
    double largest = 0.0;
    for (std::size_t k = 0; k < probes.size(); ++k) {
        const double expected = rho0 * g * (surface - probes[k].position[1]);
        const double error = (mean[k] - expected) / expected;
        std::printf("ISPH half tank: %s mean = %.1f Pa (%+.1f %% of rho g depth)\n", probes[k].name.c_str(), mean[k],
                    100.0 * error);
        EXPECT_NEAR(mean[k], expected, 0.03 * expected) << probes[k].name;
        if (std::abs(error) > std::abs(largest)) largest = error;
    }
    grit::testing::record_figure({"largest probe error (mean over 0.5-1.5 s)", 100.0 * largest, "%", "3 % per probe",
                                  "p = rho g depth"});
    const auto& ps = sim.particles();
    for (grit::Index i = 0; i < ps.size(); ++i) {
        if (ps.phase()[i] != 0 || ps.is_image(i)) continue;
        const auto& x = ps.position()[i];
        ASSERT_TRUE(x[0] >= 0.0 && x[0] < 0.2 && x[1] >= 0.0) << "fluid particle " << i << " left the half tank";
    }
    EXPECT_LT(grit::analysis::compute_diagnostics(ps).max_velocity, 0.05) << "the tank is not at rest";
}

// A column 2L x 2L collapsing to both sides (cases/double_dambreak_2d): each side is Martin & Moyce's dam
// break with a free-slip wall. The whole and its half on a symmetry plane: the surge front Z = z/L within
// 10 % of the data for 1.5 <= T <= 2.5 (as DamBreakFrontAgainstMartinMoyce), and the half within 1 % of
// the whole (two solves to a tolerance of 1e-6, not the same sums: not round-off).
TEST(Isph, DoubleDamBreakOnASymmetryPlaneIsTheWholeOne) {
    auto data = grit::testing::martin_moyce();
    std::sort(data.begin(), data.end(), [](auto l, auto r) { return l.T < r.T; });
    const double L = 0.2, scale = std::sqrt(2.0 * g / L);
    grit::sim::Simulation<2> whole(load_case("double_dambreak_2d/case.toml"), in_memory());
    grit::sim::Simulation<2> half(load_case("double_dambreak_2d/half.toml"), in_memory());
    int checked = 0;
    double largest = 0.0, apart = 0.0;
    for (const auto& [T, Z_exp] : data) {
        if (T < 1.5 || T > 2.5) continue;
        whole.advance_to(T / scale);
        half.advance_to(T / scale);
        const double Z_whole = whole.probe("front") / L, Z_half = half.probe("front") / L;
        const double H_whole = whole.probe("height") / (2.0 * L), H_half = half.probe("height") / (2.0 * L);
        std::printf("ISPH double dam break: T = %.3f  Z_exp = %.3f  whole %.3f (%+.1f %%)  half %.3f (%+.1f %% of the "
                    "whole); height %.3f, half %+.2f %%\n",
                    T, Z_exp, Z_whole, 100.0 * (Z_whole - Z_exp) / Z_exp, Z_half, 100.0 * (Z_half - Z_whole) / Z_whole,
                    H_whole, 100.0 * (H_half - H_whole) / H_whole);
        EXPECT_LT(std::abs(Z_whole - Z_exp) / Z_exp, 0.10) << "T = " << T;
        EXPECT_LT(std::abs(Z_half - Z_exp) / Z_exp, 0.10) << "T = " << T;
        EXPECT_LT(std::abs(Z_half - Z_whole) / Z_whole, 0.01) << "T = " << T;
        EXPECT_LT(std::abs(H_half - H_whole) / H_whole, 0.01) << "T = " << T;
        for (const double e : {(Z_whole - Z_exp) / Z_exp, (Z_half - Z_exp) / Z_exp})
            if (std::abs(e) > std::abs(largest)) largest = e;
        for (const double e : {(Z_half - Z_whole) / Z_whole, (H_half - H_whole) / H_whole})
            if (std::abs(e) > std::abs(apart)) apart = e;
        ++checked;
    }
    EXPECT_GE(checked, 3);
    grit::testing::record_figure({"largest front error, whole and half, 1.5 <= T <= 2.5", 100.0 * largest, "%", "10 %",
                                  "Martin & Moyce (1952)"});
    grit::testing::record_figure({"half against the whole: front and height", 100.0 * apart, "%", "1 %",
                                  "the whole double dam break"});
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
