// Unresolved fluid-grain coupling: pairs, porosity (eq. 20), grain force (eqs. 42-49), reaction (eq. 50).
#include "grit/coupling/fluid_grain_coupling.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "grit/parallel/parallel.hpp"

namespace grit::coupling {

namespace {
/// The skin of the candidate pairs, as a fraction of the smallest R_c,i: wider means fewer grid searches
/// and more candidates to test each step (docs/performance.md, "Coupling pairs kept with a skin").
constexpr double candidate_skin = 0.2;
}  // namespace

template <int Dim>
void FluidGrainCoupling<Dim>::find_pairs(const dem::GrainSet<Dim>& grains,
                                          const particles::SphParticles<Dim>& particles) {
    const Index ng = grains.size(), n = particles.size();
    const double* radius = grains.radius();
    reach_.resize(static_cast<std::size_t>(ng));
    for (Index i = 0; i < ng; ++i) reach_[static_cast<std::size_t>(i)] = parameters_.radius_factor * 2.0 * radius[i];
    const std::int32_t* phase = particles.phase();
    const auto fluid = static_cast<std::int32_t>(Phase::fluid), wall = static_cast<std::int32_t>(Phase::wall),
               solid = static_cast<std::int32_t>(Phase::solid);
    // Each fluid, wall or SPH solid particle's grains closer than R_c,i, in ascending grain index. The
    // walls only complete a grain's kernel: its immersed fraction and -grad p at it; the solids its
    // immersed fraction alone (exchange_forces). The grid search (most of this stage where grains step
    // far more often than the fluid's lists are rebuilt) runs only when the candidates within R_c,i +
    // skin go stale.
    if (candidates_stale(grains, particles)) {
        skin_ = ng > 0 ? candidate_skin * *std::min_element(reach_.begin(), reach_.end()) : 0.0;
        candidates_.build(
            particles.position(), n,
            [&](Index a) { return phase[a] == fluid || phase[a] == wall || phase[a] == solid; },
            grains.position(), reach_.data(), ng, skin_, box_);
        candidate_generation_ = particles.generation();
        particle_at_search_.assign(particles.position(), particles.position() + n);
        grain_at_search_.assign(grains.position(), grains.position() + ng);
        grain_ids_at_search_.assign(grains.id(), grains.id() + ng);
        ++candidate_builds_;
    }
    pairs_.refine(candidates_, particles.position(), grains.position(), reach_.data(), 0.0, box_);

    const std::size_t np = pairs_.pair_count();
    weight_.resize(np);
    pair_particle_.resize(np);
    const Vec* x = particles.position();
    const Vec* xg = grains.position();
    const Index* idx = pairs_.indices();
    std::visit(
        [&](const auto& type) {
            using K = std::decay_t<decltype(type)>;
            std::vector<K> kernel;
            kernel.reserve(static_cast<std::size_t>(ng));
            for (Index i = 0; i < ng; ++i) kernel.emplace_back(0.5 * reach_[static_cast<std::size_t>(i)]);
            parallel::for_each(n, [&](Index a) {
                for (Index s = pairs_.begin(a); s < pairs_.end(a); ++s) {
                    const Index i = idx[s];
                    weight_[static_cast<std::size_t>(s)] =
                        kernel[static_cast<std::size_t>(i)].value(std::sqrt(core::norm2(box_.nearest_image(x[a] - xg[i]))));
                    pair_particle_[static_cast<std::size_t>(s)] = a;
                }
            });
        },
        kernel_type_);

    // The grain side: each grain's pairs in particle order (fixed at any thread count), those with water
    // and walls and, apart, those with SPH solids (which only complete the immersed fraction).
    auto order_by_grain = [&](bool with_solids, std::vector<Index>& start, std::vector<Index>& order) {
        auto wanted = [&](std::size_t s) { return (phase[pair_particle_[s]] == solid) == with_solids; };
        start.assign(static_cast<std::size_t>(ng) + 1, 0);
        for (std::size_t s = 0; s < np; ++s)
            if (wanted(s)) ++start[static_cast<std::size_t>(idx[s]) + 1];
        for (Index i = 0; i < ng; ++i) start[static_cast<std::size_t>(i) + 1] += start[static_cast<std::size_t>(i)];
        order.resize(static_cast<std::size_t>(start.back()));
        std::vector<Index> next(start.begin(), start.end() - 1);
        for (std::size_t s = 0; s < np; ++s)
            if (wanted(s)) order[static_cast<std::size_t>(next[static_cast<std::size_t>(idx[s])]++)] = static_cast<Index>(s);
    };
    order_by_grain(false, grain_start_, grain_order_);
    order_by_grain(true, solid_start_, solid_order_);
}

template <int Dim>
bool FluidGrainCoupling<Dim>::candidates_stale(const dem::GrainSet<Dim>& grains,
                                               const particles::SphParticles<Dim>& particles) const {
    const Index ng = grains.size(), n = particles.size();
    if (particles.generation() != candidate_generation_ || static_cast<std::size_t>(n) != particle_at_search_.size() ||
        static_cast<std::size_t>(ng) != grain_at_search_.size())
        return true;
    const domain::ParticleId* id = grains.id();
    for (Index i = 0; i < ng; ++i)
        if (id[i] != grain_ids_at_search_[static_cast<std::size_t>(i)]) return true;  // fed, left or re-sorted
    // A pair missing from the candidates was R_c,i + skin apart at the search: it can be within R_c,i now
    // only if the particle and the grain moved more than the skin between them. Positions are compared
    // as stored (a wrap across a periodic face reads as a long move: a search, never a missed pair).
    const Vec* x = particles.position();
    const Vec* xg = grains.position();
    const double moved_particles = parallel::max(n, 0.0, [&](Index a) {
        return core::norm2(x[a] - particle_at_search_[static_cast<std::size_t>(a)]);
    });
    const double moved_grains = parallel::max(ng, 0.0, [&](Index i) {
        return core::norm2(xg[i] - grain_at_search_[static_cast<std::size_t>(i)]);
    });
    return std::sqrt(moved_particles) + std::sqrt(moved_grains) >= (1.0 - 1e-9) * skin_;  // margin: rounding
}

template <int Dim>
void FluidGrainCoupling<Dim>::compute_porosity(const dem::GrainSet<Dim>& grains,
                                               const particles::SphParticles<Dim>& particles,
                                               double* porosity) const {
    const double* radius = grains.radius();
    const Index* idx = pairs_.indices();
    const double floor = parameters_.min_porosity;
    const std::int32_t* phase = particles.phase();
    const auto fluid = static_cast<std::int32_t>(Phase::fluid);
    parallel::for_each(particles.size(), [&](Index a) {
        if (phase[a] != fluid) {
            porosity[a] = 1.0;
            return;
        }
        double solid = 0.0;  // sum_i V_i W_ai
        for (Index s = pairs_.begin(a); s < pairs_.end(a); ++s)
            solid += grain_volume<Dim>(radius[idx[s]]) * weight_[static_cast<std::size_t>(s)];
        porosity[a] = std::max(1.0 - solid, floor);
    });
}

template <int Dim>
void FluidGrainCoupling<Dim>::exchange_forces(dem::GrainSet<Dim>& grains, particles::SphParticles<Dim>& particles,
                                              const double* porosity, Vec* fluid_force,
                                              Vec* drag_force) {
    const Index ng = grains.size();
    const std::size_t ngs = static_cast<std::size_t>(ng);
    grain_.shepard.assign(ngs, 0.0);
    grain_.porosity.assign(ngs, 1.0);
    grain_.drag_coefficient.assign(ngs, 0.0);
    grain_force_.assign(ngs, Vec::zero());
    stable_dt_ = 1e300;
    if (pairs_.pair_count() == 0) {
        for (Index i = 0; i < ng; ++i) fluid_force[i] = drag_force[i] = Vec::zero();
        return;
    }

    const Vec* v = particles.velocity();
    const double* m = particles.mass();
    const double* rho = particles.density();  // rho_bar, the locally averaged density (eq. 21)
    const double* radius = grains.radius();
    const double* grain_mass = grains.mass();
    const Vec* vg = grains.velocity();
    Vec* fg = grains.force();
    const CouplingParameters& prm = parameters_;

    // Grain side (eqs. 42-49): sums over the grain's fluid particles, in particle order. First the
    // Shepard values at the grain (S_i, eps_i, v_f and the pressure p_i), then -grad p and div tau =
    // mu lap v at the grain in difference forms, which vanish for uniform p and v however much of the
    // kernel is empty (a grain entering the jet, the free surface).
    const double* p = particles.pressure();
    const Vec* x = particles.position();
    const Vec* xg = grains.position();
    const double mu = prm.viscosity;
    const std::int32_t* phase = particles.phase();
    const auto fluid = static_cast<std::int32_t>(Phase::fluid);
    std::visit(
        [&](const auto& type) {
            using K = std::decay_t<decltype(type)>;
            parallel::for_each(ng, [&](Index i) {
                const auto gi = static_cast<std::size_t>(i);
                const Index first = grain_start_[gi], last = grain_start_[gi + 1];
                // Wall particles (their Adami pressure: the fluid's, continued into the wall) complete the
                // kernel for the pressure and the immersed fraction; v_f and eps are the water's alone.
                // SPH solid particles (an AWJ's target; their pairs apart) complete the immersed fraction
                // only: their pressure is the solid's mean stress, not the water's.
                double shepard = 0.0, eps = 0.0, pressure = 0.0, walls = 0.0, wall_pressure = 0.0, solids = 0.0;
                for (Index k = solid_start_[gi]; k < solid_start_[gi + 1]; ++k) {
                    const auto s = static_cast<std::size_t>(solid_order_[static_cast<std::size_t>(k)]);
                    const Index a = pair_particle_[s];
                    solids += m[a] / rho[a] * weight_[s];  // V_s W_is
                }
                Vec vf = Vec::zero();
                for (Index k = first; k < last; ++k) {
                    const auto s = static_cast<std::size_t>(grain_order_[static_cast<std::size_t>(k)]);
                    const Index a = pair_particle_[s];
                    const double vw = m[a] / rho[a] * weight_[s];  // V_a W_ia
                    if (phase[a] != fluid) {
                        walls += vw;
                        wall_pressure += p[a] * vw;
                        continue;
                    }
                    shepard += vw;
                    eps += porosity[a] * vw;
                    vf += v[a] * vw;
                    pressure += p[a] * vw;
                }
                grain_.shepard[gi] = shepard;
                if (!(shepard > 0.0)) {
                    fluid_force[i] = drag_force[i] = Vec::zero();
                    return;
                }
                const double inv = 1.0 / shepard;
                eps *= inv;
                vf *= inv;
                // p_i over water and walls; without walls the water's own form, so that a case without
                // wall particles near its grains keeps its results bit for bit.
                if (walls > 0.0)
                    pressure = (pressure + wall_pressure) / (shepard + walls);
                else
                    pressure *= inv;
                const K kernel(0.5 * reach_[gi]);
                const double eta2 = 0.01 * kernel.h * kernel.h;
                Vec minus_grad_p = Vec::zero(), div_tau = Vec::zero();
                for (Index k = first; k < last; ++k) {
                    const auto s = static_cast<std::size_t>(grain_order_[static_cast<std::size_t>(k)]);
                    const Index a = pair_particle_[s];
                    const Vec xia = box_.nearest_image(xg[i] - x[a]);
                    const double r2 = core::norm2(xia);
                    const double f = kernel.gradient_factor(std::sqrt(r2));  // grad_i W_ia = xia f
                    const double volume_a = m[a] / rho[a];
                    minus_grad_p -= xia * (volume_a * (p[a] - pressure) * f);
                    if (phase[a] != fluid) continue;  // a wall: no velocity of the water's
                    // Morris et al. (1997): lap v = sum_a 2 V_a (v_i - v_a) r^2 f / (r^2 + eta^2), v_i = v_f.
                    div_tau += (vf - v[a]) * (mu * 2.0 * volume_a * r2 * f / (r2 + eta2));
                }
                const double volume = grain_volume<Dim>(radius[i]);
                const Vec u = vf - vg[i];  // v_af (eq. 45)
                DragInput in;
                in.porosity = eps;
                in.relative_speed = core::norm(u);
                in.diameter = 2.0 * radius[i];
                in.volume = volume;
                in.fluid_density = prm.fluid_density;
                in.viscosity = prm.viscosity;
                const double c = drag_coefficient(prm.drag, in);
                // A grain partly out of the fluid (entering a jet, at a free surface) takes the immersed
                // fraction of the force: the part of its kernel that is not air, water S_i, walls and
                // solids (a grain on the floor under water, or at an AWJ target's surface, is wholly
                // immersed, though the floor or the target fills part of its kernel). The reaction (eq.
                // 50) then gives no particle more than V_i W_ai times it, however few particles are near.
                const double immersed = std::min(shepard + walls + solids, 1.0);
                const Vec drag = u * (c * immersed);                                    // eq. (44)
                const Vec force = (minus_grad_p + div_tau) * (volume * immersed) + drag;  // eq. (42)
                grain_.porosity[gi] = eps;
                grain_.drag_coefficient[gi] = c * immersed;
                grain_force_[gi] = force;
                drag_force[i] = drag;
                fluid_force[i] = force;
                fg[i] += force;
            });
        },
        kernel_type_);

    // Fluid side (eq. 50): F_a = -V_a sum_i F_i W_ai / S_i, each particle's grains in ascending order.
    Vec* acc_out = particles.acceleration();
    const Index* idx = pairs_.indices();
    const double* shepard = grain_.shepard.data();
    const double* c = grain_.drag_coefficient.data();
    const Vec* force = grain_force_.data();
    const double fluid_rate = parallel::reduce(
        particles.size(), 0.0,
        [&](Index a) {
            const Index first = pairs_.begin(a), last = pairs_.end(a);
            if (first == last || phase[a] != fluid) return 0.0;
            Vec sum = Vec::zero();
            double rate = 0.0;  // sum_i c_i W_ai / S_i
            for (Index s = first; s < last; ++s) {
                const Index i = idx[s];
                if (!(shepard[i] > 0.0)) continue;
                const double w = weight_[static_cast<std::size_t>(s)] / shepard[i];
                sum += force[i] * w;
                rate += c[i] * w;
            }
            acc_out[a] -= sum * (1.0 / rho[a]);  // F_a / m_a = -(V_a / m_a) sum = -sum / rho_bar_a
            return rate / rho[a];
        },
        [](double l, double r) { return std::max(l, r); });
    const double grain_rate = parallel::reduce(
        ng, 0.0, [&](Index i) { return c[i] / grain_mass[i]; }, [](double l, double r) { return std::max(l, r); });
    const double rate = std::max(fluid_rate, grain_rate);
    stable_dt_ = rate > 0.0 ? 1.0 / rate : 1e300;
}

template class FluidGrainCoupling<2>;
template class FluidGrainCoupling<3>;

}  // namespace grit::coupling
