// JH-2 brittle laws (first seed paper eqs. 38-41, Table 3) against values computed by hand for red
// sandstone, and the single-point driver (update_solid_point) for intact and fractured strength, damage
// growth and bulking.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <variant>
#include <vector>

#include "grit/core/sym_tensor.hpp"
#include "grit/material/johnson_holmquist.hpp"
#include "grit/material/library.hpp"
#include "grit/material/material_point_driver.hpp"
#include "grit/material/solid_model.hpp"

using grit::core::SymTensor3;
using grit::material::DrivenPoint;
using grit::material::drive_point;
using grit::material::JH2;
using grit::material::Material;
using grit::material::PolynomialEos;
using grit::material::SolidPointState;
using grit::material::Spin;

namespace {

Material sandstone() {
    const auto m = grit::material::find_in_library("red_sandstone");
    EXPECT_TRUE(m.has_value());
    return m.value_or(Material{});
}

const JH2& jh2_of(const Material& m) { return std::get<JH2>(m.solid_model); }

/// Pure shear (no spin): eps_dot_xy = gamma_dot / 2.
SymTensor3 pure_shear(double gamma_dot) { return {0.0, 0.0, 0.0, 0.5 * gamma_dot, 0.0, 0.0}; }

}  // namespace

// Table 3 as the library holds it, and the HEL identity sigma_HEL = 1.5 (HEL - P_HEL) it satisfies.
TEST(JH2, LibraryHoldsTable3) {
    const Material m = sandstone();
    const auto& s = jh2_of(m).strength;
    EXPECT_DOUBLE_EQ(m.reference_density(), 2460.0);
    EXPECT_DOUBLE_EQ(m.solid.shear_modulus, 7.84e9);
    EXPECT_DOUBLE_EQ(s.A, 0.88);
    EXPECT_DOUBLE_EQ(s.N, 0.64);
    EXPECT_DOUBLE_EQ(s.B, 0.293);
    EXPECT_DOUBLE_EQ(s.M, 0.64);
    EXPECT_DOUBLE_EQ(s.C, 0.00337);
    EXPECT_DOUBLE_EQ(s.tensile_strength, 0.0103);
    EXPECT_DOUBLE_EQ(s.max_fractured_strength, 0.25);
    EXPECT_NEAR(s.hel_stress, 1.5 * (2.5e9 - s.hel_pressure), 0.01 * s.hel_stress);
    EXPECT_DOUBLE_EQ(jh2_of(m).failure.D1, 0.05);
    EXPECT_DOUBLE_EQ(jh2_of(m).failure.D2, 1.5);
    const auto& eos = std::get<PolynomialEos>(m.eos);
    EXPECT_DOUBLE_EQ(eos.k1, 10.45e9);
    EXPECT_DOUBLE_EQ(eos.k2, 20.78e9);
    EXPECT_DOUBLE_EQ(eos.k3, 22.69e9);
    EXPECT_DOUBLE_EQ(jh2_of(m).bulk_modulus, 10.45e9);  // eq. (41) uses the EOS's K1
    EXPECT_NEAR(m.sound_speed(), std::sqrt(10.45e9 / 2460.0), 1e-9);
    // `grit materials` prints the keys a case file's material section takes (io/material_tables.cpp).
    const std::string text = grit::material::describe(m);
    for (const char* line : {"  eos = \"polynomial\"\n", "  k1 = 10450000000 # [Pa]", "  model = \"jh2\"\n",
                             "  hel_pressure = 1450000000 # [Pa] (P_HEL)\n", "  intact_coefficient = 0.88 # (A)\n",
                             "  tensile_strength = 0.0103 # (T* = T / P_HEL)\n", "  failure_d2 = 1.5\n",
                             "  bulking_fraction = 1 # (beta of eq. 41)\n"})
        EXPECT_NE(text.find(line), std::string::npos) << line << "\n" << text;
    for (const char* name : {"granite", "silicon_carbide"}) {
        const auto other = grit::material::find_in_library(name);
        ASSERT_TRUE(other.has_value()) << name;
        EXPECT_TRUE(std::holds_alternative<JH2>(other->solid_model)) << name;
    }
}

