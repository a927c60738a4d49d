// Initial velocity profiles a solid block may start with (`velocity_profile` of a [[solid]] block).
#pragma once

#include <algorithm>
#include <cmath>

namespace grit::sim {

/// First bending mode of a clamped-free beam of length L, k L = 1.875 (Gray, Monaghan & Swift 2001):
/// W(s) = cosh ks - cos ks - sigma (sinh ks - sin ks), sigma = (cosh kL + cos kL) / (sinh kL + sin kL),
/// s the distance from the clamp, clamped to [0, L]. The plate's transverse velocity is V W(s) / W(L).
inline double cantilever_mode_shape(double s, double length) {
    const double kl = 1.87510407, wavenumber = kl / length;
    const double sigma = (std::cosh(kl) + std::cos(kl)) / (std::sinh(kl) + std::sin(kl));
    const double ks = wavenumber * std::clamp(s, 0.0, length);
    return std::cosh(ks) - std::cos(ks) - sigma * (std::sinh(ks) - std::sin(ks));
}

}  // namespace grit::sim
