// Grain materials (density, elasticity, friction, restitution) by name, and the pair properties two
// materials give a contact: effective moduli (Hertz), friction and restitution of the pair.
#pragma once

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace grit::dem {

/// A grain (or wall) material. Values in SI units.
struct GrainMaterial {
    std::string name;
    double density = 0.0;          ///< [kg/m^3]
    double youngs_modulus = 0.0;   ///< E [Pa]
    double poisson_ratio = 0.0;    ///< nu [-]
    double friction = 0.0;         ///< sliding friction coefficient mu [-] (first paper eq. 3)
    double restitution = 1.0;      ///< normal coefficient of restitution e [-] (eq. 11)
    double diameter = 0.0;         ///< nominal grain diameter [m] (0 when the material has none)
    /// The grain's real Young's modulus where `youngs_modulus` is softened for a longer contact time step:
    /// the wear models' elastic-limit speed (Bitter's eq. 26) takes it [Pa]; 0: `youngs_modulus`.
    double wear_youngs_modulus = 0.0;

    double youngs_modulus_for_wear() const { return wear_youngs_modulus > 0.0 ? wear_youngs_modulus : youngs_modulus; }
};

/// Garnet/alumina abrasive of the first seed paper, Table 4: rho 4120 kg/m^3, d 0.2 mm, E 248 GPa,
/// nu 0.3, mu 0.3, e 0.6.
inline GrainMaterial garnet() { return {"garnet", 4120.0, 248e9, 0.3, 0.3, 0.6, 0.2e-3}; }

/// Wall materials for grain contact (mesh walls, plane walls): carbon steel and aluminium with handbook
/// elastic constants; friction and restitution of quartz sand on them (order of the values measured for
/// sand on steel plates, e ~ 0.5-0.7, mu ~ 0.3-0.5).
inline GrainMaterial steel() { return {"steel", 7850.0, 210e9, 0.3, 0.4, 0.6, 0.0}; }
inline GrainMaterial aluminium() { return {"aluminium", 2700.0, 69e9, 0.33, 0.4, 0.6, 0.0}; }
/// Quartz sand (SiO2): rho 2650 kg/m^3, E 70 GPa, nu 0.17 (the second paper's loading is "coarse sand").
inline GrainMaterial sand() { return {"sand", 2650.0, 70e9, 0.17, 0.4, 0.6, 0.5e-3}; }

/// The built-in grain materials.
inline std::vector<GrainMaterial> grain_material_library() { return {garnet(), sand(), steel(), aluminium()}; }

/// The built-in grain material called `name`, if any.
inline std::optional<GrainMaterial> find_grain_material(std::string_view name) {
    for (auto& m : grain_material_library())
        if (m.name == name) return m;
    return std::nullopt;
}

/// Damping ratio of a linear oscillator that rebounds with restitution e (first paper, after eq. 11):
/// xi = -ln e / sqrt(pi^2 + ln^2 e); 0 for e = 1.
inline double damping_ratio(double restitution) {
    if (restitution >= 1.0) return 0.0;
    const double l = std::log(restitution);
    return -l / std::sqrt(std::numbers::pi * std::numbers::pi + l * l);
}

/// What the contact laws need from the two materials of a contact. Computed once per material pair.
struct PairMaterial {
    double youngs_a = 0.0, youngs_b = 0.0;      ///< E_a, E_b [Pa] (eq. 10)
    double poisson_a = 0.0, poisson_b = 0.0;    ///< nu_a, nu_b [-] (eq. 10)
    double youngs_effective = 0.0;              ///< Y* = 1 / ((1 - nu_a^2)/E_a + (1 - nu_b^2)/E_b) [Pa]
    double shear_effective = 0.0;               ///< G* = 1 / (2(2 - nu_a)(1 + nu_a)/E_a + ...) [Pa]
    double friction = 0.0;                      ///< mu of the pair [-]
    double restitution = 1.0;                   ///< e of the pair [-]
    double damping_ratio = 0.0;                 ///< xi(e) [-]
    /// 2 sqrt(5/6) xi sqrt(2 Y*) and 2 sqrt(5/6) xi sqrt(8 G*): the Hertz dampings gamma_n, gamma_t are
    /// these times sqrt(sqrt(R* delta) m*) (contact_laws.hpp), so a contact takes one square root for both.
    double hertz_damping_normal = 0.0;
    double hertz_damping_tangential = 0.0;
};

/// Pair properties of materials a and b. Friction and restitution of unlike materials are the mean of
/// the two (the papers use one grain material; LIGGGHTS takes a per-pair table instead).
inline PairMaterial pair_material(const GrainMaterial& a, const GrainMaterial& b) {
    PairMaterial p;
    p.youngs_a = a.youngs_modulus;
    p.youngs_b = b.youngs_modulus;
    p.poisson_a = a.poisson_ratio;
    p.poisson_b = b.poisson_ratio;
    p.youngs_effective = 1.0 / ((1.0 - a.poisson_ratio * a.poisson_ratio) / a.youngs_modulus +
                                (1.0 - b.poisson_ratio * b.poisson_ratio) / b.youngs_modulus);
    p.shear_effective = 1.0 / (2.0 * (2.0 - a.poisson_ratio) * (1.0 + a.poisson_ratio) / a.youngs_modulus +
                               2.0 * (2.0 - b.poisson_ratio) * (1.0 + b.poisson_ratio) / b.youngs_modulus);
    p.friction = 0.5 * (a.friction + b.friction);
    p.restitution = a.restitution == b.restitution ? a.restitution : 0.5 * (a.restitution + b.restitution);
    p.damping_ratio = dem::damping_ratio(p.restitution);
    const double g = 2.0 * std::sqrt(5.0 / 6.0) * p.damping_ratio;
    p.hertz_damping_normal = g * std::sqrt(2.0 * p.youngs_effective);
    p.hertz_damping_tangential = g * std::sqrt(8.0 * p.shear_effective);
    return p;
}

}  // namespace grit::dem
