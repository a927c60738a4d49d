// Equations of state against hand-computed values; their inverses; the tension branch.
#include <gtest/gtest.h>

#include <cmath>

#include "grit/material/equation_of_state.hpp"
#include "grit/material/library.hpp"

using grit::material::MieGruneisenEos;
using grit::material::TaitEos;

TEST(EquationOfState, TaitValuesAndInverse) {
    const TaitEos eos{1000.0, 30.0, 7.0};
    const double B = 1000.0 * 900.0 / 7.0;
    EXPECT_DOUBLE_EQ(eos.pressure(1000.0), 0.0);
    EXPECT_NEAR(eos.pressure(1010.0), B * (std::pow(1.01, 7) - 1.0), 1e-9 * B);
    EXPECT_NEAR(eos.pressure(990.0), B * (std::pow(0.99, 7) - 1.0), 1e-9 * B);  // tension
    EXPECT_LT(eos.pressure(990.0), 0.0);
    for (double p : {-5000.0, 0.0, 1234.5, 2.0e5}) EXPECT_NEAR(eos.pressure(eos.density(p)), p, 1e-9 * B);
}

TEST(EquationOfState, MieGruneisenWaterOfTable1) {
    // Table 1: rho0 = 1000, c0 = 1480, Gamma0 = 0.5, a = 0, S1 = 2.56, S2 = 1.98, S3 = 1.23.
    const auto water = grit::material::find_in_library("water");
    ASSERT_TRUE(water.has_value());
    const auto& eos = std::get<MieGruneisenEos>(water->eos);
    const double mu = 0.1, k = 1000.0 * 1480.0 * 1480.0;
    // Hand computation of eq. (24) with e = 0.
    const double num = k * mu * (1.0 + (1.0 - 0.25) * mu);
    const double den = 1.0 - 1.56 * mu - 1.98 * mu * mu / 1.1 - 1.23 * mu * mu * mu / (1.1 * 1.1);
    EXPECT_NEAR(eos.pressure(1100.0), num / (den * den), 1e-9 * k);
    EXPECT_NEAR(eos.pressure(1100.0), 3.4597e8, 1e5);  // 0.346 GPa at 10 % compression
    // Tension branch: linear, p = rho0 c0^2 mu.
    EXPECT_NEAR(eos.pressure(995.0), k * (-0.005), 1e-6);
    // Energy term: + rho0 (Gamma0 + a mu) e.
    EXPECT_NEAR(eos.pressure(1000.0, 2.0e4), 1000.0 * 0.5 * 2.0e4, 1e-6);
    for (double p : {-1.0e6, 0.0, 2.0e7, 3.0e8}) EXPECT_NEAR(eos.pressure(eos.density(p)), p, 1e-6 * std::abs(p) + 1e-3);
}

TEST(EquationOfState, LibraryDescribesEveryMaterial) {
    for (const auto& m : grit::material::library()) {
        EXPECT_FALSE(m.description.empty()) << m.name;
        EXPECT_NE(grit::material::describe(m).find(m.name), std::string::npos);
        EXPECT_GT(m.reference_density(), 0.0);
        EXPECT_GT(m.sound_speed(), 0.0);
    }
}
