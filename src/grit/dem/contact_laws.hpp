// Grain contact laws as pure value types: the linear spring-dashpot of the first seed paper (eqs. 2-11)
// and the Hertz-Mindlin law of the second (eqs. 11-12) with the damping and tangential stiffness of
// LIGGGHTS' `model hertz tangential history`. Chosen by name, dispatched once per loop (ContactLaw).
//
// Convention (first paper eqs. 5-8): a contact joins body a and body b; n is the unit vector from a to
// b; v_ab = v_a - v_b + (R_a w_a + R_b w_b) x n is the velocity of a's surface relative to b's at the
// contact; the overlap is delta_n = R_a + R_b - |x_b - x_a| > 0. A plane wall is body b with infinite
// radius and mass. Forces returned are those on body a; body b receives the opposite. The laws are those
// of spheres in 2D too (masses and forces in kg and N): contact_forces.hpp turns the force into the
// per-metre force of the discs (a disc collides like the sphere of its diameter, docs/theory.md).
#pragma once

#include <cmath>
#include <limits>
#include <numbers>
#include <string>
#include <string_view>
#include <variant>

#include "grit/core/error.hpp"
#include "grit/core/vec.hpp"
#include "grit/dem/grain_material.hpp"

namespace grit::dem {

/// x y / (x + y), the effective radius or mass of a pair; exactly x for y = infinity (a wall). One
/// division (the branch goes the same way for a whole loop: grain pairs or a wall).
inline double effective(double x, double y) noexcept {
    return y == std::numeric_limits<double>::infinity() ? x : x * y / (x + y);
}

/// What a law needs to know of one contact (canonical orientation a -> b).
struct ContactKinematics {
    double overlap = 0.0;          ///< delta_n > 0 [m] (eq. 5)
    double approach_speed = 0.0;   ///< v_ab . n [m/s]; positive while the bodies close in
    double radius_a = 0.0;         ///< R_a [m]
    double radius_b = 0.0;         ///< R_b [m]; infinity for a wall
    double mass_a = 0.0;           ///< m_a [kg]; in 2D the sphere's mass, not the disc's (contact_mass)
    double mass_b = 0.0;           ///< m_b [kg]; infinity for a wall
};

/// The normal force of a contact and the tangential spring and dashpot it sets.
struct NormalContact {
    double force = 0.0;                  ///< F_n [N] along -n on a; positive pushes the bodies apart
    double tangential_stiffness = 0.0;   ///< k_t [N/m]
    double tangential_damping = 0.0;     ///< d_t [N s/m]
};

/// Tangential force on a and the updated tangential spring elongation (the contact history).
template <int Dim>
struct TangentialContact {
    core::Vec<Dim> force;     ///< F_t on a [N]
    core::Vec<Dim> history;   ///< delta_t [m], to be stored for the next step (eq. 9)
};

/// F_t = -k_t delta_t - d_t v_t, with the Coulomb cap |F_t| <= mu |F_n| applied to the whole force as
/// in the first paper's eq. (3). When sliding, delta_t is set back to the elongation that gives the
/// capped force, so sliding does not store spring energy.
template <int Dim>
inline TangentialContact<Dim> coulomb_total(const core::Vec<Dim>& history, const core::Vec<Dim>& tangential_velocity,
                                            const NormalContact& normal, double friction) noexcept {
    const double kt = normal.tangential_stiffness, dt = normal.tangential_damping;
    core::Vec<Dim> f = history * (-kt) - tangential_velocity * dt;
    const double limit = friction * std::abs(normal.force);
    const double f2 = core::norm2(f);
    if (f2 > limit * limit) {
        f *= limit / std::sqrt(f2);
        return {f, (f + tangential_velocity * dt) * (-1.0 / kt)};
    }
    return {f, history};
}

/// LIGGGHTS' `tangential history` rule: the cap |k_t delta_t| <= mu |F_n| acts on the spring alone; when
/// it slides, delta_t is shortened to the cap and the tangential damping is left out.
template <int Dim>
inline TangentialContact<Dim> coulomb_spring(const core::Vec<Dim>& history, const core::Vec<Dim>& tangential_velocity,
                                             const NormalContact& normal, double friction) noexcept {
    const double kt = normal.tangential_stiffness;
    const double limit = friction * std::abs(normal.force);
    const double spring2 = kt * kt * core::norm2(history);
    // One path for both cases, the branch choosing two numbers: two returns of the pair made GCC merge
    // them through the stack, read back in one load that waited on three stores (a failed forwarding).
    // h * 1 and a damping of 0 change no bit.
    double scale = 1.0, damping = normal.tangential_damping;
    if (spring2 > limit * limit) {
        scale = limit / std::sqrt(spring2);
        damping = 0.0;
    }
    const core::Vec<Dim> h = history * scale;
    return {h * (-kt) - tangential_velocity * damping, h};
}

/// Linear spring-dashpot with Coulomb friction, first seed paper eqs. (2)-(11):
/// F_n = k_n delta_n + d_n v_n, k_n = 2 E_a R_a E_b R_b / (E_a R_a + E_b R_b) (eq. 10), k_t likewise with
/// E R nu (eq. 10), d = 2 xi sqrt(m* k) (eq. 11, with m* the pair's effective mass so that a two-body
/// impact rebounds with exactly e), tangential cap by eq. (3).
struct LinearSpringDashpot {
    static constexpr std::string_view name = "linear";

