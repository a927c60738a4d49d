// Equations of state (laws only): pressure from density (and specific internal energy), their inverse,
// and the tension branch. Weakly compressible Tait and the Mie-Grüneisen form of the first seed paper.
#pragma once

#include <cmath>
#include <string>
#include <variant>

namespace grit::material {

/// Tait (Cole 1948; Monaghan 1994): p = B [(rho/rho0)^gamma - 1], B = rho0 c0^2 / gamma.
/// The same formula holds in tension (rho < rho0); a material's pressure floor limits it.
struct TaitEos {
    static constexpr const char* name = "tait";
    double reference_density;  ///< rho0 [kg/m^3]
    double sound_speed;        ///< c0 [m/s]
    double gamma = 7.0;        ///< polytropic exponent [-]

    double stiffness() const noexcept { return reference_density * sound_speed * sound_speed / gamma; }

    /// p(rho) [Pa]; the internal energy does not enter.
    double pressure(double rho, double /*specific_energy*/ = 0.0) const noexcept {
        const double r = rho / reference_density;
        if (gamma == 7.0) {  // the usual exponent: multiplications instead of pow (4 % of a step)
            const double r2 = r * r;
            return stiffness() * (r2 * r2 * r2 * r - 1.0);
        }
        return stiffness() * (std::pow(r, gamma) - 1.0);
    }
    /// rho(p) [kg/m^3], the inverse of pressure(); p must exceed -B.
    double density(double p) const noexcept {
        return reference_density * std::pow(p / stiffness() + 1.0, 1.0 / gamma);
    }
};

/// Mie-Grüneisen with a cubic shock-velocity fit (LS-DYNA *EOS_GRUNEISEN form); first seed paper
/// eq. (24) with Table 1 for water and eq. (37) (s2 = s3 = a = 0) for metals.
/// Compression (mu > 0):
///   p = rho0 c0^2 mu [1 + (1 - Gamma0/2) mu - a/2 mu^2] / [1 - (S1-1) mu - S2 mu^2/(mu+1) - S3 mu^3/(mu+1)^2]^2
///       + rho0 (Gamma0 + a mu) e
/// Tension branch (mu < 0):  p = rho0 c0^2 mu + rho0 (Gamma0 + a mu) e.
/// mu = rho/rho0 - 1; e is the specific internal energy [J/kg]. The paper's eq. (24) prints
/// S3 eta^2/(eta+1)^2; the cited form (LS-DYNA manual) has S3 mu^3/(mu+1)^2, which we use.
struct MieGruneisenEos {
    static constexpr const char* name = "mie_gruneisen";
    double reference_density;  ///< rho0 [kg/m^3]
    double sound_speed;        ///< c0, intercept of the shock-velocity fit [m/s]
    double gruneisen_gamma;    ///< Gamma0 [-]
    double volume_correction = 0.0;  ///< a [-]
    double s1 = 1.0, s2 = 0.0, s3 = 0.0;  ///< shock-velocity fit coefficients [-]

    double cold_pressure(double mu) const noexcept {
        const double k = reference_density * sound_speed * sound_speed;
        if (mu < 0.0) return k * mu;
        const double a = volume_correction;
        const double num = k * mu * (1.0 + (1.0 - 0.5 * gruneisen_gamma) * mu - 0.5 * a * mu * mu);
        const double m1 = mu + 1.0;
        const double den = 1.0 - (s1 - 1.0) * mu - s2 * mu * mu / m1 - s3 * mu * mu * mu / (m1 * m1);
        return num / (den * den);
    }

    double pressure(double rho, double specific_energy = 0.0) const noexcept {
        const double mu = rho / reference_density - 1.0;
        return cold_pressure(mu) +
               reference_density * (gruneisen_gamma + volume_correction * mu) * specific_energy;
    }

    /// rho(p) at zero internal energy, by Newton iteration on mu (the cold curve is monotonic
    /// in the range of interest, mu < 1/(S1 - 1)).
    double density(double p) const noexcept {
        const double k = reference_density * sound_speed * sound_speed;
        if (p <= 0.0) return reference_density * (1.0 + p / k);
        double mu = p / k;
        for (int it = 0; it < 50; ++it) {
            const double f = cold_pressure(mu) - p;
            const double d = 1e-7 * (1.0 + mu);
            const double df = (cold_pressure(mu + d) - cold_pressure(mu - d)) / (2.0 * d);
            const double step = f / df;
            mu -= step;
            if (mu < 0.0) mu = 0.0;
            if (std::abs(step) < 1e-14 * (1.0 + mu)) break;
        }
        return reference_density * (1.0 + mu);
    }
};

/// Polynomial EOS of brittle solids (JH-2), first seed paper eq. (40) without the bulking increment
/// (which is per-point state, see johnson_holmquist.hpp):
///   p = K1 mu + K2 mu^2 + K3 mu^3 (mu >= 0),  p = K1 mu (mu < 0),  mu = rho/rho0 - 1.
/// The sound speed is the bulk one, sqrt(K1 / rho0), as c0 is for the metals' Mie-Grüneisen EOS.
struct PolynomialEos {
    static constexpr const char* name = "polynomial";
    double reference_density;  ///< rho0 [kg/m^3]
    double k1;                 ///< bulk modulus K1 [Pa]
    double k2 = 0.0;           ///< K2 [Pa]
    double k3 = 0.0;           ///< K3 [Pa]
    double sound_speed = std::sqrt(k1 / reference_density);  ///< sqrt(K1/rho0) [m/s]; keep it so

    PolynomialEos(double rho0, double bulk_modulus, double second = 0.0, double third = 0.0)
        : reference_density(rho0), k1(bulk_modulus), k2(second), k3(third) {}

    double cold_pressure(double mu) const noexcept {
        return mu < 0.0 ? k1 * mu : mu * (k1 + mu * (k2 + mu * k3));
    }
    /// p(rho) [Pa]; the internal energy does not enter.
    double pressure(double rho, double /*specific_energy*/ = 0.0) const noexcept {
        return cold_pressure(rho / reference_density - 1.0);
    }
    /// rho(p) [kg/m^3] by Newton iteration (the cubic rises monotonically for Table 3's rocks).
    double density(double p) const noexcept {
        if (p <= 0.0) return reference_density * (1.0 + p / k1);
        double mu = p / k1;
        for (int it = 0; it < 50; ++it) {
            const double slope = k1 + mu * (2.0 * k2 + 3.0 * k3 * mu);
            const double step = (cold_pressure(mu) - p) / slope;
            mu = std::max(mu - step, 0.0);
            if (std::abs(step) < 1e-14 * (1.0 + mu)) break;
        }
        return reference_density * (1.0 + mu);
    }
};

/// The equations of state a material may choose by name.
using EquationOfState = std::variant<TaitEos, MieGruneisenEos, PolynomialEos>;

inline double reference_density(const EquationOfState& eos) {
    return std::visit([](const auto& e) { return e.reference_density; }, eos);
}
inline double reference_sound_speed(const EquationOfState& eos) {
    return std::visit([](const auto& e) { return e.sound_speed; }, eos);
}
inline double density_from_pressure(const EquationOfState& eos, double p) {
    return std::visit([p](const auto& e) { return e.density(p); }, eos);
}
inline double pressure_from_density(const EquationOfState& eos, double rho) {
    return std::visit([rho](const auto& e) { return e.pressure(rho, 0.0); }, eos);
}

}  // namespace grit::material
