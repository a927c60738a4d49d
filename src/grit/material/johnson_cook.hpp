// Johnson-Cook strength and failure (laws only); first seed paper eqs. (33)-(36), Table 2.
#pragma once

#include <algorithm>
#include <cmath>

namespace grit::material {

/// Homologous temperature T* = (T - T0)/(Tm - T0), eq. (34), clamped to [0, 1].
inline double homologous_temperature(double T, double room_temperature, double melt_temperature) noexcept {
    return std::clamp((T - room_temperature) / (melt_temperature - room_temperature), 0.0, 1.0);
}

/// Johnson-Cook flow stress, Johnson & Cook (1983); eq. (33):
/// sigma_y = [A + B eps_p^n] [1 + C ln(rate*)] [1 - T*^m], rate* = max(rate / rate0, 1).
/// Below the reference rate the rate factor is 1 (the usual LS-DYNA / Abaqus convention), so the
/// logarithm never lowers the strength or diverges at zero rate.
struct JohnsonCookStrength {
    double A = 0.0;        ///< initial yield stress [Pa]
    double B = 0.0;        ///< hardening modulus [Pa]
    double n = 1.0;        ///< hardening exponent (N in Table 2) [-]
    double C = 0.0;        ///< strain-rate coefficient [-]
    double m = 1.0;        ///< thermal softening exponent (M in Table 2) [-]
    double reference_strain_rate = 1.0;  ///< eps0_dot [1/s]
    double room_temperature = 293.0;     ///< T0 [K]
    double melt_temperature = 1790.0;    ///< Tm [K]

    double yield_stress(double plastic_strain, double plastic_strain_rate, double temperature) const noexcept {
        const double hardening = A + B * std::pow(std::max(plastic_strain, 0.0), n);
        const double rate = std::max(plastic_strain_rate / reference_strain_rate, 1.0);
        const double thermal =
            1.0 - std::pow(homologous_temperature(temperature, room_temperature, melt_temperature), m);
        return hardening * (1.0 + C * std::log(rate)) * thermal;
    }
};

/// Johnson-Cook failure strain, Johnson & Cook (1985); eq. (35):
/// eps_f = [D1 + D2 exp(D3 sigma*)] [1 + D4 ln(rate*)] [1 + D5 T*], sigma* = sigma_m / sigma_vm, with
/// the mean stress sigma_m = -p positive in tension (so D3 < 0 makes tension more damaging).
struct JohnsonCookFailure {
    double D1 = 0.0, D2 = 0.0, D3 = 0.0, D4 = 0.0, D5 = 0.0;
    double reference_strain_rate = 1.0;  ///< [1/s]
    double room_temperature = 293.0;     ///< [K]
    double melt_temperature = 1790.0;    ///< [K]

    double failure_strain(double triaxiality, double plastic_strain_rate, double temperature) const noexcept {
        const double rate = std::max(plastic_strain_rate / reference_strain_rate, 1.0);
        const double t = homologous_temperature(temperature, room_temperature, melt_temperature);
        const double eps_f = (D1 + D2 * std::exp(D3 * triaxiality)) * (1.0 + D4 * std::log(rate)) * (1.0 + D5 * t);
        return std::max(eps_f, 1e-6);  // a tiny floor keeps eq. (36) finite for extreme triaxialities
    }
};

}  // namespace grit::material
