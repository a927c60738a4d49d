// Brittle solids (JH-2, first seed paper eqs. 38-41, Table 3 red sandstone): the compressive and tensile
// strengths a specimen test reaches against the strengths the parameters imply, and the water jet's
// cracks against jet velocity (section 4.3).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <variant>
#include <vector>

#include "grit/material/library.hpp"
#include "support/case_fixture.hpp"

using grit::testing::in_memory;
using grit::testing::load_case;

namespace {

/// Peak of the mean axial stress sigma_yy = tau_yy - p [Pa] over the middle third of the 20 mm specimen,
/// sampled every 2.5 us, signed as in the test (negative in compression).
double peak_axial_stress(const std::string& case_file, double sign) {
    grit::sim::Simulation<2> sim(load_case(case_file), in_memory());
    auto& ps = sim.particles();
    double peak = 0.0;
    const double end = sim.spec().end_time;
    for (double t = 2.5e-6; t <= end * (1.0 + 1e-12); t += 2.5e-6) {
        sim.advance_to(t);
        const auto& tau = ps.fields().get<grit::core::SymTensor3>("deviatoric_stress");
        double sum = 0.0;
        int n = 0;
        for (grit::Index i = 0; i < ps.size(); ++i) {
            if (ps.phase()[i] != static_cast<std::int32_t>(grit::Phase::solid)) continue;
            const double y = ps.position()[i][1];
            if (y < 2.0e-2 / 3.0 || y > 4.0e-2 / 3.0) continue;
            sum += tau[i].yy - ps.pressure()[i];
            ++n;
        }
        if (n == 0) continue;  // the middle third has broken away
        peak = std::max(peak, sign * sum / n);
        if (std::getenv("GRIT_TRACE")) std::printf("t %.2e sigma %.2f MPa\n", t, sum / n / 1e6);
    }
    return peak;
}

/// The axial stress magnitude [Pa] at which the elastic plane-strain uniaxial path (sigma_xx = 0,
/// eps_zz = 0, axial strain rate `rate` [1/s], sign +1 tension, -1 compression) meets the JH-2 intact
/// surface of eq. (38) (D = 0), by bisection. Elastic constants from K1 and G of the material.
double implied_strength(const grit::material::Material& m, double sign, double rate) {
    const auto& jh2 = std::get<grit::material::JH2>(m.solid_model);
    const double K = jh2.bulk_modulus, G = m.solid.shear_modulus, lambda = K - 2.0 * G / 3.0;
    // Strain per unit axial strain: (eps_xx, eps_yy, eps_zz) = (-lambda / (lambda + 2G), 1, 0).
    const double e[3] = {-lambda / (lambda + 2.0 * G), 1.0, 0.0};
    const double tr = e[0] + e[1] + e[2];
    double dev2 = 0.0;
    for (double x : e) dev2 += (x - tr / 3.0) * (x - tr / 3.0);
    const double equivalent_rate = std::sqrt(2.0 / 3.0 * dev2) * rate;
    double s[3];
    for (int k = 0; k < 3; ++k) s[k] = lambda * tr + 2.0 * G * e[k];
    const double p_unit = -(s[0] + s[1] + s[2]) / 3.0;
    const double vm_unit = std::sqrt(0.5 * ((s[0] - s[1]) * (s[0] - s[1]) + (s[1] - s[2]) * (s[1] - s[2]) +
                                            (s[2] - s[0]) * (s[2] - s[0])));
    double lo = 0.0, hi = 0.1;
    for (int it = 0; it < 200; ++it) {
        const double eps = 0.5 * (lo + hi);
        const double excess = vm_unit * eps - jh2.strength.yield_stress(sign * p_unit * eps, 0.0, equivalent_rate);
        (excess > 0.0 ? hi : lo) = eps;
    }
    return std::abs(s[1]) * 0.5 * (lo + hi);
}

}  // namespace

