// Brittle solids (JH-2, first seed paper eqs. 38-41, Table 3 red sandstone): the compressive and tensile
// strengths a specimen test reaches against the strengths the parameters imply, and the water jet's
// cracks against jet velocity (section 4.3) and against the rock's unconfined strength (granite and sandstone).
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
#include "support/validation_figures.hpp"

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
    grit::testing::record_figure({"peak axial stress against JH-2's intact strength", 100.0 * (measured / expected - 1.0),
                                  "%", "10 %", "JH-2, Yu et al. Table 3 sandstone"});
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
    grit::testing::record_figure({"peak tensile stress against JH-2's tensile strength",
                                  100.0 * (measured / expected - 1.0), "%", "10 %", "JH-2, Yu et al. Table 3 sandstone"});
}

// Pure water jet on red sandstone (section 4.3, Table 6 speeds) in the coarse case: radial cracks open
// at both edges of the jet at every speed 3 us after contact, and the damaged area grows with the jet
// speed at every output from contact (5 us) to 20 us, as in the paper's Fig. 25 (two radial cracks at
// 313 m/s, more radial and lateral ones above). Before fractured rock kept its JH-2 strength and only
// detached fragments were removed, a 3-4 mm zone was crushed and removed within 3 us and the damaged
// area fell with speed after 11 us (docs/validation.md).
TEST(Brittle, WaterJetDamageGrowsWithJetSpeed) {
    const double rho0 = 2460.0;
    const std::vector<const char*> speeds = {"313", "343", "370"};
    std::vector<std::vector<double>> damaged(speeds.size());
    grit::Index first_cracks = 0, last_cracks = 0;
    for (std::size_t v = 0; v < speeds.size(); ++v) {
        const char* speed = speeds[v];
        grit::sim::Simulation<2> sim(
            load_case("waterjet_sandstone_2d/case.toml", {std::string("inlet[0].velocity=") + speed, "time.end=2e-5"}),
            in_memory());
        for (double t = 5e-6; t <= 2.0e-5 + 1e-12; t += 1e-6) {
            sim.advance_to(t);
            const auto values = sim.output_values();
            for (const auto& o : values)
                if (o.name == "damaged_area") damaged[v].push_back(o.value);
            if (std::abs(t - 8e-6) > 1e-12) continue;
            // 3 us after contact: cracks at both jet edges (x = -0.5 and +0.5 mm) in the top millimetre.
            double cracks = 0.0, eroded = 0.0, area = 0.0;
            for (const auto& o : values) {
                if (o.name == "crack_count") cracks = o.value;
                if (o.name == "eroded_mass") eroded = o.value;
                if (o.name == "damaged_area") area = o.value;
            }
            std::printf("%s m/s at 8 us: damaged area %.2f mm^2, eroded %.3f mm^2, cracks %d\n", speed, area * 1e6,
                        eroded / rho0 * 1e6, static_cast<int>(cracks));
            EXPECT_GE(cracks, 2.0) << speed;
            if (first_cracks == 0) first_cracks = static_cast<grit::Index>(cracks);
            last_cracks = static_cast<grit::Index>(cracks);
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
    }
    for (std::size_t k = 0; k < damaged[0].size(); ++k)
        for (std::size_t v = 1; v < speeds.size(); ++v)
            EXPECT_GT(damaged[v][k], damaged[v - 1][k])
                << "damaged area at t = " << 5 + static_cast<int>(k) << " us: " << speeds[v] << " against " << speeds[v - 1];
    EXPECT_GT(last_cracks, first_cracks);
}

namespace {

/// What the water hammer leaves in the rock 10 us into the coarse water-jet case (the jet lands at 3.6-4.8
/// us): the share of damaged particles (D >= 0.5) under the jet's axis (|x| < 0.3 mm, 0.3-1.5 mm deep),
/// the damaged particles in each of the bands the radial cracks from the jet's edges cross (0.8-2.2 mm
/// off the axis, 0.5-1.5 mm deep), and the damaged area.
struct HammerDamage {
    double under_axis = 0.0;
    int left = 0, right = 0;
    double area = 0.0;
};

HammerDamage hammer_damage(const std::string& material, const std::string& speed) {
    grit::sim::Simulation<2> sim(load_case("waterjet_sandstone_2d/case.toml", {"solid[0].material=" + material,
                                                                               "inlet[0].velocity=" + speed,
                                                                               "time.end=1e-5"}),
                                 in_memory());
    sim.advance_to(1.0e-5);
    HammerDamage h;
    h.area = grit::testing::output_value(sim, "damaged_area");
    const auto& ps = sim.particles();
    const double* damage = ps.fields().get<double>("damage").data();
    int axis = 0, axis_damaged = 0;
    for (grit::Index i = 0; i < ps.size(); ++i) {
        if (ps.phase()[i] != static_cast<std::int32_t>(grit::Phase::solid)) continue;
        const double x = ps.position()[i][0] * 1e3, y = ps.position()[i][1] * 1e3;  // [mm]
        const bool hit = damage[i] >= 0.5;
        if (std::abs(x) < 0.3 && y < -0.3 && y > -1.5) {
            ++axis;
            axis_damaged += hit;
        }
        if (hit && y < -0.5 && y > -1.5 && std::abs(x) > 0.8 && std::abs(x) < 2.2) ++(x < 0.0 ? h.left : h.right);
    }
    h.under_axis = axis > 0 ? static_cast<double>(axis_damaged) / axis : 0.0;
    std::printf("%s at %s m/s, 10 us: damaged under the axis %.2f, in the radial-crack bands %d / %d, area %.2f mm^2\n",
                material.c_str(), speed.c_str(), h.under_axis, h.left, h.right, h.area * 1e6);
    return h;
}

}  // namespace

// The water hammer's pattern against the rock's unconfined strength (docs/validation.md, "Where the rock
// under the jet breaks first"). Table 3's granite stands the 0.78 GPa hammer of a 400 m/s jet (about 0.8
// GPa unconfined in plane strain): no crushed zone under the jet at 313, 370 or 400 m/s (measured: 3, 0,
// 0 % of the particles there damaged; tolerance 15 %), two radial cracks from the jet's edges at 400 m/s
// (31 and 30 damaged particles in the two bands; at least 10 asked), and damage growing with speed
// (0.60, 2.74, 3.77 mm^2), as the paper's Figs. 22 and 25 show the hammer's cracks. Table 3's sandstone
// (380 MPa unconfined) is crushed under the same jet (measured 100 %, 21.7 mm^2; at least 50 % asked):
// the paper's sandstone pattern is not what Table 3 gives.
TEST(Brittle, WaterHammerCracksGraniteAtTheJetEdgesAndCrushesSandstone) {
    const HammerDamage g313 = hammer_damage("granite", "313");
    const HammerDamage g370 = hammer_damage("granite", "370");
    const HammerDamage g400 = hammer_damage("granite", "400");
    for (const HammerDamage* h : {&g313, &g370, &g400}) EXPECT_LT(h->under_axis, 0.15);
    EXPECT_GE(g400.left, 10);
    EXPECT_GE(g400.right, 10);
    EXPECT_GT(g370.area, g313.area);
    EXPECT_GT(g400.area, g370.area);
    const HammerDamage s400 = hammer_damage("red_sandstone", "400");
    EXPECT_GT(s400.under_axis, 0.5);
}

namespace {

/// The stress at which the water's Hugoniot (rho_w (c0 + S1 u) u, u the water's velocity change) meets
/// the target's stress `target(u_t)` at its particle velocity u_t = impact - u, by bisection.
template <class Target>
double matched_stress(double impact, const Target& target) {
    const auto library_water = grit::material::find_in_library("water");
    const auto& water = std::get<grit::material::MieGruneisenEos>(library_water->eos);
    auto hugoniot = [&](double u) { return water.reference_density * (water.sound_speed + water.s1 * u) * u; };
    double lo = 0.0, hi = impact;
    for (int k = 0; k < 200; ++k) {
        const double u = 0.5 * (lo + hi);
        (hugoniot(u) < target(impact - u) ? lo : hi) = u;
    }
    return hugoniot(0.5 * (lo + hi));
}

/// A rock in elastic uniaxial strain: sigma = rho0 c_L u, c_L = sqrt((K1 + 4 G / 3) / rho0).
double rock_impedance(const std::string& name) {
    const auto m = grit::material::find_in_library(name);
    const auto& eos = std::get<grit::material::PolynomialEos>(m->eos);
    return std::sqrt(eos.reference_density * (eos.k1 + 4.0 * m->solid.shear_modulus / 3.0));
}

struct HammerPlateau {
    double water = 0.0;         ///< the shocked water's mean pressure at the probes, 1.0-2.2 us [Pa]
    double water_peak = 0.0;    ///< the largest pressure either probe read [Pa]
    double solid = 0.0;         ///< the mean normal stress -sigma_yy of the target 0.25-0.75 mm deep, 1.0-2.2 us [Pa]
    double solid_peak = 0.0;    ///< its largest value [Pa]
};

/// Runs cases/water_hammer_column_2d/<file> to 2.2 us, sampling every 50 ns.
HammerPlateau hammer_plateau(const std::string& file, const std::vector<std::string>& overrides) {
    grit::sim::Simulation<2> sim(load_case("water_hammer_column_2d/" + file, overrides), in_memory());
    const auto& ps = sim.particles();
    HammerPlateau out;
    int samples = 0, solid_samples = 0;
    for (int k = 1; k <= 44; ++k) {
        const double t = 5e-8 * k;
        sim.advance_to(t);
        const double p05 = sim.probe("p_water_05"), p10 = sim.probe("p_water_10");
        out.water_peak = std::max({out.water_peak, p05, p10});
        double sum = 0.0;
        int n = 0;
        if (ps.fields().has("deviatoric_stress")) {
            const auto& tau = ps.fields().get<grit::core::SymTensor3>("deviatoric_stress");
            for (grit::Index i = 0; i < ps.size(); ++i) {
                const double y = ps.position()[i][1];
                if (ps.phase()[i] != static_cast<std::int32_t>(grit::Phase::solid) || y > -2.5e-4 || y < -7.5e-4)
                    continue;
                sum += ps.pressure()[i] - tau[i].yy;
                ++n;
            }
        }
        const double solid = n > 0 ? sum / n : 0.0;
        out.solid_peak = std::max(out.solid_peak, solid);
        if (t < 1.0e-6 - 1e-12) continue;
        out.water += 0.5 * (p05 + p10);
        ++samples;
        if (n > 0) {
            out.solid += solid;
            ++solid_samples;
        }
    }
    out.water /= samples;
    if (solid_samples > 0) out.solid /= solid_samples;
    return out;
}

}  // namespace

// The water hammer in 1D (cases/water_hammer_column_2d, periodic across): a water column at 400 m/s on red
// sandstone, granite, OFHC copper and a rigid wall. The shocked water's pressure over its plateau
// (1.0-2.2 us, two probes) within 5 % of the impedance-matched Hugoniots: the water's of Table 1 (c0 = 1480
// m/s, S1 = 2.56) against the rocks' elastic rho c_L (Table 3: K1, G), copper's Hugoniot (Table 2: c0,
// S) plus 2/3 of its yield stress A, and a wall that does not move. In the rocks and copper the normal
// stress 0.25-0.75 mm below the interface holds the same plateau within 5 %. The water's pressure
// overshoots where the shock front passes a probe (recorded, not bounded): what the target feels is
// the plateau (its peak is recorded too).
TEST(WaterHammer, InterfacePressureMatchesTheHugoniots) {
    constexpr double impact = 400.0;
    struct Target {
        std::string label, file;
        std::vector<std::string> overrides;
        double reference;
    };
    const auto copper = grit::material::find_in_library("OFHC_copper");
    const auto& cu_eos = std::get<grit::material::MieGruneisenEos>(copper->eos);
    const double cu_yield = std::get<grit::material::JohnsonCook>(copper->solid_model).strength.A;
    const std::vector<Target> targets = {
        {"red sandstone", "case.toml", {}, matched_stress(impact, [z = rock_impedance("red_sandstone")](double u) {
             return z * u;
         })},
        {"granite", "case.toml", {"solid[0].material=\"granite\""},
         matched_stress(impact, [z = rock_impedance("granite")](double u) { return z * u; })},
        {"OFHC copper", "case.toml", {"solid[0].material=\"OFHC_copper\""},
         matched_stress(impact,
                        [&](double u) {
                            return cu_eos.reference_density * (cu_eos.sound_speed + cu_eos.s1 * u) * u +
                                   2.0 / 3.0 * cu_yield;
                        })},
        {"rigid wall", "rigid_wall.toml", {}, matched_stress(impact, [](double) { return 1e300; })},
    };
    double worst = 0.0, worst_solid = 0.0;
    for (const auto& target : targets) {
        const auto r = hammer_plateau(target.file, target.overrides);
        const double error = r.water / target.reference - 1.0;
        std::printf("%-13s Hugoniot %.3f GPa; water plateau %.3f GPa (%+.1f %%), peak %.3f GPa", target.label.c_str(),
                    target.reference / 1e9, r.water / 1e9, 100.0 * error, r.water_peak / 1e9);
        EXPECT_NEAR(r.water, target.reference, 0.05 * target.reference) << target.label;
        worst = std::max(worst, std::abs(error));
        if (target.file == "case.toml") {
            const double solid_error = r.solid / target.reference - 1.0;
            std::printf("; target's normal stress %.3f GPa (%+.1f %%), peak %.3f GPa", r.solid / 1e9,
                        100.0 * solid_error, r.solid_peak / 1e9);
            EXPECT_NEAR(r.solid, target.reference, 0.05 * target.reference) << target.label;
            worst_solid = std::max(worst_solid, std::abs(solid_error));
        }
        std::printf("\n");
    }
    grit::testing::record_figure({"largest error of the water's plateau pressure (4 targets)", 100.0 * worst, "%",
                                  "5 %", "impedance-matched Hugoniots (Tables 1-3)"});
    grit::testing::record_figure({"largest error of the target's normal stress (3 solids)", 100.0 * worst_solid, "%",
                                  "5 %", "impedance-matched Hugoniots (Tables 1-3)"});
}

// The jet's own first impact, read in the rock (cases/waterjet_sandstone_2d at 400 m/s, the nozzle 0.3 mm
// above the rock so that the front lands at 0.75 us): the peak of the mean normal stress -sigma_yy under
// the jet (abs(x) < 0.25 mm, 0.1-0.35 mm deep), on red sandstone and on granite. Release from the jet's
// edges reaches the axis within 0.2 us, so each peak is below the 1D hammer; the ratio of the two follows
// the ratio of their impedance-matched Hugoniots (0.876) within 5 %. (The water's pressure at the
// interface does not: its front rings, as in the 1D test, and reads 1.18 GPa on both.)
TEST(WaterHammer, JetImpactOnRockFollowsTheHugoniotsRatio) {
    constexpr double impact = 400.0;
    auto peak = [](const std::string& material) {
        grit::sim::Simulation<2> sim(
            load_case("waterjet_sandstone_2d/case.toml",
                      {"inlet[0].velocity=400.0", "inlet[0].position=[0.0, 3.0e-4]", "time.end=1.2e-6",
                       "output.interval=2.0e-8", "solid[0].material=\"" + material + "\""}),
            in_memory());
        const auto& ps = sim.particles();
        double highest = 0.0;
        for (int k = 30; k <= 60; ++k) {
            sim.advance_to(2e-8 * k);
            const auto& tau = ps.fields().get<grit::core::SymTensor3>("deviatoric_stress");
            double sum = 0.0;
            int n = 0;
            for (grit::Index i = 0; i < ps.size(); ++i) {
                const auto& x = ps.position()[i];
                if (ps.phase()[i] != static_cast<std::int32_t>(grit::Phase::solid) || std::abs(x[0]) > 2.5e-4 ||
                    x[1] > -1.0e-4 || x[1] < -3.5e-4)
                    continue;
                sum += ps.pressure()[i] - tau[i].yy;
                ++n;
            }
            if (n > 0) highest = std::max(highest, sum / n);
        }
        return highest;
    };
    const double sandstone = peak("red_sandstone"), granite = peak("granite");
    const double hugoniot_sandstone =
        matched_stress(impact, [z = rock_impedance("red_sandstone")](double u) { return z * u; });
    const double hugoniot_granite = matched_stress(impact, [z = rock_impedance("granite")](double u) { return z * u; });
    const double ratio = sandstone / granite, expected = hugoniot_sandstone / hugoniot_granite;
    std::printf("jet at 400 m/s: the rock's peak -sigma_yy under the jet %.3f GPa (sandstone), %.3f GPa (granite): "
                "ratio %.3f against the Hugoniots' %.3f (%+.1f %%); %.0f / %.0f %% of the 1D hammer\n",
                sandstone / 1e9, granite / 1e9, ratio, expected, 100.0 * (ratio / expected - 1.0),
                100.0 * sandstone / hugoniot_sandstone, 100.0 * granite / hugoniot_granite);
    EXPECT_NEAR(ratio, expected, 0.05 * expected);
    grit::testing::record_figure({"jet on rock: sandstone / granite peak stress against the Hugoniots' ratio",
                                  100.0 * (ratio / expected - 1.0), "%", "5 %",
                                  "impedance-matched Hugoniots (Tables 1, 3)"});
}
