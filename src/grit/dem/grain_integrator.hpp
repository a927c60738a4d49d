// Velocity-Verlet integration of grain translation and rotation (first seed paper eq. 1), and the DEM
// time-step limits (eq. 51 for the linear law; Rayleigh and Hertz impact times for the Hertz law).
#pragma once

#include <cmath>
#include <numbers>

#include "grit/core/types.hpp"
#include "grit/core/vec.hpp"
#include "grit/dem/contact_laws.hpp"
#include "grit/dem/grain_material.hpp"
#include "grit/dem/grain_set.hpp"
#include "grit/dem/spin.hpp"
#include "grit/dem/grain_loop.hpp"

namespace grit::dem {

/// Half kick of grain i: v += dt/2 F/m and w += dt/2 T/I (eq. 1; spheres and discs have isotropic
/// inertia, so the gyroscopic term of the second paper's eq. 10 vanishes). Fixed grains (the `fixed`
/// field, [[grains]].fixed) keep their zero velocity, so the drift does not move them either.
template <int Dim>
struct GrainKick {
    core::Vec<Dim>* v;
    Spin<Dim>* w;
    const core::Vec<Dim>* f;
    const Spin<Dim>* t;
    const double* m;
    const double* inertia;
    const std::int32_t* fixed;  ///< null when no grain is fixed

    explicit GrainKick(GrainSet<Dim>& grains)
        : v(grains.velocity()), w(grains.angular_velocity()), f(std::as_const(grains).force()),
          t(std::as_const(grains).torque()), m(std::as_const(grains).mass()),
          inertia(std::as_const(grains).inertia()), fixed(fixed_flags(std::as_const(grains))) {}
    void operator()(Index i, double half_dt) const noexcept {
        if (fixed && fixed[i]) return;
        v[i] += f[i] * (half_dt / m[i]);
        w[i] += t[i] * (half_dt / inertia[i]);
    }
};

/// Half kick of every grain.
template <int Dim>
void kick_grains(GrainSet<Dim>& grains, double half_dt) {
    const GrainKick<Dim> kick(grains);
    for_each_grain(grains.size(), [&](Index i) { kick(i, half_dt); });
}

/// The first half kick and the drift (x += dt v; orientation is not tracked: grains are round) of a
/// step in one pass over the grains, then after(i) (more work on grain i while its lines are loaded);
/// returns the largest squared distance of a grain from reference[i] after the drift (0 when reference is
/// null), for the neighbour lists' skin check.
template <int Dim, class After = NoGrainWork>
double kick_drift_grains(GrainSet<Dim>& grains, double half_dt, double dt, const core::Vec<Dim>* reference,
                         After&& after = {}) {
    const GrainKick<Dim> kick(grains);
    auto* x = grains.position();
    const auto* v = kick.v;
    return max_over_grains(grains.size(), 0.0, [&](Index i) {
        kick(i, half_dt);
        x[i] += v[i] * dt;
        after(i);
        return reference ? core::norm2(x[i] - reference[i]) : 0.0;
    });
}

/// Coefficient alpha_tn of eq. (51), 300 in the first paper.
inline constexpr double paper_alpha_tn = 300.0;

/// DEM time-step limit of eq. (51) for the linear law: dt = 2 pi / alpha_tn sqrt(m / k_n), with m the
/// grain's sphere mass rho 4/3 pi R^3 and k_n the eq. (10) stiffness of two such grains (k_n = E R). A
/// grain against a wall (k_n = 2 E R, m* = m) and two equal grains (k_n = E R, m* = m/2) have the same
/// contact period, so this is the limit of both. The same in 2D: a disc's contacts are the sphere's
/// (contact_mass, disc_force_scale), so their period is too.
inline double linear_time_step(const GrainMaterial& material, double radius, double alpha_tn = paper_alpha_tn) {
    const double m = sphere_mass(material.density, radius);
    return 2.0 * std::numbers::pi / alpha_tn * std::sqrt(m / (material.youngs_modulus * radius));
}

/// Rayleigh time of a grain, t_R = pi R sqrt(rho / G) / (0.1631 nu + 0.8766), the usual Hertz-law
/// limit (a fraction of it, 0.2 by default as LIGGGHTS advises, is used as the step).
inline double rayleigh_time(const GrainMaterial& material, double radius) {
    const double shear = material.youngs_modulus / (2.0 * (1.0 + material.poisson_ratio));
    return std::numbers::pi * radius * std::sqrt(material.density / shear) /
           (0.1631 * material.poisson_ratio + 0.8766);
}

/// Duration of an elastic Hertz impact, Johnson, Contact Mechanics (1985) eq. (11.24):
/// t_c = 2.868 (m*^2 / (R* E*^2 v))^(1/5), with E* = Y* of the pair and m* of the spheres (in 2D too:
/// contact_mass).
inline double hertz_contact_time(double effective_mass, double effective_radius, double youngs_effective,
                                 double impact_speed) {
    return 2.868 * std::pow(effective_mass * effective_mass /
                                (effective_radius * youngs_effective * youngs_effective * impact_speed),
                            0.2);
}

/// Peak force of an elastic Hertz impact: the overlap where the kinetic energy 1/2 m* v^2 equals the
/// elastic energy 8/15 Y* sqrt(R*) delta^(5/2), then F = 4/3 Y* sqrt(R*) delta^(3/2).
inline double hertz_peak_force(double effective_mass, double effective_radius, double youngs_effective,
                               double impact_speed) {
    const double delta = std::pow(15.0 * effective_mass * impact_speed * impact_speed /
                                      (16.0 * youngs_effective * std::sqrt(effective_radius)),
                                  0.4);
    return 4.0 / 3.0 * youngs_effective * std::sqrt(effective_radius) * std::pow(delta, 1.5);
}

}  // namespace grit::dem