// Eq. (38) at four pressures; the numbers were evaluated by hand (python) from Table 3.
TEST(JH2, StrengthMatchesEq38) {
    const Material rock = sandstone();
    const auto& s = jh2_of(rock).strength;
    // Intact: sigma_HEL A (P* + T*)^N.
    EXPECT_NEAR(s.yield_stress(0.0, 0.0, 1.0), 74.3628e6, 1e3);
    EXPECT_NEAR(s.yield_stress(0.1e9, 0.0, 1.0), 274.5072e6, 1e3);
    EXPECT_NEAR(s.yield_stress(0.5e9, 0.0, 1.0), 716.7798e6, 1e3);
    // Fractured: sigma_HEL B P*^M, capped at sigma_fmax* sigma_HEL = 395 MPa at P = 2.9 GPa.
    EXPECT_NEAR(s.yield_stress(0.1e9, 1.0, 1.0), 83.6083e6, 1e3);
    EXPECT_NEAR(s.yield_stress(0.5e9, 1.0, 1.0), 234.2017e6, 1e3);
    EXPECT_NEAR(s.yield_stress(2.9e9, 1.0, 1.0), 395.0e6, 1e-3);
    // Damaged: sigma_i - D (sigma_i - sigma_f) at D = 0.4.
    EXPECT_NEAR(s.yield_stress(0.5e9, 0.4, 1.0), 523.7486e6, 1e3);
    // Rate: 1 + C ln(1000) at 1000/s; no gain below the reference rate.
    EXPECT_NEAR(s.yield_stress(0.0, 0.0, 1000.0), 76.0939e6, 1e3);
    EXPECT_DOUBLE_EQ(s.yield_stress(0.1e9, 0.0, 0.01), s.yield_stress(0.1e9, 0.0, 1.0));
    // Tension: no intact strength at or below P = -T = -T* P_HEL; fractured rock none in tension.
    EXPECT_NEAR(s.tensile_pressure(), 14.935e6, 1.0);
    EXPECT_DOUBLE_EQ(s.yield_stress(-s.tensile_pressure(), 0.0, 1.0), 0.0);
    EXPECT_DOUBLE_EQ(s.yield_stress(-2.0 * s.tensile_pressure(), 0.0, 1.0), 0.0);
    EXPECT_DOUBLE_EQ(s.yield_stress(-0.5 * s.tensile_pressure(), 1.0, 1.0), 0.0);
}

// Eq. (39) failure strain, eq. (41) bulking and eq. (40)'s pressure with the tension limit.
TEST(JH2, FailureStrainBulkingAndPressure) {
    const Material rock = sandstone();
    const JH2& m = jh2_of(rock);
    EXPECT_NEAR(m.failure.failure_strain(0.1e9, m.strength), 1.115826e-3, 1e-9);
    EXPECT_NEAR(m.failure.failure_strain(0.2e9, m.strength), 2.853505e-3, 1e-9);
    EXPECT_NEAR(m.failure.failure_strain(0.0, m.strength), 5.226679e-5, 1e-11);
    EXPECT_DOUBLE_EQ(m.failure.failure_strain(-m.strength.tensile_pressure(), m.strength), m.failure.min_failure_strain);
    // dp = -K1 mu + sqrt((K1 mu + dp_n)^2 + 2 beta K1 dU), mu = 1e-3, dp_n = 2 MPa, dU = 5 kJ/m^3.
    EXPECT_NEAR(grit::material::bulking_pressure(2e6, 1e-3, 10.45e9, 1.0, 5e3), 5.659081e6, 1.0);
    EXPECT_DOUBLE_EQ(grit::material::bulking_pressure(2e6, 1e-3, 10.45e9, 1.0, 0.0), 2e6);  // no loss, no change
    EXPECT_DOUBLE_EQ(grit::material::bulking_pressure(2e6, 1e-3, 10.45e9, 0.0, 5e3), 2e6);  // beta = 0
    // Polynomial EOS: K1 mu + K2 mu^2 + K3 mu^3 in compression, K1 mu in tension; rho(p) inverts it.
    const PolynomialEos eos{2460.0, 10.45e9, 20.78e9, 22.69e9};
    const double mu = 0.02;
    EXPECT_NEAR(eos.pressure(2460.0 * (1.0 + mu)), 10.45e9 * mu + 20.78e9 * mu * mu + 22.69e9 * mu * mu * mu, 1.0);
    EXPECT_NEAR(eos.pressure(2460.0 * (1.0 - mu)), -10.45e9 * mu, 1e-3);
    EXPECT_NEAR(eos.density(eos.pressure(2460.0 * 1.05)), 2460.0 * 1.05, 1e-9);
    EXPECT_NEAR(eos.density(-5e6), 2460.0 * (1.0 - 5e6 / 10.45e9), 1e-9);
    // Bulking adds in compression only; tension is limited to -T (1 - D).
    const double T = m.strength.tensile_pressure();
    EXPECT_DOUBLE_EQ(grit::material::jh2_pressure(1e8, 0.01, 3e6, 0.0, T), 1.03e8);
    EXPECT_DOUBLE_EQ(grit::material::jh2_pressure(-1e6, -1e-4, 3e6, 0.0, T), -1e6);
    EXPECT_DOUBLE_EQ(grit::material::jh2_pressure(-1e8, -1e-2, 0.0, 0.0, T), -T);
    EXPECT_DOUBLE_EQ(grit::material::jh2_pressure(-1e8, -1e-2, 0.0, 0.5, T), -0.5 * T);
    EXPECT_DOUBLE_EQ(grit::material::jh2_pressure(-1e8, -1e-2, 0.0, 1.0, T), 0.0);
}

