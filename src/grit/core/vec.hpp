// Small fixed-size vector used for positions, velocities and forces in 2D and 3D.
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

namespace grit::core {

/// A Dim-component vector of doubles; a plain aggregate so arrays of it are flat and GPU-friendly.
template <int Dim>
struct Vec {
    static_assert(Dim == 2 || Dim == 3, "grit supports 2D and 3D");
    double c[Dim];

    static constexpr Vec zero() noexcept {
        Vec v{};
        for (int k = 0; k < Dim; ++k) v.c[k] = 0.0;
        return v;
    }
    static constexpr Vec filled(double s) noexcept {
        Vec v{};
        for (int k = 0; k < Dim; ++k) v.c[k] = s;
        return v;
    }
    constexpr double& operator[](int k) noexcept { return c[k]; }
    constexpr const double& operator[](int k) const noexcept { return c[k]; }

    constexpr Vec& operator+=(const Vec& o) noexcept {
        for (int k = 0; k < Dim; ++k) c[k] += o.c[k];
        return *this;
    }
    constexpr Vec& operator-=(const Vec& o) noexcept {
        for (int k = 0; k < Dim; ++k) c[k] -= o.c[k];
        return *this;
    }
    constexpr Vec& operator*=(double s) noexcept {
        for (int k = 0; k < Dim; ++k) c[k] *= s;
        return *this;
    }
};

template <int Dim>
constexpr Vec<Dim> operator+(Vec<Dim> a, const Vec<Dim>& b) noexcept { return a += b; }
template <int Dim>
constexpr Vec<Dim> operator-(Vec<Dim> a, const Vec<Dim>& b) noexcept { return a -= b; }
template <int Dim>
constexpr Vec<Dim> operator-(Vec<Dim> a) noexcept { return a *= -1.0; }
template <int Dim>
constexpr Vec<Dim> operator*(Vec<Dim> a, double s) noexcept { return a *= s; }
template <int Dim>
constexpr Vec<Dim> operator*(double s, Vec<Dim> a) noexcept { return a *= s; }

template <int Dim>
constexpr double dot(const Vec<Dim>& a, const Vec<Dim>& b) noexcept {
    double s = 0.0;
    for (int k = 0; k < Dim; ++k) s += a.c[k] * b.c[k];
    return s;
}
template <int Dim>
constexpr double norm2(const Vec<Dim>& a) noexcept { return dot(a, a); }
template <int Dim>
inline double norm(const Vec<Dim>& a) noexcept { return std::sqrt(norm2(a)); }

/// a x b (3D).
constexpr Vec<3> cross(const Vec<3>& a, const Vec<3>& b) noexcept {
    return {{a.c[1] * b.c[2] - a.c[2] * b.c[1], a.c[2] * b.c[0] - a.c[0] * b.c[2], a.c[0] * b.c[1] - a.c[1] * b.c[0]}};
}

template <int Dim>
constexpr bool all_finite(const Vec<Dim>& a) noexcept {
    for (int k = 0; k < Dim; ++k)
        if (!std::isfinite(a.c[k])) return false;
    return true;
}

/// The first Dim values of `v` (a case file's array, already checked to have Dim numbers).
template <int Dim>
Vec<Dim> to_vec(const std::vector<double>& v) {
    Vec<Dim> x{};
    for (int k = 0; k < Dim; ++k) x[k] = v[static_cast<std::size_t>(k)];
    return x;
}

/// x as three numbers, the last 0 in 2D (the rows of the CSV logs).
template <int Dim>
std::array<double, 3> to_array3(const Vec<Dim>& x) noexcept {
    std::array<double, 3> a{};
    for (int k = 0; k < Dim; ++k) a[static_cast<std::size_t>(k)] = x[k];
    return a;
}

}  // namespace grit::core
