// Wear models against hand-computed values and their analytic shapes: Finnie's peak and continuity,
// Bitter's threshold, Oka's peak, LIGGGHTS' form as Finnie's with k = 2.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "grit/wear/wear_models.hpp"

using namespace grit::wear;

namespace {

constexpr double deg = std::numbers::pi / 180.0;

WearMaterial steel() {
    return *find_wear_material("steel");
}
const Impactor grain{1.3875e-6, 0.5e-3, 2650.0, 70e9, 0.17};  // a 1 mm quartz grain: 2650 * 4/3 pi r^3

/// The angle of the largest f over (0, 90] degrees, by a scan at 0.001 degree.
template <class F>
double peak_of(F f) {
    double best = 0.0, at = 0.0;
    for (int i = 1; i <= 90000; ++i) {
        const double a = i * 0.001 * deg;
        if (f(a) > best) best = f(a), at = a;
    }
    return at / deg;
}

}  // namespace

// Eqs. 22-23 at 30 degrees, k = 2, psi = 2, p = 1.18 GPa: tan 30 = 0.577 > k/6, so f = k cos^2 / 6 = 0.25,
// V = m 10^2 / (2 * 1.18e9 * 2) * 0.25.
TEST(WearModels, FinnieHandValue) {
    const double expected = 1.3875e-6 * 100.0 / (2.0 * 1.18e9 * 2.0) * 0.25;
    EXPECT_NEAR(finnie_volume(steel(), grain, 10.0, 30.0 * deg), expected, 1e-12 * expected);
    const double low =
        1.3875e-6 * 100.0 / (2.0 * 1.18e9 * 2.0) * (std::sin(20.0 * deg) - 3.0 * std::pow(std::sin(10.0 * deg), 2));
    EXPECT_NEAR(finnie_volume(steel(), grain, 10.0, 10.0 * deg), low, 1e-12 * low);
}

// The peak is at atan(k/3)/2 (16.85 degrees for k = 2) and the branches meet at tan a = k/6.
TEST(WearModels, FinniePeakAndContinuity) {
    for (const double k : {1.5, 2.0, 3.0}) {
        EXPECT_NEAR(peak_of([&](double a) { return finnie_angle_function(a, k); }), std::atan(k / 3.0) / 2.0 / deg,
                    0.002);
        const double joint = std::atan(k / 6.0);
        EXPECT_NEAR(finnie_angle_function(joint - 1e-9, k), finnie_angle_function(joint + 1e-9, k), 1e-8);
    }
    EXPECT_NEAR(std::atan(2.0 / 3.0) / 2.0 / deg, 16.845, 0.001);
}

// Eq. 26 by hand for steel and quartz: D_k = pi^2/(2 sqrt 10) (1.59 Y)^2.5 sqrt(R_f/rho_p) K^2, with the
// grain's density (docs/theory.md, "Errata in the papers"); below it in the normal component the
// deformation term is zero, above it M (U sin a - D_k)^2 / (2 E_f).
TEST(WearModels, BitterThresholdAndTerms) {
    const WearMaterial w = steel();
    const double compliance = (1.0 - 0.17 * 0.17) / 70e9 + (1.0 - 0.09) / 210e9;
    const double dk = std::numbers::pi * std::numbers::pi / (2.0 * std::sqrt(10.0)) * std::pow(1.59 * 0.35e9, 2.5) *
                      std::sqrt(1.0 / 2650.0) * compliance * compliance;
    EXPECT_NEAR(bitter_threshold_speed(w, grain), dk, 1e-12 * dk);
    EXPECT_NEAR(dk, 0.0735, 0.0005);  // 0.043 m/s with the steel's density, as eq. 26 is printed
    EXPECT_EQ(bitter_deformation_volume(w, grain, 0.99 * dk, 90.0 * deg), 0.0);
    EXPECT_EQ(bitter_deformation_volume(w, grain, 2.0 * dk, 20.0 * deg), 0.0);  // 2 dk sin 20 < dk
    const double u = 10.0, a = 60.0 * deg;
    const double deformation = grain.mass * std::pow(u * std::sin(a) - dk, 2) / (2.0 * w.bitter_deformation_factor);
    EXPECT_NEAR(bitter_deformation_volume(w, grain, u, a), deformation, 1e-12 * deformation);
    const double ck = std::sqrt(3.0 * 1.18e9 / 2650.0);
    const double cutting = 100.0 / (2.0 * std::sqrt(29.0)) * std::pow(0.5e-3, 3) * std::pow(u / ck, 2.3) *
                           std::sin(2.0 * a) * std::sqrt(std::sin(a));
    EXPECT_NEAR(bitter_cutting_volume(w, grain, u, a), cutting, 1e-12 * cutting);
    EXPECT_NEAR(bitter_volume(w, grain, u, a), cutting + deformation, 1e-12 * (cutting + deformation));
}

