// Johnson-Holmquist (JH-2) strength, damage and bulking for brittle solids (laws only); first seed paper
// eqs. (38), (39) and (41), Table 3; Johnson & Holmquist (1994), Holmquist & Johnson (2005, 2011).
// Strengths are normalised by sigma_HEL and pressures by P_HEL, as the paper writes them.
#pragma once

#include <cmath>

namespace grit::material {

/// JH-2 strength, eq. (38), in normalised form:
///   intact     sigma_i* = A (P* + T*)^N (1 + C ln rate*)
///   fractured  sigma_f* = B (P*)^M (1 + C ln rate*), at most sigma_fmax*
///   damaged    sigma*   = sigma_i* - D (sigma_i* - sigma_f*)
/// with P* = p / P_HEL, sigma = sigma* sigma_HEL and rate* = max(rate / rate0, 1) (below the reference
/// rate the factor is 1, as for Johnson-Cook). The intact strength is zero at or below P* = -T* (the
/// material holds no shear where it is torn hydrostatically); the fractured one is zero in tension.
struct JH2Strength {
    double A = 0.0;  ///< intact strength coefficient [-]
    double N = 1.0;  ///< intact strength exponent [-]
    double B = 0.0;  ///< fractured strength coefficient [-]
    double M = 1.0;  ///< fractured strength exponent [-]
    double C = 0.0;  ///< strain-rate coefficient [-]
    double tensile_strength = 0.0;        ///< T* = T / P_HEL, normalised hydrostatic tensile strength [-]
    double max_fractured_strength = 0.0;  ///< sigma_fmax* [-]
    double hel_pressure = 1.0;            ///< P_HEL, pressure at the Hugoniot elastic limit [Pa]
    double hel_stress = 1.0;              ///< sigma_HEL, equivalent stress at the HEL [Pa]
    double reference_strain_rate = 1.0;   ///< eps0_dot [1/s]

    double rate_factor(double strain_rate) const noexcept {
        const double r = strain_rate / reference_strain_rate;
        return r > 1.0 ? 1.0 + C * std::log(r) : 1.0;
    }
    /// sigma_i* at pressure p [Pa] (positive in compression).
    double intact(double p, double strain_rate) const noexcept {
        const double s = p / hel_pressure + tensile_strength;
        return s > 0.0 ? A * std::pow(s, N) * rate_factor(strain_rate) : 0.0;
    }
    /// sigma_f* at pressure p [Pa].
    double fractured(double p, double strain_rate) const noexcept {
        const double s = p / hel_pressure;
        if (!(s > 0.0)) return 0.0;
        const double sf = B * std::pow(s, M) * rate_factor(strain_rate);
        return sf < max_fractured_strength ? sf : max_fractured_strength;
    }
    /// Equivalent (von Mises) strength sigma = sigma* sigma_HEL [Pa] at damage D.
    double yield_stress(double p, double damage, double strain_rate) const noexcept {
        const double si = intact(p, strain_rate);
        const double d = damage < 0.0 ? 0.0 : damage > 1.0 ? 1.0 : damage;
        return (si - d * (si - fractured(p, strain_rate))) * hel_stress;
    }
    /// Hydrostatic tensile strength T = T* P_HEL [Pa].
    double tensile_pressure() const noexcept { return tensile_strength * hel_pressure; }
};

/// JH-2 plastic strain to fracture, eq. (39): eps_f = D1 (P* + T*)^D2, D += d eps_p / eps_f.
/// At P* <= -T* eps_f would be zero: the floor `min_failure_strain` keeps the sum finite, so plastic
/// strain there fractures the point within a step or two.
struct JH2Failure {
    double D1 = 0.0, D2 = 1.0;
    double min_failure_strain = 1e-6;  ///< [-]

    double failure_strain(double p, const JH2Strength& s) const noexcept {
        const double x = p / s.hel_pressure + s.tensile_strength;
        const double eps_f = x > 0.0 ? D1 * std::pow(x, D2) : 0.0;
        return eps_f > min_failure_strain ? eps_f : min_failure_strain;
    }
};

/// Bulking pressure after one step, eq. (41): the loss of deviatoric elastic energy dU >= 0 [J/m^3]
/// (U = sigma_y^2 / 6G, Johnson & Holmquist 1994) turns, with fraction beta, into potential hydrostatic
/// energy: dp_{n+1} = -K1 mu + sqrt((K1 mu + dp_n)^2 + 2 beta K1 dU).
inline double bulking_pressure(double previous, double mu, double bulk_modulus, double beta, double energy_loss) noexcept {
    const double k_mu = bulk_modulus * mu;
    const double loss = energy_loss > 0.0 ? energy_loss : 0.0;
    return -k_mu + std::sqrt((k_mu + previous) * (k_mu + previous) + 2.0 * beta * bulk_modulus * loss);
}

/// Pressure of a JH-2 point from the polynomial EOS value `eos_pressure` (eq. 40 without dp): the bulking
/// increment adds in compression (mu >= 0) only, as eq. (40) writes it, and tension is limited to the
/// damaged hydrostatic strength -T (1 - D): intact rock holds T, fractured rock (D = 1) holds no tension.
inline double jh2_pressure(double eos_pressure, double mu, double bulking, double damage, double tensile_pressure) noexcept {
    const double p = mu >= 0.0 ? eos_pressure + bulking : eos_pressure;
    const double intact = damage < 0.0 ? 1.0 : damage > 1.0 ? 0.0 : 1.0 - damage;
    const double floor = -tensile_pressure * intact;
    return p > floor ? p : floor;
}

}  // namespace grit::material