// A point sheared at constant pressure P = 0.2 GPa: elastic up to the intact strength (eq. 38, D = 0),
// then every plastic increment adds d eps_p / eps_f to D (eq. 39, eps_f constant at constant P, so
// D = eps_p / eps_f), the stress sits on the damaged surface sigma_i - D (sigma_i - sigma_f), and at D = 1
// it stays on the fractured strength sigma_f. The bulking pressure at mu = 0 then holds the lost
// deviatoric energy (sigma_i^2 - sigma_f^2) / 6G: dp = sqrt(sigma_i^2 - sigma_f^2) sqrt(beta K1 / 3G)
// (eq. 41 summed).
TEST(JH2, DriverIntactDamagedFractured) {
    const Material m = sandstone();
    const JH2& model = jh2_of(m);
    const double p = 0.2e9, G = m.solid.shear_modulus;
    const double gamma_dot = 100.0, dt = 1e-8;  // 100/s: equivalent rate 100/sqrt(3) = 57.7/s
    const double rate = gamma_dot / std::sqrt(3.0);
    const double sigma_i = model.strength.yield_stress(p, 0.0, rate);
    const double sigma_f = model.strength.yield_stress(p, 1.0, rate);
    const double eps_f = model.failure.failure_strain(p, model.strength);
    // Elastic shear: sigma_vm = sqrt(3) G gamma; yield after gamma_y = sigma_i / (sqrt 3 G).
    const double gamma_y = sigma_i / (std::sqrt(3.0) * G);
    const int steps = static_cast<int>((gamma_y + 1.5 * std::sqrt(3.0) * eps_f) / (gamma_dot * dt)) + 10;
    const auto h = drive_point(m, DrivenPoint{grit::material::rest_state(m), p}, pure_shear(gamma_dot), Spin{}, dt, steps);
    double peak = 0.0;
    bool saw_damaged = false;
    for (std::size_t k = 1; k < h.size(); ++k) {
        const auto& s = h[k];
        const double vm = s.deviatoric_stress.von_mises();
        peak = std::max(peak, vm);
        if (s.damage > 0.0 && s.damage < 1.0) {
            saw_damaged = true;
            EXPECT_NEAR(s.damage, s.plastic_strain / eps_f, 1e-9) << "step " << k;
            EXPECT_NEAR(vm, sigma_i - s.damage * (sigma_i - sigma_f), 1e-6 * sigma_i) << "step " << k;
        }
    }
    EXPECT_TRUE(saw_damaged);
    // The intact strength is the peak, reached to within one step's elastic increment sqrt(3) G gamma_dot dt.
    EXPECT_LE(peak, sigma_i);
    EXPECT_GT(peak, sigma_i - std::sqrt(3.0) * G * gamma_dot * dt);
    // Fractured (D = 1): the point flows on eq. (38)'s fractured strength sigma_f* = B (P*)^M, as JH-2
    // does (docs/theory.md), and eps_p keeps growing.
    const SolidPointState& last = h.back();
    EXPECT_DOUBLE_EQ(last.damage, 1.0);
    EXPECT_NEAR(last.deviatoric_stress.von_mises(), sigma_f, 1e-9 * sigma_f);
    EXPECT_NEAR(sigma_f / sigma_i, 0.318, 0.001);  // by hand: B (0.138)^M / (A (0.148)^N) at P = 0.2 GPa
    EXPECT_GT(last.plastic_strain, 1.2 * eps_f);
    // Bulking: dp^2 grows by 2 beta K dU with dU = (sigma_y0^2 - sigma_y^2) / 6G per step (mu = 0), which
    // sums to the loss from the intact to the fractured strength.
    const double dp_intact = sigma_i * std::sqrt(model.bulking_fraction * model.bulk_modulus / (3.0 * G));
    EXPECT_NEAR(dp_intact, 276.87e6, 0.01e6);  // by hand: 273.14 MPa at the reference rate x (1 + C ln 57.74)
    const double dp_max = dp_intact * std::sqrt(1.0 - (sigma_f / sigma_i) * (sigma_f / sigma_i));
    EXPECT_NEAR(last.bulking_pressure, dp_max, 1e-9 * dp_max);
}

// Beyond the hydrostatic tensile strength there is no intact strength: every shear increment is plastic,
// d eps_p = sqrt(3) G gamma_dot dt / 3G = gamma_dot dt / sqrt(3), against eps_f at its floor (1e-6), so
// D = 0.577 after one step and 1 after two, with no deviatoric stress left.
TEST(JH2, DriverFracturesInTension) {
    const Material m = sandstone();
    const double p = -1.1 * jh2_of(m).strength.tensile_pressure();
    const auto h = drive_point(m, DrivenPoint{grit::material::rest_state(m), p}, pure_shear(100.0), Spin{}, 1e-8, 3);
    EXPECT_NEAR(h[1].damage, 1e-6 / std::sqrt(3.0) / 1e-6, 1e-9);
    EXPECT_DOUBLE_EQ(h[1].deviatoric_stress.von_mises(), 0.0);  // no strength at all in this state
    EXPECT_DOUBLE_EQ(h[2].damage, 1.0);
    EXPECT_DOUBLE_EQ(h.back().deviatoric_stress.von_mises(), 0.0);
}
