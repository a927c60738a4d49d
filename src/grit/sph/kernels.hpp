// SPH smoothing kernels (laws only): cubic spline (first seed paper eq. 17) and Wendland C2 (second seed
// paper eq. 5), normalised in 2D and 3D, both with support radius 2h.
#pragma once

#include <algorithm>
#include <numbers>
#include <string>
#include <variant>

namespace grit::sph {

/// Monaghan & Lattanzio (1985) cubic B-spline; first seed paper eq. (17).
template <int Dim>
struct CubicSpline {
    static constexpr const char* name = "cubic_spline";
    double h;      ///< smoothing length [m]
    double inv_h;  ///< 1/h [1/m]
    double sigma;  ///< normalisation a_d: 15/(7 pi h^2) in 2D, 3/(2 pi h^3) in 3D

    explicit CubicSpline(double smoothing_length)
        : h(smoothing_length),
          inv_h(1.0 / smoothing_length),
          sigma(Dim == 2 ? 15.0 / (7.0 * std::numbers::pi * h * h)
                         : 3.0 / (2.0 * std::numbers::pi * h * h * h)) {}

    double support() const noexcept { return 2.0 * h; }

    /// W(r) [1/m^Dim]
    double value(double r) const noexcept {
        const double q = r * inv_h;
        if (q < 1.0) return sigma * (2.0 / 3.0 - q * q + 0.5 * q * q * q);
        if (q < 2.0) {
            const double t = 2.0 - q;
            return sigma * t * t * t / 6.0;
        }
        return 0.0;
    }

    /// (1/r) dW/dr [1/m^(Dim+2)], finite at r = 0, so grad_a W_ab = x_ab * gradient_factor(r_ab).
    double gradient_factor(double r) const noexcept {
        const double q = r * inv_h;
        const double s = sigma * inv_h * inv_h;
        const double t = std::max(2.0 - q, 0.0);  // 0 beyond the support
        const double outer = -0.5 * t * t / std::max(q, 1.0);
        return s * (q < 1.0 ? -2.0 + 1.5 * q : outer);
    }
};

/// Wendland (1995) C2 kernel; second seed paper eq. (5): W = alpha_D (1 - q/2)^4 (2q + 1), q = r/h <= 2.
template <int Dim>
struct WendlandC2 {
    static constexpr const char* name = "wendland_c2";
    double h;      ///< smoothing length [m]
    double inv_h;  ///< 1/h [1/m]
    double sigma;  ///< alpha_D: 7/(4 pi h^2) in 2D, 21/(16 pi h^3) in 3D

    explicit WendlandC2(double smoothing_length)
        : h(smoothing_length),
          inv_h(1.0 / smoothing_length),
          sigma(Dim == 2 ? 7.0 / (4.0 * std::numbers::pi * h * h)
                         : 21.0 / (16.0 * std::numbers::pi * h * h * h)) {}

    double support() const noexcept { return 2.0 * h; }

    double value(double r) const noexcept {
        const double q = r * inv_h;
        if (q >= 2.0) return 0.0;
        const double t = 1.0 - 0.5 * q;
        const double t2 = t * t;
        return sigma * t2 * t2 * (2.0 * q + 1.0);
    }

    /// (1/r) dW/dr = -5 alpha_D (1 - q/2)^3 / h^2.
    double gradient_factor(double r) const noexcept {
        const double t = std::max(1.0 - 0.5 * r * inv_h, 0.0);  // 0 beyond the support
        return -5.0 * sigma * inv_h * inv_h * t * t * t;
    }
};

/// The kernels a case may choose by name; dispatched once per loop with std::visit.
template <int Dim>
using Kernel = std::variant<CubicSpline<Dim>, WendlandC2<Dim>>;

/// Names accepted for `numerics.kernel`.
inline constexpr const char* kernel_names[] = {"cubic_spline", "wendland_c2"};

/// Builds a kernel from its name; returns false if the name is unknown.
template <int Dim>
bool make_kernel(const std::string& name, double h, Kernel<Dim>& out) {
    if (name == CubicSpline<Dim>::name) {
        out = CubicSpline<Dim>(h);
        return true;
    }
    if (name == WendlandC2<Dim>::name) {
        out = WendlandC2<Dim>(h);
        return true;
    }
    return false;
}

}  // namespace grit::sph
