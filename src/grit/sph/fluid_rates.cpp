// The fluid SPH sums, one gather loop over fluid particles, dispatched once on the kernel type.
#include "grit/sph/fluid_rates.hpp"

#include <cmath>

#include "grit/parallel/parallel.hpp"
#include "grit/sph/artificial_viscosity.hpp"

namespace grit::sph {

namespace {

template <int Dim, class K>
void fluid_rates_loop(particles::SphParticles<Dim>& ps, const neighbors::NeighborList<Dim>& nl, const K& kernel,
                      const FluidRateParameters<Dim>& prm) {
    using Vec = core::Vec<Dim>;
    const Vec* x = ps.position();
    const Vec* v = ps.velocity();
    const double* rho = ps.density();
    const double* p = ps.pressure();
    const double* m = ps.mass();
    const std::int32_t* phase = ps.phase();
    const std::int32_t* mat = ps.material();
    Vec* acc = ps.acceleration();
    double* drho = ps.density_rate();
    const Index* nbr = nl.indices();
    const PairCoefficients* coef = prm.materials.data();

    const double h = kernel.h;
    const double support2 = kernel.support() * kernel.support();
    const double eps_h2 = 0.01 * h * h;  // regularisation of eqs. (25) and (27)
    const double delta = prm.density_diffusion;
    const Vec g = prm.gravity;
    const ArtificialViscosity av{h};
    const auto fluid = static_cast<std::int32_t>(Phase::fluid);

    parallel::for_each(ps.size(), [&](Index a) {
        if (phase[a] != fluid) return;
        const Vec xa = x[a];
        const Vec va = v[a];
        const double rho_a = rho[a];
        const double p_over_rho2_a = p[a] / (rho_a * rho_a);
        const PairCoefficients& ca = coef[mat[a]];
        const double diffusion_scale = 2.0 * delta * h * ca.sound_speed;
        const double hydrostatic_scale = ca.reference_density / (ca.sound_speed * ca.sound_speed);

        Vec dv = Vec::zero();
        double continuity = 0.0;  // sum_b m_b / rho_b v_ab . grad W
        double diffusion = 0.0;
        for (Index k = nl.begin(a); k < nl.end(a); ++k) {
            const Index b = nbr[k];
            const Vec xab = xa - x[b];
            const double r2 = core::norm2(xab);
            if (r2 >= support2) continue;
            const double r = std::sqrt(r2);
            const double f = kernel.gradient_factor(r);  // grad_a W_ab = xab * f
            const Vec vab = va - v[b];
            const double vx = core::dot(vab, xab);
            const double rho_b = rho[b];
            const double volume_b = m[b] / rho_b;
            const PairCoefficients& cb = coef[mat[b]];

            continuity += volume_b * vx * f;  // eq. (22)

            // Pressure (eq. 23) and artificial viscosity (eqs. 26-27), both along grad W.
            double scalar = -(p_over_rho2_a + p[b] / (rho_b * rho_b));
            if (vx < 0.0) {
                scalar -= av.pi(vx, r2, 0.5 * (ca.sound_speed + cb.sound_speed), 0.5 * (rho_a + rho_b),
                                0.5 * (ca.alpha + cb.alpha), 0.5 * (ca.beta + cb.beta));
            }
            dv += xab * (m[b] * scalar * f);

            // Laminar viscosity, eq. (25) in the form of Lo & Shao (2002), along v_ab.
            const double nu = 0.5 * (ca.kinematic_viscosity + cb.kinematic_viscosity);
            if (nu > 0.0) dv += vab * (m[b] * 4.0 * nu * r2 * f / ((rho_a + rho_b) * (r2 + eps_h2)));

            // Density diffusion between fluid particles, less its hydrostatic part.
            if (delta > 0.0 && phase[b] == fluid) {
                const double hydrostatic = hydrostatic_scale * core::dot(g, xab);  // rho^H_a - rho^H_b
                diffusion += volume_b * ((rho_a - rho_b) - hydrostatic) * r2 * f / (r2 + eps_h2);
            }
        }
        drho[a] = rho_a * continuity + diffusion_scale * diffusion;
        acc[a] = dv + g;
    });
}

}  // namespace

template <int Dim>
void compute_fluid_rates(particles::SphParticles<Dim>& particles, const neighbors::NeighborList<Dim>& neighbors,
                         const Kernel<Dim>& kernel, const FluidRateParameters<Dim>& parameters) {
    std::visit([&](const auto& k) { fluid_rates_loop(particles, neighbors, k, parameters); }, kernel);
}

template void compute_fluid_rates<2>(particles::SphParticles<2>&, const neighbors::NeighborList<2>&,
                                     const Kernel<2>&, const FluidRateParameters<2>&);
template void compute_fluid_rates<3>(particles::SphParticles<3>&, const neighbors::NeighborList<3>&,
                                     const Kernel<3>&, const FluidRateParameters<3>&);

}  // namespace grit::sph
