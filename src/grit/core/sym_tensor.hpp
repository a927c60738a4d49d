// Symmetric 3x3 tensor (stress, strain rate) stored as 6 components; 3x3 in 2D too (plane strain),
// because sigma_zz enters von Mises, Johnson-Cook and JH-2.
#pragma once

#include <cmath>

namespace grit::core {

/// Components xx, yy, zz, xy, yz, zx.
struct SymTensor3 {
    double xx = 0.0, yy = 0.0, zz = 0.0, xy = 0.0, yz = 0.0, zx = 0.0;

    static constexpr SymTensor3 zero() noexcept { return {}; }
    static constexpr SymTensor3 identity() noexcept { return {1.0, 1.0, 1.0, 0.0, 0.0, 0.0}; }

    constexpr double trace() const noexcept { return xx + yy + zz; }
    /// The deviatoric part, s = t - tr(t)/3 I.
    constexpr SymTensor3 deviator() const noexcept {
        const double m = trace() / 3.0;
        return {xx - m, yy - m, zz - m, xy, yz, zx};
    }
    /// s : s (double contraction).
    constexpr double contract(const SymTensor3& o) const noexcept {
        return xx * o.xx + yy * o.yy + zz * o.zz + 2.0 * (xy * o.xy + yz * o.yz + zx * o.zx);
    }
    /// Von Mises equivalent of a deviatoric tensor: sqrt(3/2 s:s).
    double von_mises() const noexcept { return std::sqrt(1.5 * contract(*this)); }

    constexpr SymTensor3& operator+=(const SymTensor3& o) noexcept {
        xx += o.xx; yy += o.yy; zz += o.zz; xy += o.xy; yz += o.yz; zx += o.zx;
        return *this;
    }
    constexpr SymTensor3& operator*=(double s) noexcept {
        xx *= s; yy *= s; zz *= s; xy *= s; yz *= s; zx *= s;
        return *this;
    }
};

constexpr SymTensor3 operator+(SymTensor3 a, const SymTensor3& b) noexcept { return a += b; }
constexpr SymTensor3 operator-(SymTensor3 a, const SymTensor3& b) noexcept {
    a += SymTensor3{-b.xx, -b.yy, -b.zz, -b.xy, -b.yz, -b.zx};
    return a;
}
constexpr SymTensor3 operator*(SymTensor3 a, double s) noexcept { return a *= s; }
constexpr SymTensor3 operator*(double s, SymTensor3 a) noexcept { return a *= s; }

}  // namespace grit::core