// Uniaxial compression (plane strain) of red sandstone: the peak axial stress within 10 % of the JH-2
// intact strength on the elastic path (392 MPa at 50/s).
TEST(Brittle, CompressiveStrengthFromJH2) {
    const auto m = grit::material::find_in_library("red_sandstone").value();
    const double expected = implied_strength(m, -1.0, 50.0);
    const double measured = peak_axial_stress("compression_sandstone_2d/case.toml", -1.0);
    std::printf("compressive strength: measured %.1f MPa, JH-2 implies %.1f MPa (%+.1f %%)\n", measured / 1e6,
                expected / 1e6, 100.0 * (measured / expected - 1.0));
    EXPECT_NEAR(expected, 392.0e6, 2.0e6);
    EXPECT_NEAR(measured, expected, 0.10 * expected);
}

// Direct tension (plane strain): the peak within 10 % of the JH-2 tensile strength on the elastic path
// (29.6 MPa at 10/s, set by T* with A and N).
TEST(Brittle, TensileStrengthFromJH2) {
    const auto m = grit::material::find_in_library("red_sandstone").value();
    const double expected = implied_strength(m, 1.0, 10.0);
    const double measured = peak_axial_stress("tension_sandstone_2d/case.toml", 1.0);
    std::printf("tensile strength: measured %.2f MPa, JH-2 implies %.2f MPa (%+.1f %%)\n", measured / 1e6,
                expected / 1e6, 100.0 * (measured / expected - 1.0));
    EXPECT_NEAR(measured, expected, 0.10 * expected);
}

// Pure water jet on red sandstone (section 4.3, Table 6 speeds) in the coarse case, 3 us after contact:
// radial cracks open at both edges of the jet at every speed, and the damage footprint (damaged area
// still in the specimen plus the area removed) grows with the jet speed, as does the crack count from
// 313 to 370 m/s (the paper's Fig. 25: two radial cracks at 313 m/s, more radial and lateral ones above).
TEST(Brittle, WaterJetCracksGrowWithJetSpeed) {
    const double rho0 = 2460.0;
    double last_footprint = 0.0;
    grit::Index first_cracks = 0, last_cracks = 0;
    for (const char* speed : {"313", "343", "370"}) {
        grit::sim::Simulation<2> sim(
            load_case("waterjet_sandstone_2d/case.toml", {std::string("inlet[0].velocity=") + speed, "time.end=8e-6"}),
            in_memory());
        const grit::sim::RunSummary s = sim.run();
        const double damaged_area = s.value("damaged_area"), eroded_mass = s.value("eroded_mass");
        const auto crack_count = static_cast<grit::Index>(s.value("crack_count"));
        const double footprint = damaged_area + eroded_mass / rho0;
        std::printf("%s m/s: damaged area %.2f mm^2, eroded %.2f mm^2, cracks %d, C_d %.2f mm, C_w %.2f mm\n", speed,
                    damaged_area * 1e6, eroded_mass / rho0 * 1e6, static_cast<int>(crack_count),
                    s.value("crater_depth") * 1e3, s.value("crater_width") * 1e3);
        EXPECT_GE(crack_count, 2) << speed;
        EXPECT_GT(footprint, last_footprint) << speed;
        last_footprint = footprint;
        if (first_cracks == 0) first_cracks = crack_count;
        last_cracks = crack_count;
        // Damage at both jet edges (x = -0.5 and +0.5 mm), in the top millimetre of the rock.
        auto& ps = sim.particles();
        const double* damage = ps.fields().get<double>("damage").data();
        bool left = false, right = false;
        for (grit::Index i = 0; i < ps.size(); ++i) {
            if (ps.phase()[i] != static_cast<std::int32_t>(grit::Phase::solid) || damage[i] < 0.5) continue;
            const auto& x = ps.position()[i];
            if (x[1] < -1.0e-3 || x[1] > 0.0) continue;
            left = left || std::abs(x[0] + 0.5e-3) < 0.5e-3;
            right = right || std::abs(x[0] - 0.5e-3) < 0.5e-3;
        }
        EXPECT_TRUE(left && right) << speed << " m/s: no damage at one of the jet's edges";
    }
    EXPECT_GT(last_cracks, first_cracks);
}
