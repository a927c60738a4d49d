// Monaghan artificial viscosity (law only); first seed paper eqs. (26)-(27).
#pragma once

namespace grit::sph {

/// Pi_ab = (-alpha c_ab phi_ab + beta phi_ab^2) / rho_ab for approaching pairs (v_ab . x_ab < 0),
/// phi_ab = h v_ab . x_ab / (|x_ab|^2 + (0.1 h)^2). Monaghan (1992).
struct ArtificialViscosity {
    double h;  ///< smoothing length [m]

    /// Pi_ab [m^5/(kg s^2)] for an approaching pair; vx = v_ab . x_ab (< 0), r2 = |x_ab|^2.
    double pi(double vx, double r2, double mean_sound_speed, double mean_density, double alpha,
              double beta) const noexcept {
        const double phi = h * vx / (r2 + 0.01 * h * h);
        return (-alpha * mean_sound_speed * phi + beta * phi * phi) / mean_density;
    }
};

}  // namespace grit::sph
