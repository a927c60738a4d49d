// Drag laws of the unresolved fluid-grain coupling, as pure functions: each gives the coefficient
// c = |F_d| / |u| [kg/s] (per metre of thickness in 2D) of the drag F_d = c u on a grain of volume V and
// diameter d, u = v_f - v_i its velocity relative to the fluid, eps the porosity at the grain.
//
// Every law is written per unit grain volume, so a 2D disc (V = pi d^2 / 4 per metre) takes the same
// formula as a sphere (V = pi d^3 / 6): the projected area of the single-particle laws is read as
// A = 1.5 V / d, which is pi d^2 / 4 for a sphere (docs/theory.md, "Drag in 2D").
#pragma once

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <string_view>

#include "grit/core/error.hpp"

namespace grit::coupling {

/// What a drag law needs to know of one grain and the fluid around it.
struct DragInput {
    double porosity = 1.0;       ///< eps_i, Shepard-interpolated at the grain (eq. 45) [-]
    double relative_speed = 0.0; ///< |v_f - v_i| [m/s]
    double diameter = 0.0;       ///< d_i [m]
    double volume = 0.0;         ///< V_i [m^3] (m^2 per metre in 2D)
    double fluid_density = 0.0;  ///< rho_f [kg/m^3]
    double viscosity = 0.0;      ///< mu_f [Pa s]
};

enum class DragLaw { gidaspow, di_felice, single_particle, single_particle_as_printed };

inline DragLaw make_drag_law(std::string_view name) {
    if (name == "gidaspow") return DragLaw::gidaspow;
    if (name == "di_felice") return DragLaw::di_felice;
    if (name == "single_particle") return DragLaw::single_particle;
    if (name == "single_particle_as_printed") return DragLaw::single_particle_as_printed;
    throw core::InputError("unknown drag law '" + std::string(name) +
                           "' (expected \"gidaspow\", \"di_felice\", \"single_particle\" or "
                           "\"single_particle_as_printed\")");
}

/// Schiller-Naumann drag coefficient of the first paper's eq. (48): 24/Re (1 + 0.15 Re^0.687) below
/// Re = 1000, 0.44 above.
inline double schiller_naumann(double re) {
    return re < 1000.0 ? 24.0 / re * (1.0 + 0.15 * std::pow(re, 0.687)) : 0.44;
}

/// Gidaspow (1994), the first paper's eqs. (44) and (47)-(49), read with ERRATA.md: Ergun for
/// eps < 0.8, Wen-Yu for eps >= 0.8. F_d = beta V (v_f - v_i) / (1 - eps); beta / (1 - eps) is formed
/// directly so that eps -> 1 (a lone grain) is not 0/0:
///   Ergun:  beta / (1-eps) = 150 (1-eps) mu / (eps d^2) + 1.75 rho |u| / d
///   Wen-Yu: beta / (1-eps) = 0.75 C_d eps rho |u| eps^-2.65 / d,  C_d(Re), Re = eps rho |u| d / mu.
inline double gidaspow_coefficient(const DragInput& in) {
    const double eps = in.porosity, d = in.diameter, rho = in.fluid_density, mu = in.viscosity;
    const double u = in.relative_speed;
    double beta_over = 0.0;
    if (eps < 0.8) {
        beta_over = 150.0 * (1.0 - eps) * mu / (eps * d * d) + 1.75 * rho * u / d;
    } else {
        const double re = eps * rho * u * d / mu;
        // C_d rho |u| stays finite as u -> 0: 24/Re rho |u| = 24 mu / (eps d).
        const double cd_rho_u = re > 0.0 ? schiller_naumann(re) * rho * u : 24.0 * mu / (eps * d);
        beta_over = 0.75 * cd_rho_u * eps * std::pow(eps, -2.65) / d;
    }
    return beta_over * in.volume;
}

/// Di Felice (1994): F_d = 1/2 C_d rho |u| u A eps^(2 - chi), C_d = (0.63 + 4.8 / sqrt(Re))^2,
/// chi = 3.7 - 0.65 exp(-(1.5 - log10 Re)^2 / 2), Re = eps rho |u| d / mu, A = 1.5 V / d.
inline double di_felice_coefficient(const DragInput& in) {
    const double eps = in.porosity, d = in.diameter, rho = in.fluid_density, mu = in.viscosity;
    const double u = in.relative_speed;
    const double area = 1.5 * in.volume / d;
    const double re = eps * rho * u * d / mu;
    if (!(re > 0.0)) {
        // Re -> 0: C_d |u| -> 4.8^2 mu / (eps rho d), and chi -> 3.7 - 0.65 exp(-inf) = 3.7.
        return 0.5 * 4.8 * 4.8 * mu / (eps * d) * area * std::pow(eps, 2.0 - 3.7);
    }
    const double s = 0.63 + 4.8 / std::sqrt(re);
    const double l = 1.5 - std::log10(re);
    const double chi = 3.7 - 0.65 * std::exp(-0.5 * l * l);
    return 0.5 * s * s * rho * u * area * std::pow(eps, 2.0 - chi);
}

/// The second paper's single-particle law, eqs. (18)-(19) with the velocity factor ERRATA.md restores:
/// Stokes F = 3 pi mu d u (written 18 mu V / d^2 u) below Re_p = 0.01, else
/// F = A rho |u| u (1.84 Re_p^-0.31 + 0.293 Re_p^0.06)^3.45, A = 1.5 V / d, Re_p = rho |u| d / mu.
/// No porosity: it is the drag of a lone grain.
inline double single_particle_coefficient(const DragInput& in) {
    const double d = in.diameter, rho = in.fluid_density, mu = in.viscosity, u = in.relative_speed;
    const double re = rho * u * d / mu;
    if (re < 0.01) return 18.0 * mu * in.volume / (d * d);
    const double f = 1.84 * std::pow(re, -0.31) + 0.293 * std::pow(re, 0.06);
    return 1.5 * in.volume / d * rho * u * std::pow(f, 3.45);
}

/// The second paper's eq. (19) exactly as printed, for comparison with its pictures (not a force: one
/// velocity factor short, ERRATA.md): |F| = A rho |u| (1.84 Re_p^-0.31 + 0.293 Re_p^0.06)^3.45 with |u| in m/s,
/// so c = A rho (...)^3.45, read in SI as kg/s. Below 1 m/s of slip it drags harder than the law it
/// misprints, by 1/|u|: a grain follows the water almost as a tracer. Stokes (eq. 18) below Re_p = 0.01.
inline double single_particle_as_printed_coefficient(const DragInput& in) {
    const double d = in.diameter, rho = in.fluid_density, mu = in.viscosity, u = in.relative_speed;
    const double re = rho * u * d / mu;
    if (re < 0.01) return 18.0 * mu * in.volume / (d * d);
    const double f = 1.84 * std::pow(re, -0.31) + 0.293 * std::pow(re, 0.06);
    return 1.5 * in.volume / d * rho * std::pow(f, 3.45);
}

/// c = |F_d| / |u| of the chosen law [kg/s].
inline double drag_coefficient(DragLaw law, const DragInput& in) {
    switch (law) {
        case DragLaw::gidaspow: return gidaspow_coefficient(in);
        case DragLaw::di_felice: return di_felice_coefficient(in);
        case DragLaw::single_particle: return single_particle_coefficient(in);
        case DragLaw::single_particle_as_printed: return single_particle_as_printed_coefficient(in);
    }
    return 0.0;
}

}  // namespace grit::coupling