    NormalContact normal(const ContactKinematics& c, const PairMaterial& p) const noexcept {
        const double era = p.youngs_a * c.radius_a, erb = p.youngs_b * c.radius_b;
        const double kn = 2.0 * effective(era, erb);
        const double kt = 2.0 * effective(era * p.poisson_a, erb * p.poisson_b);
        const double m = effective(c.mass_a, c.mass_b);
        const double two_xi = 2.0 * p.damping_ratio;
        return {kn * c.overlap + two_xi * std::sqrt(m * kn) * c.approach_speed, kt, two_xi * std::sqrt(m * kt)};
    }
    /// Normal stiffness k_n of eq. (10) [N/m], used by the time-step limit of eq. (51).
    double normal_stiffness(const ContactKinematics& c, const PairMaterial& p) const noexcept {
        return 2.0 * effective(p.youngs_a * c.radius_a, p.youngs_b * c.radius_b);
    }
    template <int Dim>
    TangentialContact<Dim> tangential(const core::Vec<Dim>& history, const core::Vec<Dim>& tangential_velocity,
                                      const NormalContact& normal, const PairMaterial& p) const noexcept {
        return coulomb_total(history, tangential_velocity, normal, p.friction);
    }
};

/// Hertz-Mindlin: second seed paper eqs. (11)-(12), F_n = K delta^(3/2) + damping, K = 4/3 Y* sqrt(R*)
/// (eq. 12 written with h_j = (1 - nu_j^2) / (pi E_j)), with the damping and the Mindlin tangential
/// stiffness of LIGGGHTS `model hertz tangential history` (its gran_model_hertz documentation):
///   k_n = 4/3 Y* sqrt(R* delta), S_n = 2 Y* sqrt(R* delta), gamma_n = 2 sqrt(5/6) xi sqrt(S_n m*),
///   k_t = S_t = 8 G* sqrt(R* delta),                       gamma_t = 2 sqrt(5/6) xi sqrt(S_t m*),
/// F_n = k_n delta + gamma_n v_n, F_t = -k_t delta_t - gamma_t v_t, xi = -ln e / sqrt(pi^2 + ln^2 e).
/// Like LIGGGHTS (limitForce off), F_n may turn slightly attractive at the end of a damped impact.
struct HertzMindlin {
    static constexpr std::string_view name = "hertz";

    NormalContact normal(const ContactKinematics& c, const PairMaterial& p) const noexcept {
        const double s = std::sqrt(effective(c.radius_a, c.radius_b) * c.overlap);  // sqrt(R* delta)
        // 2 sqrt(5/6) xi sqrt(S m*) with S = 2 Y* s (normal) and 8 G* s (tangential).
        const double root_sm = std::sqrt(s * effective(c.mass_a, c.mass_b));
        const double gamma_n = p.hertz_damping_normal * root_sm;
        const double gamma_t = p.hertz_damping_tangential * root_sm;
        return {(4.0 / 3.0) * p.youngs_effective * s * c.overlap + gamma_n * c.approach_speed,
                8.0 * p.shear_effective * s, gamma_t};
    }
    /// Tangent normal stiffness dF/d delta = 2 Y* sqrt(R* delta) [N/m] at this overlap.
    double normal_stiffness(const ContactKinematics& c, const PairMaterial& p) const noexcept {
        return 2.0 * p.youngs_effective * std::sqrt(effective(c.radius_a, c.radius_b) * c.overlap);
    }
    template <int Dim>
    TangentialContact<Dim> tangential(const core::Vec<Dim>& history, const core::Vec<Dim>& tangential_velocity,
                                      const NormalContact& normal, const PairMaterial& p) const noexcept {
        return coulomb_spring(history, tangential_velocity, normal, p.friction);
    }
};

/// The contact-law family, dispatched once per loop with std::visit.
using ContactLaw = std::variant<LinearSpringDashpot, HertzMindlin>;

/// The law called `name` ("linear" or "hertz"); InputError otherwise.
inline ContactLaw make_contact_law(std::string_view name) {
    if (name == LinearSpringDashpot::name) return LinearSpringDashpot{};
    if (name == HertzMindlin::name) return HertzMindlin{};
    throw core::InputError("unknown grain contact law '" + std::string(name) + "' (expected \"linear\" or \"hertz\")");
}

inline std::string_view law_name(const ContactLaw& law) {
    return std::visit([](const auto& l) { return l.name; }, law);
}

}  // namespace grit::dem
