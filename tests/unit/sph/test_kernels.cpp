// Kernel properties over every kernel, in 2D and 3D: unit integral, gradient consistent with the value
// (and antisymmetric), compact support of radius 2h, and the published normalisation constants.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "grit/core/vec.hpp"
#include "grit/sph/kernels.hpp"

namespace {

template <int Dim, class K>
double integral(const K& k) {
    // Radial quadrature: int W dV = int_0^2h W(r) S_d r^(d-1) dr, S_2 = 2 pi, S_3 = 4 pi.
    const int n = 200000;
    const double R = k.support(), dr = R / n;
    double s = 0.0;
    for (int i = 0; i < n; ++i) {
        const double r = (i + 0.5) * dr;
        s += k.value(r) * (Dim == 2 ? 2.0 * std::numbers::pi * r : 4.0 * std::numbers::pi * r * r) * dr;
    }
    return s;
}

template <int Dim, class K>
double lattice_sum(const K& k, double dx) {
    // sum_b W_ab dx^d over a regular lattice: the discrete partition of unity.
    const int m = static_cast<int>(std::ceil(k.support() / dx)) + 1;
    double s = 0.0;
    for (int i = -m; i <= m; ++i)
        for (int j = -m; j <= m; ++j)
            for (int l = (Dim == 3 ? -m : 0); l <= (Dim == 3 ? m : 0); ++l)
                s += k.value(dx * std::sqrt(double(i * i + j * j + l * l)));
    return s * std::pow(dx, Dim);
}

template <int Dim, class K>
void check_kernel(const K& k) {
    EXPECT_NEAR(integral<Dim>(k), 1.0, 1e-6);
    EXPECT_NEAR(lattice_sum<Dim>(k, k.h / 2.0), 1.0, 0.01);  // discrete partition of unity, h = 2 dx
    EXPECT_LT(k.value(k.support()), 1e-12 * k.value(0.0));  // zero up to the round-off of r / h
    EXPECT_EQ(k.value(1.5 * k.support()), 0.0);
    EXPECT_EQ(k.gradient_factor(k.support() * 1.0001), 0.0);
    EXPECT_GT(k.value(0.999 * k.support()), 0.0);
    // gradient_factor(r) * r is dW/dr: compare with a central difference.
    for (double q : {0.05, 0.3, 0.9, 1.0, 1.1, 1.7, 1.95}) {
        const double r = q * k.h, d = 1e-6 * k.h;
        const double numeric = (k.value(r + d) - k.value(r - d)) / (2 * d);
        EXPECT_NEAR(k.gradient_factor(r) * r, numeric, 1e-6 * std::abs(numeric) + 1e-9 * k.value(0.0) / k.h)
            << "q = " << q;
        EXPECT_LT(k.gradient_factor(r), 0.0);  // W decreases outwards: grad_a W_ab = -grad_b W_ba
    }
    EXPECT_TRUE(std::isfinite(k.gradient_factor(0.0)));
}

}  // namespace

TEST(Kernels, CubicSpline2D) { check_kernel<2>(grit::sph::CubicSpline<2>(0.013)); }
TEST(Kernels, CubicSpline3D) { check_kernel<3>(grit::sph::CubicSpline<3>(0.7)); }
TEST(Kernels, WendlandC2_2D) { check_kernel<2>(grit::sph::WendlandC2<2>(2.0e-4)); }
TEST(Kernels, WendlandC2_3D) { check_kernel<3>(grit::sph::WendlandC2<3>(1.1)); }

TEST(Kernels, PublishedNormalisation) {
    const double h = 0.5;
    // First seed paper eq. (17): a_d = 15 / (7 pi h^2) in 2D; W(0) = 2/3 a_d.
    EXPECT_DOUBLE_EQ(grit::sph::CubicSpline<2>(h).value(0.0), 2.0 / 3.0 * 15.0 / (7.0 * std::numbers::pi * h * h));
    // Second seed paper eq. (5): alpha_D = 21 / (16 pi h^3) in 3D; W(0) = alpha_D.
    EXPECT_DOUBLE_EQ(grit::sph::WendlandC2<3>(h).value(0.0), 21.0 / (16.0 * std::numbers::pi * h * h * h));
}

TEST(Kernels, ChosenByName) {
    grit::sph::Kernel<2> k = grit::sph::CubicSpline<2>(1.0);
    EXPECT_TRUE(grit::sph::make_kernel<2>("wendland_c2", 0.1, k));
    EXPECT_TRUE(std::holds_alternative<grit::sph::WendlandC2<2>>(k));
    EXPECT_FALSE(grit::sph::make_kernel<2>("gaussian", 0.1, k));
}

TEST(Kernels, GradientIsAntisymmetric) {
    // grad_a W_ab = x_ab F(r) = -grad_b W_ba, for both kernels and both dimensions.
    const grit::core::Vec<3> xa{{0.01, 0.02, -0.03}}, xb{{-0.05, 0.04, 0.02}};
    const auto xab = xa - xb, xba = xb - xa;
    auto check = [&](const auto& k) {
        const auto ga = xab * k.gradient_factor(grit::core::norm(xab));
        const auto gb = xba * k.gradient_factor(grit::core::norm(xba));
        for (int d = 0; d < 3; ++d) EXPECT_EQ(ga[d], -gb[d]);
        EXPECT_NE(ga[0], 0.0);
    };
    check(grit::sph::CubicSpline<3>(0.1));
    check(grit::sph::WendlandC2<3>(0.1));
}