// The built-in E_f is Oka's: at the reference (1 mm quartz, 20 m/s) Bitter's normal-incidence term per
// kilogram, V^2 / (2 E_f), is Oka's E90 for each wall material. By hand for steel (Hv 1.18 GPa):
// E90 = 65 * 1.18^-0.12 (20/104)^(2.3 * 1.18^0.038) (1000/326)^0.19 = 1.74 mm^3/kg, so E_f = 400 / (2 * 1.74e-9)
// = 1.15e11 J/m^3; at 104 m/s E90 = 78.8 mm^3/kg and E_f = 6.9e10.
TEST(WearModels, BitterDeformationFactorIsDerivedFromOka) {
    for (const auto& w : wear_material_library()) {
        EXPECT_EQ(w.bitter_calibration_speed, 20.0) << w.name;
        EXPECT_EQ(w.bitter_calibration_diameter, 1e-3) << w.name;
        const double e90 = oka_e90(w, 20.0, 1e-3) * 1e-9;  // [m^3/kg]
        EXPECT_NEAR(20.0 * 20.0 / (2.0 * w.bitter_deformation_factor), e90, 1e-12 * e90) << w.name;
    }
    const WearMaterial s = steel();
    const double k2 = 2.3 * std::pow(1.18, 0.038);
    const double e90 = 65.0 * std::pow(1.18, -0.12) * std::pow(20.0 / 104.0, k2) * std::pow(1e-3 / 326e-6, 0.19);
    EXPECT_NEAR(e90, 1.74, 0.01);
    EXPECT_NEAR(s.bitter_deformation_factor, 400.0 / (2.0 * e90 * 1e-9), 1e-9 * s.bitter_deformation_factor);
    EXPECT_NEAR(s.bitter_deformation_factor, 1.15e11, 0.01e11);
    EXPECT_NEAR(bitter_deformation_factor_from_oka(s, 104.0, 1e-3), 6.86e10, 0.01e10);
    // Through the whole model: a normal impact well above D_k removes Oka's E90 less Bitter's threshold.
    const double v = bitter_deformation_volume(s, grain, 20.0, 90.0 * deg) / grain.mass;
    const double dk = bitter_threshold_speed(s, grain);
    EXPECT_NEAR(v, e90 * 1e-9 * std::pow(1.0 - dk / 20.0, 2), 1e-12 * v);
}

// Oka: E90 = K Hv^k1 (V/V')^k2 (D/D')^k3 with the Part 2 exponents, and g peaks where
// sin a = n1 (1 + Hv) / (Hv (n1 + n2)).
TEST(WearModels, OkaHandValueAndPeak) {
    for (const double hv : {0.36, 1.18, 1.8}) {
        WearMaterial w = steel();
        w.vickers_hardness = hv;
        const double n1 = 0.71 * std::pow(hv, 0.14), n2 = 2.4 * std::pow(hv, -0.94), k2 = 2.3 * std::pow(hv, 0.038);
        const double e90 = 65.0 * std::pow(hv, -0.12) * std::pow(50.0 / 104.0, k2) * std::pow(1e-3 / 326e-6, 0.19);
        EXPECT_NEAR(oka_e90(w, 50.0, 1e-3), e90, 1e-12 * e90);
        const double s = n1 * (1.0 + hv) / (hv * (n1 + n2));
        const double expected = s < 1.0 ? std::asin(s) / deg : 90.0;
        EXPECT_NEAR(peak_of([&](double a) { return oka_angle_function(w, a); }), expected, 0.002) << hv;
        const double a = 40.0 * deg;
        const double volume =
            grain.mass * e90 * std::pow(std::sin(a), n1) * std::pow(1.0 + hv * (1.0 - std::sin(a)), n2) * 1e-9;
        EXPECT_NEAR(oka_volume(w, grain, 50.0, a), volume, 1e-12 * volume);
    }
}

TEST(WearModels, LiggghtsFormIsFinnieWithKTwo) {
    for (int a = 1; a <= 90; ++a)
        EXPECT_NEAR(liggghts_angle_function(a * deg), finnie_angle_function(a * deg, 2.0), 1e-14);
    EXPECT_NEAR(liggghts_mass_rate(steel(), 3.0, 2.0, 90.0 * deg), 0.0, 1e-15);
    EXPECT_NEAR(liggghts_mass_rate(steel(), 3.0, 2.0, 30.0 * deg), 2.0 * 1.0 * 3.0 * 2.0 * 0.25, 1e-12);
}

// The models' peaks per kilogram of 1 mm quartz, as docs/theory.md tabulates them ("Wear models: the three
// models side by side"): with each one's own sourced constants Finnie's peak is 9.4x Oka's on steel at
// 20 m/s and Bitter's (its cutting term) 24x; the ratios are the constants', not the physics' (hand values
// from an independent scan of the printed formulas, to 1 %).
TEST(WearModels, PeaksOfTheModelsAgainstOkas) {
    struct Row {
        const char* wall;
        double speed, finnie_over_oka, bitter_over_oka;
    };
    for (const Row& r : {Row{"steel", 20.0, 9.43, 23.88}, Row{"steel", 104.0, 5.61, 23.17},
                         Row{"aluminium", 20.0, 18.12, 54.26}, Row{"aluminium", 104.0, 12.76, 62.55}}) {
        const WearMaterial w = *find_wear_material(r.wall);
        auto per_kg_peak = [&](auto volume) {
            return volume(w, grain, r.speed, peak_of([&](double a) { return volume(w, grain, r.speed, a); }) * deg) /
                   grain.mass;
        };
        const double finnie = per_kg_peak(finnie_volume), bitter = per_kg_peak(bitter_volume),
                     oka = per_kg_peak(oka_volume);
        EXPECT_NEAR(finnie / oka, r.finnie_over_oka, 0.01 * r.finnie_over_oka) << r.wall << " " << r.speed;
        EXPECT_NEAR(bitter / oka, r.bitter_over_oka, 0.01 * r.bitter_over_oka) << r.wall << " " << r.speed;
    }
}
