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

// Eq. 26 by hand for steel and quartz: D_k = pi^2/(2 sqrt 10) (1.59 Y)^2.5 sqrt(R_f/rho_t) K^2; below it in
// the normal component the deformation term is zero, above it M (U sin a - D_k)^2 / (2 E_f).
TEST(WearModels, BitterThresholdAndTerms) {
    const WearMaterial w = steel();
    const double compliance = (1.0 - 0.17 * 0.17) / 70e9 + (1.0 - 0.09) / 210e9;
    const double dk = std::numbers::pi * std::numbers::pi / (2.0 * std::sqrt(10.0)) * std::pow(1.59 * 0.35e9, 2.5) *
                      std::sqrt(1.0 / 7850.0) * compliance * compliance;
    EXPECT_NEAR(bitter_threshold_speed(w, grain), dk, 1e-12 * dk);
    EXPECT_GT(dk, 0.01);
    EXPECT_LT(dk, 1.0);  // 0.043 m/s: a fraction of a metre per second
    EXPECT_EQ(bitter_deformation_volume(w, grain, 0.99 * dk, 90.0 * deg), 0.0);
    EXPECT_EQ(bitter_deformation_volume(w, grain, 2.0 * dk, 20.0 * deg), 0.0);  // 2 dk sin 20 < dk
    const double u = 10.0, a = 60.0 * deg;
    const double deformation = grain.mass * std::pow(u * std::sin(a) - dk, 2) / (2.0 * 7.7e9);
    EXPECT_NEAR(bitter_deformation_volume(w, grain, u, a), deformation, 1e-12 * deformation);
    const double ck = std::sqrt(3.0 * 1.18e9 / 2650.0);
    const double cutting = 100.0 / (2.0 * std::sqrt(29.0)) * std::pow(0.5e-3, 3) * std::pow(u / ck, 2.3) *
                           std::sin(2.0 * a) * std::sqrt(std::sin(a));
    EXPECT_NEAR(bitter_cutting_volume(w, grain, u, a), cutting, 1e-12 * cutting);
    EXPECT_NEAR(bitter_volume(w, grain, u, a), cutting + deformation, 1e-12 * (cutting + deformation));
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
