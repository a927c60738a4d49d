// Penalty contact between grains and SPH solid/wall particles (first seed paper eqs. 12-14).
#include "grit/coupling/grain_boundary_contact.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "grit/dem/spin.hpp"
#include "grit/neighbors/cell_grid.hpp"
#include "grit/parallel/parallel.hpp"

namespace grit::coupling {

namespace {

// Calls f(grain) for the grains in the cells around x (the grid's cells are at least one reach wide).
template <int Dim, class F>
void for_grains_near(const neighbors::CellGrid<Dim>& grid, const std::vector<Index>& cell_start,
                     const std::vector<Index>& order, const core::Vec<Dim>& x, F&& f) {
    const auto c = grid.coords(x);
    std::array<Index, Dim> lo{}, hi{};
    for (int k = 0; k < Dim; ++k) {
        lo[k] = std::max<Index>(c[k] - 1, 0);
        hi[k] = std::min<Index>(c[k] + 1, grid.dims[k] - 1);
    }
    std::array<Index, Dim> cc = lo;
    for (;;) {
        const Index cell = grid.linear(cc);
        for (Index k = cell_start[cell]; k < cell_start[cell + 1]; ++k) f(order[k]);
        int d = 0;
        while (d < Dim && ++cc[d] > hi[d]) cc[d] = lo[d], ++d;
        if (d == Dim) break;
    }
}

}  // namespace

template <int Dim>
void GrainBoundaryContact<Dim>::compute(const dem::GrainSet<Dim>& grains,
                                        const particles::SphParticles<Dim>& particles, double dt) {
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
    const double largest = parallel::max(ng, 0.0, [&](Index i) { return radius[i]; });
    const double near_distance = 2.0 * d_ini;  // pairs listed (the log's release distance)
    const double reach = largest + near_distance;

    // Grains binned on a grid one reach wide; particles outside the grains' box (grown by the reach)
    // are skipped at once.
    const auto grid = neighbors::CellGrid<Dim>::covering(xg, ng, reach);
    std::vector<Index> order, cell_start;
    neighbors::sort_by_cell(grid, xg, ng, order, cell_start);
    Vec lo = Vec::zero(), hi = Vec::zero();
    for (int k = 0; k < Dim; ++k) {
        lo[k] = parallel::min(ng, 1e300, [&](Index i) { return xg[i][k]; }) - reach;
        hi[k] = parallel::max(ng, -1e300, [&](Index i) { return xg[i][k]; }) + reach;
    }

    const Index n = particles.size();
    const Vec* x = particles.position();
    const Vec* v = particles.velocity();
    const double* m = particles.mass();
    const std::int32_t* phase = particles.phase();
    const auto solid = static_cast<std::int32_t>(Phase::solid), wall = static_cast<std::int32_t>(Phase::wall);
    auto candidate = [&](Index a) {
        if (phase[a] != solid && phase[a] != wall) return false;
        for (int k = 0; k < Dim; ++k)
            if (x[a][k] < lo[k] || x[a][k] > hi[k]) return false;
        return true;
    };
    auto touches = [&](Index a, Index i) {
        const double r2 = core::norm2(x[a] - xg[i]);
        const double reach_i = radius[i] + near_distance;
        return r2 < reach_i * reach_i;
    };

    // Two passes (count, then fill) keep the contacts ordered by particle at any thread count.
    std::vector<Index> count(static_cast<std::size_t>(n) + 1, 0);
    parallel::for_each(n, [&](Index a) {
        if (!candidate(a)) return;
        Index c = 0;
        for_grains_near(grid, cell_start, order, x[a], [&](Index i) { c += touches(a, i) ? 1 : 0; });
        count[static_cast<std::size_t>(a) + 1] = c;
    });
    for (Index a = 0; a < n; ++a) count[a + 1] += count[a];
    contacts_.resize(static_cast<std::size_t>(count[n]));
    if (contacts_.empty()) return;

    const double chi = parameters_.overlap_coefficient, mu = parameters_.friction;
    parallel::for_each(n, [&](Index a) {
        if (count[a + 1] == count[a]) return;
        Index slot = count[a];
        // The particle's grains in ascending index, whatever order the cells give them (contacts are
        // few, so the small allocation is rare).
        std::vector<Index> all;
        for_grains_near(grid, cell_start, order, x[a], [&](Index i) {
            if (touches(a, i)) all.push_back(i);
        });
        std::sort(all.begin(), all.end());
        for (const Index i : all) {
            PenaltyContact<Dim>& c = contacts_[static_cast<std::size_t>(slot++)];
            const Vec r = x[a] - xg[i];
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
