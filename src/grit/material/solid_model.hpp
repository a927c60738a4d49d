// Constitutive models of solids (laws only) and the update of one material point over one time
// step: Jaumann stress rate (first seed paper eq. 30), von Mises radial return (eq. 32), plastic strain,
// cumulative damage (eqs. 36, 39), bulking (eq. 41) and adiabatic heating. The SPH stage and the single-point driver call the
// same function, so what the driver verifies is what the particles do.
#pragma once

#include <algorithm>
#include <cmath>
#include <string>
#include <variant>

#include "grit/core/sym_tensor.hpp"
#include "grit/material/equation_of_state.hpp"
#include "grit/material/johnson_cook.hpp"
#include "grit/material/johnson_holmquist.hpp"

namespace grit::material {

/// Linear elastic (no yield).
struct ElasticSolid {
    static constexpr const char* name = "elastic";
};

/// Johnson-Cook strength with (optionally) Johnson-Cook failure.
struct JohnsonCook {
    static constexpr const char* name = "johnson_cook";
    JohnsonCookStrength strength;
    JohnsonCookFailure failure;
    bool failure_enabled = true;
    /// The largest triaxiality eq. (35) takes at a particle on the solid's surface (free or wetted): a
    /// surface carries at most its normal traction, so one principal stress is zero or compressive, and
    /// such a state reaches 2/3 at most (equibiaxial tension). SPH does not hold a surface particle's own
    /// pressure to that; above it, the triaxiality is a discretisation error (docs/theory.md).
    double surface_triaxiality = 2.0 / 3.0;
    /// The length l over which eq. (36)'s damage is averaged (non-local damage; sph/nonlocal_damage.hpp)
    /// [m]. 0, the paper's and the default: each point accumulates its own increments (local damage,
    /// which makes the removal mesh dependent: docs/theory.md, "Removal").
    double damage_length = 0.0;
    bool nonlocal_damage() const noexcept { return failure_enabled && damage_length > 0.0; }
};

/// Johnson-Holmquist (JH-2) brittle strength, damage and bulking. Eq. (41) needs K1 and rho0 of the
/// material's polynomial EOS (eq. 40): bind_eos copies them (the library and the case reader call it).
struct JH2 {
    static constexpr const char* name = "jh2";
    JH2Strength strength;
    JH2Failure failure;
    double bulking_fraction = 1.0;   ///< beta of eq. (41), 0 <= beta <= 1 [-]
    double bulk_modulus = 0.0;       ///< K1 [Pa]
    double reference_density = 0.0;  ///< rho0 [kg/m^3]

