// Angular quantities of grains: a scalar (the z component) for discs in 2D, a 3-vector for spheres in
// 3D, and the two cross products the contact loops need.
#pragma once

#include <type_traits>

#include "grit/core/vec.hpp"

namespace grit::dem {

/// Angular velocity, torque or angular momentum: the z component in 2D (discs rotate in the plane), a
/// full vector in 3D.
template <int Dim>
using Spin = std::conditional_t<Dim == 2, double, core::Vec<3>>;

template <int Dim>
constexpr Spin<Dim> zero_spin() noexcept {
    if constexpr (Dim == 2) return 0.0;
    else return core::Vec<3>::zero();
}

/// w x r: the velocity of a point at r from the centre of a body spinning at w.
template <int Dim>
constexpr core::Vec<Dim> spin_cross(const Spin<Dim>& w, const core::Vec<Dim>& r) noexcept {
    if constexpr (Dim == 2) {
        return core::Vec<2>{{-w * r[1], w * r[0]}};
    } else {
        return core::Vec<3>{{w[1] * r[2] - w[2] * r[1], w[2] * r[0] - w[0] * r[2], w[0] * r[1] - w[1] * r[0]}};
    }
}

/// r x f: the torque of a force f applied at r from the centre.
template <int Dim>
constexpr Spin<Dim> moment(const core::Vec<Dim>& r, const core::Vec<Dim>& f) noexcept {
    if constexpr (Dim == 2) {
        return r[0] * f[1] - r[1] * f[0];
    } else {
        return core::Vec<3>{{r[1] * f[2] - r[2] * f[1], r[2] * f[0] - r[0] * f[2], r[0] * f[1] - r[1] * f[0]}};
    }
}

}  // namespace grit::dem
