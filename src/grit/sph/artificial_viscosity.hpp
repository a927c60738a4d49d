// Monaghan artificial viscosity (law only); first seed paper eqs. (26)-(27).
#pragma once

#include <algorithm>

#include "grit/sph/pair_coefficients.hpp"

namespace grit::sph {

/// Pi_ab = (-alpha c_ab phi_ab + beta phi_ab^2) / rho_ab for approaching pairs (v_ab . x_ab < 0), else 0;
/// phi_ab = h v_ab . x_ab / (|x_ab|^2 + (0.1 h)^2). Monaghan (1992). Coefficients and sound speed are the
/// means of the pair's materials. Written without a branch (phi = 0 for receding pairs) so pair loops
/// vectorise; the caller passes the reciprocals it already has.
/// vx = v_ab . x_ab; inv_r2 = 1 / (|x_ab|^2 + 0.01 h^2); inv_rho_sum = 1 / (rho_a + rho_b).
inline double artificial_viscosity(double h, double vx, double inv_r2, double inv_rho_sum, const PairCoefficients& ca,
                                   const PairCoefficients& cb) noexcept {
    const double phi = h * std::min(vx, 0.0) * inv_r2;
    const double alpha = 0.5 * (ca.alpha + cb.alpha), beta = 0.5 * (ca.beta + cb.beta);
    const double sound_speed = 0.5 * (ca.sound_speed + cb.sound_speed);
    return (-alpha * sound_speed * phi + beta * phi * phi) * 2.0 * inv_rho_sum;  // / rho_ab
}

}  // namespace grit::sph
