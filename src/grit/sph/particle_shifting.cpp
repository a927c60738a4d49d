// Particle shifting: two gather loops over the fluid particles (the shift, then the velocity
// correction that needs every particle's shift settled).
#include "grit/sph/particle_shifting.hpp"

#include <cmath>

#include "grit/parallel/parallel.hpp"

namespace grit::sph {

namespace {
constexpr double anti_pairing = 0.2;  ///< R of Lind et al. (2012) eq. 25, with exponent 4
constexpr double max_shift = 0.2;     ///< of dx, a step
}  // namespace

template <int Dim>
void shift_particles(particles::SphParticles<Dim>& ps, const neighbors::NeighborList<Dim>& nl,
                     const Kernel<Dim>& kernel, const ShiftingSettings<Dim>& s, double dt,
                     const std::int32_t* free_surface, std::vector<core::Vec<Dim>>& shift) {
    using Vec = core::Vec<Dim>;
    const Index n = ps.size();
    shift.assign(static_cast<std::size_t>(n), Vec::zero());
    Vec* x = ps.position();
    Vec* v = ps.velocity();
    Vec* v_half = ps.velocity_half();
    const double* rho = ps.density();
    const double* m = ps.mass();
    const std::int32_t* ph = ps.phase();
    const Index* nbr = nl.indices();
    std::visit(
        [&](const auto& k) {
            neighbors::with_image(s.periodic_box, [&](const auto image) {
                const double support2 = k.support() * k.support();
                const double inv_w_dx = 1.0 / k.value(s.spacing);
                const double cap = max_shift * s.spacing;
                parallel::for_each_dynamic(n, [&](Index a) {
                    if (ph[a] != fluid_phase) return;
                    Vec grad_c = Vec::zero(), colour = Vec::zero();
                    bool near_surface = free_surface[a] != 0;
                    for (Index e = nl.begin(a); e < nl.end(a); ++e) {
                        const Index b = nbr[e];
                        if (ph[b] != fluid_phase && ph[b] != wall_phase) continue;
                        const Vec xab = image(x[a] - x[b]);
                        const double r2 = core::norm2(xab);
                        if (r2 >= support2) continue;
                        const double r = std::sqrt(r2);
                        const Vec grad = xab * (m[b] / rho[b] * k.gradient_factor(r));
                        const double ratio = k.value(r) * inv_w_dx;
                        grad_c += grad * (1.0 + anti_pairing * ratio * ratio * ratio * ratio);
                        colour += grad;
                        if (ph[b] == fluid_phase && free_surface[b] != 0) near_surface = true;
                    }
                    Vec dr = grad_c * (-s.coefficient * k.h * std::sqrt(core::norm2(v[a])) * dt);
                    if (near_surface) {  // tangential only: the inward normal is along colour
                        const double c = std::sqrt(core::norm2(colour));
                        if (c > 0.0) {
                            const Vec normal = colour * (1.0 / c);
                            dr -= normal * core::dot(dr, normal);
                        }
                    }
                    const double length = std::sqrt(core::norm2(dr));
                    if (length > cap) dr *= cap / length;
                    shift[static_cast<std::size_t>(a)] = dr;
                });
                // v_a += (dr_a . grad) v_a with grad v_a = sum_b V_b (v_b - v_a) (x) grad_a W_ab
                std::vector<Vec> dv(static_cast<std::size_t>(n), Vec::zero());
                parallel::for_each_dynamic(n, [&](Index a) {
                    const Vec& dr = shift[static_cast<std::size_t>(a)];
                    if (ph[a] != fluid_phase || core::norm2(dr) == 0.0) return;
                    Vec sum = Vec::zero();
                    for (Index e = nl.begin(a); e < nl.end(a); ++e) {
                        const Index b = nbr[e];
                        if (ph[b] != fluid_phase && ph[b] != wall_phase) continue;
                        const Vec xab = image(x[a] - x[b]);
                        const double r2 = core::norm2(xab);
                        if (r2 >= support2) continue;
                        sum += (v[b] - v[a]) * (m[b] / rho[b] * k.gradient_factor(std::sqrt(r2)) * core::dot(xab, dr));
                    }
                    dv[static_cast<std::size_t>(a)] = sum;
                });
                parallel::for_each(n, [&](Index a) {
                    if (ph[a] != fluid_phase) return;
                    const auto i = static_cast<std::size_t>(a);
                    x[a] += shift[i];
                    if (s.periodic_box.any()) x[a] = s.periodic_box.wrap(x[a]);
                    v[a] += dv[i];
                    v_half[a] = v[a];
                });
            });
        },
        kernel);
}

template void shift_particles<2>(particles::SphParticles<2>&, const neighbors::NeighborList<2>&, const Kernel<2>&,
                                 const ShiftingSettings<2>&, double, const std::int32_t*, std::vector<core::Vec<2>>&);
template void shift_particles<3>(particles::SphParticles<3>&, const neighbors::NeighborList<3>&, const Kernel<3>&,
                                 const ShiftingSettings<3>&, double, const std::int32_t*, std::vector<core::Vec<3>>&);

}  // namespace grit::sph
