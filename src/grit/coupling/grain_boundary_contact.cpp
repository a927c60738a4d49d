// Penalty contact between grains and SPH solid/wall particles (first seed paper eqs. 12-14).
#include "grit/coupling/grain_boundary_contact.hpp"

#include <algorithm>
#include <cmath>

#include "grit/dem/spin.hpp"
#include "grit/parallel/parallel.hpp"

namespace grit::coupling {

template <int Dim>
void GrainBoundaryContact<Dim>::compute(const dem::GrainSet<Dim>& grains,
                                        const particles::SphParticles<Dim>& particles, double dt,
                                        const neighbors::PeriodicBox<Dim>& box) {
    contacts_.clear();
    const Index ng = grains.size();
    grain_start_.assign(static_cast<std::size_t>(ng) + 1, 0);
    grain_order_.clear();
    if (ng == 0 || particles.size() == 0) return;

    const Vec* xg = grains.position();
    const Vec* vg = grains.velocity();
    const auto* wg = grains.angular_velocity();
    const double* radius = grains.radius();
    const double d_ini = parameters_.spacing;
    const double near_distance = 2.0 * d_ini;  // pairs listed (the log's release distance)

    const Index n = particles.size();
    const Vec* x = particles.position();
    const Vec* v = particles.velocity();
    const double* m = particles.mass();
    const std::int32_t* phase = particles.phase();
    const auto solid = static_cast<std::int32_t>(Phase::solid), wall = static_cast<std::int32_t>(Phase::wall);
    const bool walls = parameters_.walls;
    // Each solid or wall particle's grains within R_i + 2 d_ini, in ascending grain index; the contacts
    // take the list's order (by particle, then grain) at any thread count.
    pairs_.build(
        x, n, [&](Index a) { return phase[a] == solid || (walls && phase[a] == wall); }, xg, radius, ng, near_distance,
        box);
    contacts_.resize(pairs_.pair_count());
    if (contacts_.empty()) return;

    const double chi = parameters_.overlap_coefficient, mu = parameters_.friction;
    const bool periodic = box.any();
    parallel::for_each(n, [&](Index a) {
        for (Index slot = pairs_.begin(a); slot < pairs_.end(a); ++slot) {
            const Index i = pairs_.indices()[slot];
            PenaltyContact<Dim>& c = contacts_[static_cast<std::size_t>(slot)];
            const Vec r = periodic ? box.nearest_image(x[a] - xg[i]) : x[a] - xg[i];
            const double d = std::sqrt(core::norm2(r));
            const Vec normal = d > 0.0 ? r * (1.0 / d) : Vec::zero();
            c.grain = i;
            c.particle = a;
            c.normal = normal;
            c.lever = normal * radius[i];                    // contact point p on the grain's surface
            const double overlap = d_ini - (d - radius[i]);  // d_n = d_ini - d_p (step 4)
            c.touching = overlap > 0.0;
            if (!c.touching) continue;
            // Eq. (12): the velocity of p relative to the particle.
            const Vec vpa = vg[i] + dem::spin_cross<Dim>(wg[i], c.lever) - v[a];
            // Eq. (13): the normal force that removes the overlap in one step, tangential capped by mu|F_n|.
            const double fn = (1.0 - chi) * 2.0 * m[a] / (dt * dt) * overlap;
            Vec force = normal * fn;
            const Vec vt = vpa - normal * core::dot(vpa, normal);
            const double vt_norm = std::sqrt(core::norm2(vt));
            if (vt_norm > 0.0) {
                const double ft = std::min(2.0 * m[a] / dt * vt_norm, mu * std::abs(fn));
                force += vt * (ft / vt_norm);
            }
            c.force = force;
        }
    });

    // The grain side: each grain's contacts in particle order.
    for (const auto& c : contacts_) ++grain_start_[static_cast<std::size_t>(c.grain) + 1];
    for (Index g = 0; g < ng; ++g) grain_start_[g + 1] += grain_start_[g];
    grain_order_.resize(contacts_.size());
    std::vector<Index> next(grain_start_.begin(), grain_start_.end() - 1);
    for (std::size_t k = 0; k < contacts_.size(); ++k)
        grain_order_[static_cast<std::size_t>(next[contacts_[k].grain]++)] = static_cast<Index>(k);

    // Eq. (13) removes the overlap in one step only if the grain does not move: its stiffness
    // 2 m_a / dt^2 gives the grain and the particles it touches omega^2 dt^2 = 2 (1 + sum m_a / M), which
    // leap-frog integrates stably only up to 4. Particles as heavy as the grain (a copper particle at
    // 0.1 mm spacing is 0.7 of a 0.2 mm garnet grain in 2D) made an impact end with up to nine times the
    // grain's energy, and blow up at 0.125 mm. Scaling every contact of grain g by M / (M + sum m_a)
    // keeps omega^2 dt^2 = 2 for any mass ratio, and is eq. (13) itself for a grain much heavier than what
    // it touches (docs/theory.md, "the grain's share").
    const double* grain_mass = grains.mass();
    parallel::for_each(ng, [&](Index g) {
        double touching_mass = 0.0;
        for (Index k = grain_start_[g]; k < grain_start_[g + 1]; ++k) {
            const auto& c = contacts_[static_cast<std::size_t>(grain_order_[k])];
            if (c.touching) touching_mass += m[c.particle];
        }
        if (touching_mass == 0.0) return;
        const double share = grain_mass[g] / (grain_mass[g] + touching_mass);
        for (Index k = grain_start_[g]; k < grain_start_[g + 1]; ++k)
            contacts_[static_cast<std::size_t>(grain_order_[k])].force *= share;
    });
}

template <int Dim>
void GrainBoundaryContact<Dim>::apply(dem::GrainSet<Dim>& grains, particles::SphParticles<Dim>& particles,
                                      const std::int32_t* fixed) const {
    if (contacts_.empty()) return;
    Vec* acc = particles.acceleration();
    const double* m = particles.mass();
    const std::int32_t* phase = particles.phase();
    const auto solid = static_cast<std::int32_t>(Phase::solid);
    // Contacts are ordered by particle: one thread per run of the same particle would be finer, but
    // the contacts are few; a serial pass keeps the order fixed.
    for (const auto& c : contacts_) {
        const Index a = c.particle;
        if (!c.touching || phase[a] != solid || (fixed && fixed[a])) continue;
        acc[a] += c.force * (1.0 / m[a]);
    }
    Vec* f = grains.force();
    auto* t = grains.torque();
    parallel::for_each(grains.size(), [&](Index g) {
        for (Index k = grain_start_[g]; k < grain_start_[g + 1]; ++k) {
            const auto& c = contacts_[static_cast<std::size_t>(grain_order_[k])];
            if (!c.touching) continue;
            f[g] -= c.force;                                  // Newton's third law, applied at p
            t[g] += dem::moment<Dim>(c.lever, -c.force);      // eq. (14)
        }
    });
}

template class GrainBoundaryContact<2>;
template class GrainBoundaryContact<3>;

}  // namespace grit::coupling