    void bind_eos(const PolynomialEos& eos) noexcept {
        bulk_modulus = eos.k1;
        reference_density = eos.reference_density;
    }
};

/// The solid models a material may choose by name.
using SolidModel = std::variant<ElasticSolid, JohnsonCook, JH2>;

/// Elastic and thermal data every solid has.
struct SolidProperties {
    double shear_modulus = 0.0;       ///< G [Pa]
    double specific_heat = 0.0;       ///< c_p [J/(kg K)]; used when adiabatic_heating
    double taylor_quinney = 0.9;      ///< fraction of plastic work turned into heat [-]
    bool adiabatic_heating = false;   ///< off: T stays at the room temperature
    double room_temperature = 293.0;  ///< initial temperature [K]
};

/// Spin tensor W (antisymmetric): W_xy = -W_yx etc. [1/s]
struct Spin {
    double xy = 0.0, yz = 0.0, zx = 0.0;
};

/// State carried by a solid material point.
struct SolidPointState {
    core::SymTensor3 deviatoric_stress;  ///< tau [Pa]
    double plastic_strain = 0.0;         ///< equivalent plastic strain eps_p [-]
    double plastic_strain_rate = 0.0;    ///< of the last step [1/s]
    double damage = 0.0;                 ///< D of eq. (36) or (39) [-]
    double temperature = 293.0;          ///< [K]
    double bulking_pressure = 0.0;       ///< dp of eqs. (40)-(41) (JH-2 only) [Pa]
    /// Johnson-Cook: this step's local increment d eps_p / eps_f of eq. (36) [-]; a non-local material
    /// leaves `damage` to the averaging of these over its damage length (JohnsonCook::damage_length).
    double damage_increment = 0.0;
};

/// Adds a damage increment (eq. 36); a failed ductile point (D = 1) carries no shear.
inline void accumulate_ductile_damage(SolidPointState& s, double increment) noexcept {
    s.damage = std::min(1.0, s.damage + increment);
    if (s.damage >= 1.0) s.deviatoric_stress = core::SymTensor3::zero();
}

/// Jaumann rate of the deviatoric stress, eq. (30): 2G (eps_dot - tr/3 I) + tau W^T + W tau
/// (the paper's tau^{a c} R^{b c} + tau^{b c} R^{a c}).
inline core::SymTensor3 jaumann_rate(const core::SymTensor3& tau, const core::SymTensor3& strain_rate,
                                     const Spin& w, double shear_modulus) noexcept {
    // With R = [[0, w.xy, -w.zx], [-w.xy, 0, w.yz], [w.zx, -w.yz, 0]] the rotation term is Q + Q^T,
    // Q = tau R^T, written out without R's zeros (per particle and step; the looped form was not inlined).
    const double a = w.xy, b = w.yz, c = w.zx;
    const double q00 = a * tau.xy - c * tau.zx, q11 = b * tau.yz - a * tau.xy, q22 = c * tau.zx - b * tau.yz;
    const double q01 = b * tau.zx - a * tau.xx, q10 = a * tau.yy - c * tau.yz;
    const double q12 = c * tau.xy - b * tau.yy, q21 = b * tau.zz - a * tau.zx;
    const double q20 = a * tau.yz - c * tau.zz, q02 = c * tau.xx - b * tau.xy;
    const core::SymTensor3 e = strain_rate.deviator();
    const double g2 = 2.0 * shear_modulus;
    return {g2 * e.xx + 2.0 * q00, g2 * e.yy + 2.0 * q11, g2 * e.zz + 2.0 * q22,
            g2 * e.xy + q01 + q10, g2 * e.yz + q12 + q21, g2 * e.zx + q20 + q02};
}

/// The rate entering the strength laws: the equivalent deviatoric strain rate sqrt(2/3 e : e) [1/s].
inline double equivalent_strain_rate(const core::SymTensor3& strain_rate) noexcept {
    const core::SymTensor3 e = strain_rate.deviator();
    return std::sqrt(2.0 / 3.0 * e.contract(e));
}

/// Advances one material point by dt: trial stress from the Jaumann rate, radial return onto the
/// yield surface (eq. 32). Johnson-Cook: sigma_vm_trial - 3 G d eps_p = sigma_y(eps_p + d eps_p), damage
/// D += d eps_p / eps_f (eq. 36), heating dT = beta sigma_y d eps_p / (rho c_p). JH-2: strength from
/// pressure and damage (eq. 38), damage (eq. 39), bulking pressure (eq. 41). At D >= 1 the deviatoric
/// stress is zero and plastic strain stops. `pressure` is p (positive in compression); `density` rho.
/// `at_surface`: the point is on the solid's surface, where eq. (35)'s triaxiality is bounded by
/// JohnsonCook::surface_triaxiality.
template <class Model>
SolidPointState update_solid_point(const Model& model, const SolidProperties& props, const SolidPointState& s,
                                   const core::SymTensor3& strain_rate, const Spin& spin, double pressure,
                                   double density, double dt, bool at_surface = false) noexcept {
    SolidPointState next = s;
    // A failed ductile point carries no shear (eq. 36; it is removed at the end of the step). Fractured
    // rock keeps eq. (38)'s D = 1 strength sigma_f* = B (P*)^M: comminuted rock under confinement is
    // a granular solid, not a fluid (JH-2; docs/theory.md).
    if (s.damage >= 1.0 && !std::is_same_v<Model, JH2>) {
        next.deviatoric_stress = core::SymTensor3::zero();
        next.plastic_strain_rate = 0.0;
        return next;
    }
    core::SymTensor3 trial = s.deviatoric_stress + jaumann_rate(s.deviatoric_stress, strain_rate, spin,
                                                                props.shear_modulus) * dt;
    trial = trial.deviator();  // keep it traceless against round-off
    next.deviatoric_stress = trial;
    next.plastic_strain_rate = 0.0;
    next.damage_increment = 0.0;
    if constexpr (std::is_same_v<Model, JohnsonCook>) {
        const double vm_trial = trial.von_mises();
        const double rate = equivalent_strain_rate(strain_rate);
        const double sigma_y0 = model.strength.yield_stress(s.plastic_strain, rate, s.temperature);
        if (vm_trial > sigma_y0) {
            // Radial return with hardening: solve vm_trial - 3 G d_eps = sigma_y(eps_p + d_eps) for d_eps
            // (secant iterations from the perfectly plastic guess), so the stress lands on the yield
            // surface of the end of the step, not of its start.
            const double three_g = 3.0 * props.shear_modulus;
            auto residual = [&](double d) {
                return vm_trial - three_g * d - model.strength.yield_stress(s.plastic_strain + d, rate, s.temperature);
            };
            const double d_max = (vm_trial - sigma_y0) / three_g;  // perfectly plastic: residual(d_max) <= 0
            double d0 = 0.0, r0 = vm_trial - sigma_y0;
            double d1 = d_max, r1 = residual(d1);
            for (int it = 0; it < 30 && std::abs(r1) > 1e-10 * vm_trial && r1 != r0; ++it) {
                const double d2 = std::clamp(d1 - r1 * (d1 - d0) / (r1 - r0), 0.0, d_max);
                d0 = d1;
                r0 = r1;
                d1 = d2;
                r1 = residual(d1);
            }
            const double d_eps = d1;
            const double sigma_y = vm_trial - three_g * d_eps;
            next.deviatoric_stress = trial * (sigma_y / vm_trial);  // eq. (32)
            next.plastic_strain = s.plastic_strain + d_eps;
            next.plastic_strain_rate = dt > 0.0 ? d_eps / dt : 0.0;
            if (props.adiabatic_heating && props.specific_heat > 0.0)
                next.temperature = s.temperature + props.taylor_quinney * sigma_y * d_eps / (density * props.specific_heat);
            if (model.failure_enabled) {
                const double vm = next.deviatoric_stress.von_mises();
                double triaxiality = vm > 0.0 ? -pressure / vm : 0.0;
                if (at_surface) triaxiality = std::min(triaxiality, model.surface_triaxiality);
                const double eps_f = model.failure.failure_strain(triaxiality, next.plastic_strain_rate, s.temperature);
                next.damage_increment = d_eps / eps_f;  // eq. (36)
                if (!model.nonlocal_damage()) accumulate_ductile_damage(next, next.damage_increment);
            }
        }
    } else if constexpr (std::is_same_v<Model, JH2>) {
        // JH-2 (eqs. 38, 39, 41): no hardening, so the return is explicit at the strength of the start of
        // the step, d eps_p = (sigma_vm_trial - sigma_y) / 3G. The damage this increment adds lowers the
        // strength; the stress is returned onto the lowered surface, and the deviatoric elastic energy it
        // loses, U = sigma_y^2 / 6G (Johnson & Holmquist 1994), feeds the bulking pressure.
        const double vm_trial = trial.von_mises();
        const double rate = equivalent_strain_rate(strain_rate);
        const double sigma_y0 = model.strength.yield_stress(pressure, s.damage, rate);
        if (vm_trial > sigma_y0) {
            const double three_g = 3.0 * props.shear_modulus;
            const double d_eps = (vm_trial - sigma_y0) / three_g;
            next.plastic_strain = s.plastic_strain + d_eps;
            next.plastic_strain_rate = dt > 0.0 ? d_eps / dt : 0.0;
            next.damage = std::min(1.0, s.damage + d_eps / model.failure.failure_strain(pressure, model.strength));
            const double sigma_y = model.strength.yield_stress(pressure, next.damage, rate);
            next.deviatoric_stress = vm_trial > 0.0 ? trial * (sigma_y / vm_trial) : trial;
            const double energy_loss = (sigma_y0 * sigma_y0 - sigma_y * sigma_y) / (2.0 * three_g);
            const double mu = density / model.reference_density - 1.0;
            next.bulking_pressure =
                bulking_pressure(s.bulking_pressure, mu, model.bulk_modulus, model.bulking_fraction, energy_loss);
        }
    }
    return next;
}

}  // namespace grit::material
