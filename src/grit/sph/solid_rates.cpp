// The solid SPH sums, one gather loop over solid particles, dispatched once on the kernel type.
#include "grit/sph/solid_rates.hpp"

#include <algorithm>
#include <cmath>

#include "grit/parallel/parallel.hpp"
#include <Eigen/Dense>

#include "grit/sph/artificial_stress.hpp"

namespace grit::sph {

namespace {

template <int Dim, class K>
void solid_rates_loop(particles::SphParticles<Dim>& ps, const neighbors::NeighborList<Dim>& nl, const K& kernel,
                      const SolidRateParameters<Dim>& prm, const FluidWorkspace& sph, SolidWorkspace& work) {
    using Vec = core::Vec<Dim>;
    using core::SymTensor3;
    const Index n = ps.size();
    const Vec* x = ps.position();
    const Vec* v = ps.velocity();
    const double* rho = ps.density();
    const double* p = ps.pressure();
    const double* m = ps.mass();
    const std::int32_t* phase = ps.phase();
    const std::int32_t* mat = ps.material();
    const SymTensor3* tau = ps.fields().template get<SymTensor3>("deviatoric_stress").data();
    Vec* acc = ps.acceleration();
    double* drho = ps.density_rate();
    const Index* nbr = nl.indices();
    const PairCoefficients* coef = prm.materials.data();
    const double* p_term = sph.pressure_term.data();
    const double* volume = sph.volume.data();
    const auto solid = static_cast<std::int32_t>(Phase::solid);

    work.strain_rate.assign(static_cast<std::size_t>(n), SymTensor3::zero());
    work.spin.assign(static_cast<std::size_t>(n), material::Spin{});
    work.artificial_stress.assign(static_cast<std::size_t>(n), SymTensor3::zero());
    work.energy_rate.assign(static_cast<std::size_t>(n), 0.0);
    SymTensor3* strain_rate = work.strain_rate.data();
    material::Spin* spin = work.spin.data();
    SymTensor3* art = work.artificial_stress.data();
    double* de = work.energy_rate.data();

    // Artificial stress of each solid particle from its total stress sigma = -p I + tau.
    const double eps_as = prm.artificial_stress;
    if (eps_as > 0.0) {
        parallel::for_each(n, [&](Index i) {
            if (phase[i] != solid) return;
            const SymTensor3 sigma = tau[i] - SymTensor3::identity() * p[i];
            art[i] = artificial_stress(sigma, rho[i], eps_as, Dim == 2);
        });
    }
    const double w_dx = kernel.value(prm.spacing);
    const double as_n = prm.artificial_stress_exponent;

    const double h = kernel.h;
    const double eps_h2 = 0.01 * h * h;
    const Vec g = prm.gravity;

    parallel::for_each(n, [&](Index a) {
        if (phase[a] != solid) return;
        const Vec xa = x[a];
        const Vec va = v[a];
        const double rho_a = rho[a];
        const double p_term_a = p_term[a];
        const double inv_rho2_a = 1.0 / (rho_a * rho_a);
        const SymTensor3 tau_a = tau[a] * inv_rho2_a;
        const SymTensor3 art_a = art[a];
        const PairCoefficients& ca = coef[mat[a]];

        // Kernel gradient correction for the velocity gradient (Randles & Libersky 1996; second seed
        // paper eq. 8): L = [sum_b V_b grad_a W_ab (x) (x_b - x_a)]^-1 over solid neighbours, so that eq.
        // (31) is exact for linear velocity fields, also at free surfaces, where the plain sum sees half a
        // kernel and underestimates tangential strain rates by half (a bending plate turns soft).
        double mm[3][3] = {{0.0, 0.0, 0.0}, {0.0, 0.0, 0.0}, {0.0, 0.0, 0.0}};
        for (Index k = nl.begin(a); k < nl.end(a); ++k) {
            const Index b = nbr[k];
            if (phase[b] != solid) continue;
            const Vec xab = xa - x[b];
            const double f = kernel.gradient_factor(std::sqrt(core::norm2(xab)));
            for (int i = 0; i < Dim; ++i)
                for (int j = 0; j < Dim; ++j) mm[i][j] -= volume[b] * f * xab[i] * xab[j];
        }
        double corr[3][3] = {{1.0, 0.0, 0.0}, {0.0, 1.0, 0.0}, {0.0, 0.0, 1.0}};
        if constexpr (Dim == 2) {
            const double det = mm[0][0] * mm[1][1] - mm[0][1] * mm[1][0];
            if (std::abs(det) > 1e-6) {
                corr[0][0] = mm[1][1] / det;
                corr[1][1] = mm[0][0] / det;
                corr[0][1] = -mm[0][1] / det;
                corr[1][0] = -mm[1][0] / det;
            }
        } else {
            Eigen::Matrix3d m3;
            m3 << mm[0][0], mm[0][1], mm[0][2], mm[1][0], mm[1][1], mm[1][2], mm[2][0], mm[2][1], mm[2][2];
            if (std::abs(m3.determinant()) > 1e-6) {
                const Eigen::Matrix3d inv = m3.inverse();
                for (int i = 0; i < 3; ++i)
                    for (int j = 0; j < 3; ++j) corr[i][j] = inv(i, j);
            }
        }

        Vec dv = Vec::zero();
        double continuity = 0.0, work_rate = 0.0;
        SymTensor3 grad_v_sym = SymTensor3::zero();
        material::Spin w{};
        for (Index k = nl.begin(a); k < nl.end(a); ++k) {
            const Index b = nbr[k];
            const Vec xab = xa - x[b];
            const double r2 = core::norm2(xab);
            const double r = std::sqrt(r2);
            const double f = kernel.gradient_factor(r);
            if (f == 0.0) continue;
            const Vec vab = va - v[b];
            const double vx = core::dot(vab, xab);
            const double volume_b = volume[b];
            const PairCoefficients& cb = coef[mat[b]];

            if (phase[b] == static_cast<std::int32_t>(Phase::wall)) continuity += volume_b * vx * f;  // eq. (28) with walls

            // Pressure and artificial viscosity with every neighbour (eq. 29, first sum).
            const double phi = h * std::min(vx, 0.0) / (r2 + eps_h2);
            const double pi_ab = (-0.5 * (ca.alpha + cb.alpha) * 0.5 * (ca.sound_speed + cb.sound_speed) * phi +
                                  0.5 * (ca.beta + cb.beta) * phi * phi) /
                                 (0.5 * (rho_a + rho[b]));
            // Multi-phase pressure form across a fluid-solid interface, as in the fluid sums.
            const double pressure = phase[b] != solid && phase[b] != static_cast<std::int32_t>(Phase::wall)
                                        ? (p_term_a * rho_a / rho[b] + p_term[b] * rho[b] / rho_a)
                                        : (p_term_a + p_term[b]);
            dv += xab * (m[b] * (-pressure - pi_ab) * f);
            work_rate += 0.5 * m[b] * (pressure + pi_ab) * vx * f;

            if (phase[b] != solid) continue;
            // Deviatoric stress (eq. 29, second sum) and artificial stress, between solids.
            SymTensor3 t = tau_a + tau[b] * (1.0 / (rho[b] * rho[b]));
            if (eps_as > 0.0) {
                const double fab = std::pow(kernel.value(r) / w_dx, as_n);
                t += (art_a + art[b]) * fab;
            }
            const double gx = xab[0] * f, gy = xab[1] * f, gz = Dim == 3 ? xab[Dim - 1] * f : 0.0;
            dv[0] += m[b] * (t.xx * gx + t.xy * gy + t.zx * gz);
            dv[1] += m[b] * (t.xy * gx + t.yy * gy + t.yz * gz);
            if constexpr (Dim == 3) dv[Dim - 1] += m[b] * (t.zx * gx + t.yz * gy + t.zz * gz);

            // Strain rate and spin, eq. (31), with v_ba = -v_ab and the corrected kernel gradient L grad W.
            const double ux = -vab[0] * volume_b, uy = -vab[1] * volume_b, uz = Dim == 3 ? -vab[Dim - 1] * volume_b : 0.0;
            const double cx = corr[0][0] * gx + corr[0][1] * gy + corr[0][2] * gz;
            const double cy = corr[1][0] * gx + corr[1][1] * gy + corr[1][2] * gz;
            const double cz = corr[2][0] * gx + corr[2][1] * gy + corr[2][2] * gz;
            grad_v_sym.xx += ux * cx;
            grad_v_sym.yy += uy * cy;
            grad_v_sym.zz += uz * cz;
            grad_v_sym.xy += 0.5 * (ux * cy + uy * cx);
            grad_v_sym.yz += 0.5 * (uy * cz + uz * cy);
            grad_v_sym.zx += 0.5 * (uz * cx + ux * cz);
            w.xy += 0.5 * (ux * cy - uy * cx);
            w.yz += 0.5 * (uy * cz - uz * cy);
            w.zx += 0.5 * (uz * cx - ux * cz);
        }
        // Eq. (28) between solids with the corrected gradient: rho_dot = -rho tr(grad v). The plain sum
        // sees half a kernel at a free surface and would halve the volumetric stiffness of the surface
        // layer, which carries most of a bending stress.
        drho[a] = rho_a * (continuity - grad_v_sym.trace());
        acc[a] = dv + g;
        strain_rate[a] = grad_v_sym;
        spin[a] = w;
        // Internal energy: pressure work and artificial-viscosity heating from the pair sums, plus the
        // deviatoric work tau : eps_dot / rho.
        de[a] = work_rate + tau[a].contract(grad_v_sym) / rho_a;
    });
}

}  // namespace

template <int Dim>
void compute_solid_rates(particles::SphParticles<Dim>& particles, const neighbors::NeighborList<Dim>& neighbors,
                         const Kernel<Dim>& kernel, const SolidRateParameters<Dim>& parameters,
                         const FluidWorkspace& sph, SolidWorkspace& workspace) {
    std::visit([&](const auto& k) { solid_rates_loop(particles, neighbors, k, parameters, sph, workspace); }, kernel);
}

template void compute_solid_rates<2>(particles::SphParticles<2>&, const neighbors::NeighborList<2>&, const Kernel<2>&,
                                     const SolidRateParameters<2>&, const FluidWorkspace&, SolidWorkspace&);
template void compute_solid_rates<3>(particles::SphParticles<3>&, const neighbors::NeighborList<3>&, const Kernel<3>&,
                                     const SolidRateParameters<3>&, const FluidWorkspace&, SolidWorkspace&);

}  // namespace grit::sph
