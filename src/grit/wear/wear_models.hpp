// Single-particle erosion models: the volume one grain removes from a wall in one impact (Finnie, Bitter,
// Oka et al.), and LIGGGHTS' Finnie form accumulated over the steps of a contact. Pure functions of the
// impact and the wall's wear material; docs/theory.md "Wear models" gives the sources and the choices.
#pragma once

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace grit::wear {

/// The wall's material as the wear models see it, with the models' constants. SI units except the
/// Vickers hardness (GPa, as Oka's fits take it).
struct WearMaterial {
    std::string name;
    double density = NAN;           ///< rho_t [kg/m^3]
    double youngs_modulus = NAN;    ///< E_t [Pa]
    double poisson_ratio = NAN;     ///< q_t [-]
    double flow_stress = NAN;       ///< p of Finnie (eq. 23) and sigma of Bitter (eq. 25) [Pa]
    double elastic_limit = NAN;     ///< Y of Bitter (eq. 26) [Pa]
    double vickers_hardness = NAN;  ///< Hv of Oka [GPa]
    // Finnie (second paper eqs. 22-23)
    double finnie_k = 2.0;    ///< ratio of vertical to horizontal force on the grain [-]
    double finnie_psi = 2.0;  ///< ratio of the depth of contact to the length of the cut [-]
    // Bitter (eqs. 24-26)
    double bitter_exponent = 2.3;            ///< n, the cutting term's velocity exponent [-]
    double bitter_roundness = 1.0;           ///< R_f, the grain's roundness factor [-]
    double bitter_deformation_factor = NAN;  ///< E_f (epsilon), energy to remove a unit volume by deformation [J/m^3]
    /// Where E_f is derived from Oka's E90 (bitter_deformation_factor_from_oka): the quartz grain's speed [m/s]
    /// and diameter [m] at which the two agree; NaN where E_f is a given number.
    double bitter_calibration_speed = NAN;
    double bitter_calibration_diameter = NAN;
    // Oka et al. 2005 (Part 2 correlations; SiO2 sand constants)
    double oka_K = 65.0;  ///< [mm^3/kg]
    double oka_k1 = -0.12;
    double oka_k3 = 0.19;
    double oka_reference_speed = 104.0;      ///< V' [m/s]
    double oka_reference_diameter = 326e-6;  ///< D' [m]
    // LIGGGHTS' Finnie form
    double liggghts_k = 1.0;  ///< k_finnie [s^2/m^2]
};

/// The grain of an impact.
struct Impactor {
    double mass = 0.0;            ///< [kg]
    double radius = 0.0;          ///< [m]
    double density = 0.0;         ///< rho_p [kg/m^3]
    double youngs_modulus = 0.0;  ///< E_p [Pa]
    double poisson_ratio = 0.0;   ///< q_p [-]
};

/// Finnie's angle function (second paper eq. 22 with the continuous second branch, ERRATA.md):
/// sin 2a - (6/k) sin^2 a for tan a <= k/6, k cos^2 a / 6 beyond. Its peak is at a = atan(k/3) / 2.
inline double finnie_angle_function(double angle, double k) {
    if (std::tan(angle) <= k / 6.0) return std::sin(2.0 * angle) - 6.0 / k * std::sin(angle) * std::sin(angle);
    return k * std::cos(angle) * std::cos(angle) / 6.0;
}

/// Finnie (eqs. 22-23): removed volume m V^2 / (psi p k) f(a) [m^3]. `angle` in radians from the surface.
inline double finnie_volume(const WearMaterial& w, const Impactor& g, double speed, double angle) {
    return g.mass * speed * speed / (w.finnie_psi * w.flow_stress * w.finnie_k) *
           finnie_angle_function(angle, w.finnie_k);
}

/// Bitter's threshold speed D_k (eq. 26): below it, in the normal component, the impact is elastic [m/s].
/// The density is the grain's: the speed at which a Hertzian impact first yields the target depends on the
/// impactor's kinetic energy per volume (Johnson, Contact Mechanics, sec. 11.4), not the target's density
/// the printed equation names (docs/theory.md, "Errata in the papers").
inline double bitter_threshold_speed(const WearMaterial& w, const Impactor& g) {
    const double compliance = (1.0 - g.poisson_ratio * g.poisson_ratio) / g.youngs_modulus +
                              (1.0 - w.poisson_ratio * w.poisson_ratio) / w.youngs_modulus;
    return std::numbers::pi * std::numbers::pi / (2.0 * std::sqrt(10.0)) * std::pow(1.59 * w.elastic_limit, 2.5) *
           std::sqrt(w.bitter_roundness / g.density) * compliance * compliance;
}

/// Bitter's cutting speed scale C_k (eq. 25) [m/s].
inline double bitter_cutting_speed(const WearMaterial& w, const Impactor& g) {
    return std::sqrt(3.0 * w.flow_stress * std::pow(w.bitter_roundness, 0.6) / g.density);
}

/// Bitter's deformation term (eq. 24, second bracket): M_p (U sin a - D_k)^2 / (2 E_f) above the
/// threshold, zero below it [m^3].
inline double bitter_deformation_volume(const WearMaterial& w, const Impactor& g, double speed, double angle) {
    const double excess = speed * std::sin(angle) - bitter_threshold_speed(w, g);
    return excess > 0.0 ? g.mass * excess * excess / (2.0 * w.bitter_deformation_factor) : 0.0;
}

/// Bitter's cutting term (eq. 24, first bracket): 100/(2 sqrt 29) r^3 (U/C_k)^n sin 2a sqrt(sin a) [m^3].
inline double bitter_cutting_volume(const WearMaterial& w, const Impactor& g, double speed, double angle) {
    return 100.0 / (2.0 * std::sqrt(29.0)) * g.radius * g.radius * g.radius *
           std::pow(speed / bitter_cutting_speed(w, g), w.bitter_exponent) * std::sin(2.0 * angle) *
           std::sqrt(std::sin(angle));
}

/// Bitter (eq. 24): cutting plus deformation [m^3].
inline double bitter_volume(const WearMaterial& w, const Impactor& g, double speed, double angle) {
    return bitter_cutting_volume(w, g, speed, angle) + bitter_deformation_volume(w, g, speed, angle);
}

/// Oka's exponents from the wall's hardness (Part 2, SiO2): n1 = 0.71 Hv^0.14, n2 = 2.4 Hv^-0.94,
/// k2 = 2.3 Hv^0.038.
inline double oka_n1(const WearMaterial& w) {
    return 0.71 * std::pow(w.vickers_hardness, 0.14);
}
inline double oka_n2(const WearMaterial& w) {
    return 2.4 * std::pow(w.vickers_hardness, -0.94);
}
inline double oka_k2(const WearMaterial& w) {
    return 2.3 * std::pow(w.vickers_hardness, 0.038);
}

/// Oka's angle function g(a) = sin^n1 a (1 + Hv (1 - sin a))^n2; its peak is where
/// sin a = n1 (1 + Hv) / (Hv (n1 + n2)) (90 degrees when that passes 1).
inline double oka_angle_function(const WearMaterial& w, double angle) {
    const double s = std::sin(angle);
    return std::pow(s, oka_n1(w)) * std::pow(1.0 + w.vickers_hardness * (1.0 - s), oka_n2(w));
}

/// Oka's erosion at normal impact E90 = K Hv^k1 (V/V')^k2 (D/D')^k3 [mm^3 per kg of grains].
inline double oka_e90(const WearMaterial& w, double speed, double diameter) {
    return w.oka_K * std::pow(w.vickers_hardness, w.oka_k1) * std::pow(speed / w.oka_reference_speed, oka_k2(w)) *
           std::pow(diameter / w.oka_reference_diameter, w.oka_k3);
}

/// Oka et al. 2005: removed volume m E90 g(a) [m^3] (E in mm^3/kg).
inline double oka_volume(const WearMaterial& w, const Impactor& g, double speed, double angle) {
    return g.mass * oka_e90(w, speed, 2.0 * g.radius) * oka_angle_function(w, angle) * 1e-9;
}

/// Bitter's deformation wear factor E_f that makes his normal-incidence term V^2 / (2 E_f), per kilogram of
/// grains, equal Oka's E90 for quartz of `diameter` at `speed`: E_f = V^2 / (2 E90) [J/m^3]. No source gives
/// E_f for grit's wall materials; Oka's measured constants do give E90 (docs/theory.md, "Wear models").
inline double bitter_deformation_factor_from_oka(const WearMaterial& w, double speed, double diameter) {
    return speed * speed / (2.0 * oka_e90(w, speed, diameter) * 1e-9);
}

/// Gives `w` the E_f derived from Oka at `speed` [m/s] and `diameter` [m], and records that it is derived.
inline void derive_bitter_deformation_factor(WearMaterial& w, double speed, double diameter) {
    w.bitter_calibration_speed = speed;
    w.bitter_calibration_diameter = diameter;
    w.bitter_deformation_factor = bitter_deformation_factor_from_oka(w, speed, diameter);
}

/// The built-in calibration of E_f: 1 mm quartz sand (the second paper's coarse sand) at 20 m/s (its Pelton
/// jet's speed).
inline constexpr double bitter_reference_speed = 20.0;      ///< [m/s]
inline constexpr double bitter_reference_diameter = 1e-3;  ///< [m]

/// LIGGGHTS' Finnie angle function (k = 2 in Finnie's form): sin 2a - 3 sin^2 a for tan a <= 1/3,
/// cos^2 a / 3 beyond.
inline double liggghts_angle_function(double angle) {
    if (std::tan(angle) <= 1.0 / 3.0) return std::sin(2.0 * angle) - 3.0 * std::sin(angle) * std::sin(angle);
    return std::cos(angle) * std::cos(angle) / 3.0;
}

/// LIGGGHTS' Finnie form over a contact (its mesh/surface/stress `wear finnie`): the mass a contact
/// removes in a step of dt while the grain approaches the wall, 2 k |v| |F| f(a) dt [kg], |F| the
/// contact's force, v the grain's velocity relative to the wall.
inline double liggghts_mass_rate(const WearMaterial& w, double speed, double force, double angle) {
    return 2.0 * w.liggghts_k * speed * force * liggghts_angle_function(angle);
}

/// The models by name.
enum class WearModel { none, finnie, bitter, oka, finnie_liggghts };

inline std::optional<WearModel> wear_model_named(std::string_view name) {
    if (name == "none") return WearModel::none;
    if (name == "finnie") return WearModel::finnie;
    if (name == "bitter") return WearModel::bitter;
    if (name == "oka") return WearModel::oka;
    if (name == "finnie_liggghts") return WearModel::finnie_liggghts;
    return std::nullopt;
}

/// Removed volume of one impact by a per-impact model [m^3] (0 for none and for LIGGGHTS' form, which
/// accumulates over the contact instead).
inline double impact_volume(WearModel model, const WearMaterial& w, const Impactor& g, double speed, double angle) {
    switch (model) {
        case WearModel::finnie:
            return finnie_volume(w, g, speed, angle);
        case WearModel::bitter:
            return bitter_volume(w, g, speed, angle);
        case WearModel::oka:
            return oka_volume(w, g, speed, angle);
        default:
            return 0.0;
    }
}

/// The material keys a model needs (for the case reader's messages).
inline std::vector<std::string> needed_keys(WearModel model) {
    switch (model) {
        case WearModel::finnie:
            return {"density", "flow_stress"};
        case WearModel::bitter:
            return {"density",     "youngs_modulus", "poisson_ratio",
                    "flow_stress", "elastic_limit",  "bitter_deformation_factor"};
        case WearModel::oka:
            return {"density", "vickers_hardness"};
        case WearModel::finnie_liggghts:
            return {"density"};
        default:
            return {};
    }
}

/// Built-in wear materials (docs/theory.md "Wear models" gives each value's source).
inline std::vector<WearMaterial> wear_material_library() {
    WearMaterial steel;
    steel.name = "steel";  // carbon steel
    steel.density = 7850.0;
    steel.youngs_modulus = 210e9;
    steel.poisson_ratio = 0.3;
    steel.vickers_hardness = 1.18;  // Oka et al. 2005 carbon steel (upper value)
    steel.flow_stress = 1.18e9;     // Finnie's flow pressure taken as the hardness
    steel.elastic_limit = 0.35e9;   // yield strength of a structural carbon steel
    derive_bitter_deformation_factor(steel, bitter_reference_speed, bitter_reference_diameter);
    WearMaterial aluminium;
    aluminium.name = "aluminium";
    aluminium.density = 2700.0;
    aluminium.youngs_modulus = 69e9;
    aluminium.poisson_ratio = 0.33;
    aluminium.vickers_hardness = 0.36;  // Oka et al. 2005 aluminium
    aluminium.flow_stress = 0.36e9;
    aluminium.elastic_limit = 0.276e9;  // Al 6061-T6 yield strength
    derive_bitter_deformation_factor(aluminium, bitter_reference_speed, bitter_reference_diameter);
    return {steel, aluminium};
}

inline std::optional<WearMaterial> find_wear_material(std::string_view name) {
    for (auto& m : wear_material_library())
        if (m.name == name) return m;
    return std::nullopt;
}

}  // namespace grit::wear
