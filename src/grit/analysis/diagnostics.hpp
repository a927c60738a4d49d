// Global diagnostics of the moving (non-wall) particles: kinetic energy, mass, momentum, peak speed.
#pragma once

#include "grit/core/vec.hpp"
#include "grit/parallel/parallel.hpp"
#include "grit/particles/sph_particles.hpp"

namespace grit::analysis {

template <int Dim>
struct Diagnostics {
    double kinetic_energy = 0.0;  ///< [J] (per metre of thickness in 2D)
    double mass = 0.0;            ///< [kg] (per metre in 2D)
    core::Vec<Dim> momentum = core::Vec<Dim>::zero();
    double max_velocity = 0.0;    ///< [m/s]
};

template <int Dim>
struct DiagnosticsSum {
    double kinetic_energy = 0.0, mass = 0.0;
    core::Vec<Dim> momentum = core::Vec<Dim>::zero();
    DiagnosticsSum& operator+=(const DiagnosticsSum& o) {
        kinetic_energy += o.kinetic_energy;
        mass += o.mass;
        momentum += o.momentum;
        return *this;
    }
};

/// Deterministic (thread-count independent) diagnostics of every particle that is not a wall (nor a
/// symmetry plane's image).
template <int Dim>
Diagnostics<Dim> compute_diagnostics(const particles::SphParticles<Dim>& ps) {
    const auto* v = ps.velocity();
    const auto* m = ps.mass();
    const auto* phase = ps.phase();
    const auto* id = ps.id();
    const auto wall = static_cast<std::int32_t>(Phase::wall);
    const auto s = parallel::sum(ps.size(), DiagnosticsSum<Dim>{}, [&](Index i) {
        DiagnosticsSum<Dim> d;
        if (phase[i] == wall || particles::SphParticles<Dim>::is_image_id(id[i])) return d;
        d.kinetic_energy = 0.5 * m[i] * core::norm2(v[i]);
        d.mass = m[i];
        d.momentum = v[i] * m[i];
        return d;
    });
    Diagnostics<Dim> out;
    out.kinetic_energy = s.kinetic_energy;
    out.mass = s.mass;
    out.momentum = s.momentum;
    out.max_velocity = std::sqrt(parallel::max(ps.size(), 0.0, [&](Index i) {
        return phase[i] == wall ? 0.0 : core::norm2(v[i]);
    }));
    return out;
}

}  // namespace grit::analysis
