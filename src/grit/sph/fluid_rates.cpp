// The fluid SPH sums, one gather loop over fluid particles, dispatched once on the kernel type.
#include "grit/sph/fluid_rates.hpp"

#include <cmath>

#include "grit/parallel/parallel.hpp"
#include <algorithm>

#include "grit/neighbors/half_lists.hpp"
#include "grit/sph/artificial_viscosity.hpp"

namespace grit::sph {

namespace {

// Porous: the fluid is coupled to grains; `density` holds rho_bar = eps rho (eq. 21) and the density
// diffusion acts on rho = rho_bar / eps, the density the pressure follows.
// `image` takes x_a - x_b to its nearest periodic image; without periodic axes it is OpenImage, the
// identity, and the loop compiles to what it was before periodic axes existed.
// Corrected: the pressure, artificial viscosity and continuity terms take L_a grad W_ab (eq. 8 of the
// second seed paper) for grad W_ab; the laminar viscosity and the density diffusion, Laplacian forms
// along x_ab, do not.
template <int Dim, class K, bool Porous, bool Corrected, class Image>
void fluid_rates_loop(particles::SphParticles<Dim>& ps, const neighbors::NeighborList<Dim>& nl, const K& kernel,
                      const FluidRateParameters<Dim>& prm, const SphWorkspace& work, const double* porosity,
                      const GradientCorrection<Dim>* correction, const Image image) {
    using Vec = core::Vec<Dim>;
    const Index n = ps.size();
    const Vec* x = ps.position();
    const Vec* v = ps.velocity();
    const double* rho = ps.density();
    const double* m = ps.mass();
    const std::int32_t* phase = ps.phase();
    const std::int32_t* mat = ps.material();
    Vec* acc = ps.acceleration();
    double* drho = ps.density_rate();
    const Index* nbr = nl.indices();
    const PairCoefficients* coef = prm.materials.data();

    const double* p_term = work.pressure_term.data();
    const double* volume = work.volume.data();

    const double h = kernel.h;
    const double eps_h2 = 0.01 * h * h;  // regularisation of eqs. (25) and (27)
    const double delta = prm.density_diffusion;
    const Vec g = prm.gravity;
    const Vec g_hydrostatic = prm.hydrostatic_gravity;
    const auto fluid = static_cast<std::int32_t>(Phase::fluid);
    const auto solid = static_cast<std::int32_t>(Phase::solid);

    parallel::for_each_dynamic(n, [&](Index a) {
        if (phase[a] != fluid) return;
        const Vec xa = x[a];
        const Vec va = v[a];
        const double rho_a = rho[a];
        const double rho_a_true = Porous ? rho_a / porosity[a] : rho_a;
        const double p_term_a = p_term[a];
        const double inv_rho_a = 1.0 / rho_a;
        const PairCoefficients& ca = coef[mat[a]];
        const double diffusion_scale = 2.0 * delta * h * ca.sound_speed;
        const double hydrostatic_scale = ca.reference_density / (ca.sound_speed * ca.sound_speed);
        const GradientCorrection<Dim> La = Corrected ? correction[a] : GradientCorrection<Dim>::identity();

        double dv[Dim] = {};
        double continuity = 0.0;  // sum_b V_b v_ab . grad W
        double diffusion = 0.0;
        const Index first = nl.begin(a), last = nl.end(a);
#pragma omp simd reduction(+ : dv[:Dim], continuity, diffusion)
        for (Index k = first; k < last; ++k) {
            const Index b = nbr[k];
            const Vec xab = image(xa - x[b]);
            const double r2 = core::norm2(xab);
            // Pairs in the list's skin beyond the support get f = 0 and add nothing; testing for
            // them would cost a mispredicted branch, so they go through the same arithmetic.
            const double f = kernel.gradient_factor(std::sqrt(r2));  // grad_a W_ab = xab * f
            const Vec vab = va - v[b];
            const double vx = core::dot(vab, xab);
            const double volume_b = volume[b];
            const PairCoefficients& cb = coef[mat[b]];
            const double inv_r2 = 1.0 / (r2 + eps_h2);
            const double inv_rho_sum = 1.0 / (rho_a + rho[b]);

            if constexpr (Corrected)
                continuity += volume_b * core::dot(vab, La.apply(xab)) * f;
            else
                continuity += volume_b * vx * f;  // eq. (22)

            // Pressure (eq. 23) and artificial viscosity (eqs. 26-27), both along grad W.
            const double pi_ab = artificial_viscosity(h, vx, inv_r2, inv_rho_sum, ca, cb);
            // Across a fluid-solid interface (density ratio up to 9) the pressure term takes the
            // multi-phase form (p_a + p_b) / (rho_a rho_b) of Colagrossi & Landrini (2003); still
            // antisymmetric, so momentum is conserved. Repulsive only: a solid in tension does not pull
            // water into itself (docs/theory.md, "Water inside a solid").
            const double ratio = rho[b] * inv_rho_a;  // rho_b / rho_a
            const double pressure = phase[b] == solid ? std::max(p_term_a / ratio + p_term[b] * ratio, 0.0)
                                                      : (p_term_a + p_term[b]);
            const double along_x = m[b] * (-pressure - pi_ab) * f;

            // Laminar viscosity, eq. (25) in the form of Lo & Shao (2002), along v_ab.
            const double nu = 0.5 * (ca.kinematic_viscosity + cb.kinematic_viscosity);
            const double along_v = m[b] * 4.0 * nu * r2 * f * inv_rho_sum * inv_r2;
            if constexpr (Corrected) {
                const Vec gx = La.apply(xab);
                for (int d = 0; d < Dim; ++d) dv[d] += gx[d] * along_x + vab[d] * along_v;
            } else {
                for (int d = 0; d < Dim; ++d) dv[d] += xab[d] * along_x + vab[d] * along_v;
            }

            // Density diffusion between fluid particles only, less its hydrostatic part.
            const double fluid_b = phase[b] == fluid ? 1.0 : 0.0;
            const double hydrostatic = hydrostatic_scale * core::dot(g_hydrostatic, xab);  // rho^H_a - rho^H_b
            const double rho_b_true = Porous ? rho[b] / porosity[b] : rho[b];
            diffusion += fluid_b * volume_b * ((rho_a_true - rho_b_true) - hydrostatic) * r2 * f * inv_r2;
        }
        Vec total = g;
        for (int d = 0; d < Dim; ++d) total[d] += dv[d];
        acc[a] = total;
        // With grains, d(rho_bar)/dt takes eps_a times the diffusion of rho.
        drho[a] = rho_a * continuity + (Porous ? porosity[a] : 1.0) * diffusion_scale * diffusion;
    });
}

// The same sums with each fluid-fluid pair evaluated once (neighbors::sum_pairs_once): the pair's terms
// go to a with m_b, V_b and to b with -m_a, V_a (momentum and mass conserved pair by pair); the pairs
// with walls and solids are one-sided, as in the gather loop. Without the kernel-gradient correction
// only: with it, a pair's two gradients differ (L_a grad W, L_b grad W). OneMaterial: every fluid particle
// has one material (the common case); a pair's coefficients are then a's, and the means of eqs. (25)-(27)
// are the same numbers (0.5 (c + c) = c exactly), so they are not gathered.
template <int Dim, class K, bool OneMaterial, class Image>
void fluid_rates_pairs_once(particles::SphParticles<Dim>& ps, const K& kernel, const FluidRateParameters<Dim>& prm,
                            const SphWorkspace& work, const double* porosity, FluidPairs<Dim>& pairs,
                            const Image image) {
    using Vec = core::Vec<Dim>;
    using Sum = FluidSum<Dim>;
    const bool porous = porosity != nullptr;  // coupled to grains: `density` holds rho_bar = eps rho (eq. 21)
    const Vec* x = ps.position();
    const Vec* v = ps.velocity();
    const double* rho = ps.density();
    const double* m = ps.mass();
    const std::int32_t* phase = ps.phase();
    const std::int32_t* mat = ps.material();
    Vec* acc = ps.acceleration();
    double* drho = ps.density_rate();
    const neighbors::HalfLists& lists = pairs.lists;
    const Index* upper = lists.upper();
    const Index* other = lists.other();
    const PairCoefficients* coef = prm.materials.data();
    const double* p_term = work.pressure_term.data();
    const double* volume = work.volume.data();

    const double h = kernel.h;
    const double eps_h2 = 0.01 * h * h;
    const double delta = prm.density_diffusion;
    const Vec g = prm.gravity;
    const Vec g_hydrostatic = prm.hydrostatic_gravity;
    const auto solid = static_cast<std::int32_t>(Phase::solid);
    // rho0 / c0^2 of each material: the hydrostatic density difference per unit of g . x_ab.
    std::vector<double> hydrostatic_scales;
    for (const PairCoefficients& c : prm.materials)
        hydrostatic_scales.push_back(c.reference_density / (c.sound_speed * c.sound_speed));
    const double* hydrostatic_scale = hydrostatic_scales.data();
    const std::size_t row_length = static_cast<std::size_t>(lists.longest_upper());

    // Columns of a row, one per gathered or computed value of its pairs (below).
    enum Column : std::size_t { xab_0 = 0, vab_0 = Dim, rho_b_col = 2 * Dim, rho_b_true_col, p_term_b_col, alpha_b_col,
                                beta_b_col, c_b_col, nu_b_col, scale_b_col, force_0, vx_f_col = force_0 + Dim,
                                diffusion_a_col, laplacian_col, diffusion_b_col, column_count };

    auto visit = [&](Index a, Sum& sum_a, auto&& share) {
        // A row's pairs in three loops: the partners' values gathered into contiguous columns (the
        // loads through the list), the pair arithmetic over the columns (no indirection, no branch: it
        // vectorises), then a's sums in list order and b's shares: the terms of a single fused loop, summed
        // in its order (the last bits differ where the compiler fuses other multiply-adds).
        thread_local std::vector<double> rows;
        rows.resize(row_length * column_count);
        double* col[column_count];  // col[c][j]: column c of the row's j-th pair
        for (std::size_t c = 0; c < column_count; ++c) col[c] = rows.data() + row_length * c;

        const Vec xa = x[a];
        const Vec va = v[a];
        const double rho_a = rho[a];
        const double rho_a_true = porous ? rho_a / porosity[a] : rho_a;
        const double p_term_a = p_term[a];
        const double inv_rho_a = 1.0 / rho_a;
        const PairCoefficients& ca = coef[mat[a]];
        const double scale_a = hydrostatic_scale[mat[a]];

        const Index first = lists.upper_begin(a), last = lists.upper_end(a);
        const Index count = last - first;
        for (Index j = 0; j < count; ++j) {
            const Index b = upper[first + j];
            const Vec xab = image(xa - x[b]);
            const Vec vab = va - v[b];
            for (int d = 0; d < Dim; ++d) {
                col[xab_0 + d][j] = xab[d];
                col[vab_0 + d][j] = vab[d];
            }
            col[rho_b_col][j] = rho[b];
            col[rho_b_true_col][j] = porous ? rho[b] / porosity[b] : rho[b];
            col[p_term_b_col][j] = p_term[b];
            if constexpr (!OneMaterial) {
                const PairCoefficients& cb = coef[mat[b]];
                col[alpha_b_col][j] = cb.alpha;
                col[beta_b_col][j] = cb.beta;
                col[c_b_col][j] = cb.sound_speed;
                col[nu_b_col][j] = cb.kinematic_viscosity;
                col[scale_b_col][j] = hydrostatic_scale[mat[b]];
            }
        }
#pragma omp simd
        for (Index j = 0; j < count; ++j) {
            Vec xab, vab;
            for (int d = 0; d < Dim; ++d) {
                xab[d] = col[xab_0 + d][j];
                vab[d] = col[vab_0 + d][j];
            }
            const double r2 = core::norm2(xab);
            const double f = kernel.gradient_factor(std::sqrt(r2));  // grad_a W_ab = xab * f
            const double vx = core::dot(vab, xab);
            PairCoefficients cb = ca;
            double scale_b = scale_a;
            if constexpr (!OneMaterial) {
                cb = PairCoefficients{col[c_b_col][j], 0.0, col[alpha_b_col][j], col[beta_b_col][j], col[nu_b_col][j]};
                scale_b = col[scale_b_col][j];
            }
            const double rho_b = col[rho_b_col][j];
            const double inv_r2 = 1.0 / (r2 + eps_h2);
            const double inv_rho_sum = 1.0 / (rho_a + rho_b);
            // Pressure (eq. 23) and artificial viscosity (eqs. 26-27) along grad W, laminar viscosity
            // (eq. 25, Lo & Shao 2002) along v_ab: the force per unit mass of each particle's partner.
            const double pi_ab = artificial_viscosity(h, vx, inv_r2, inv_rho_sum, ca, cb);
            const double along_x = (-(p_term_a + col[p_term_b_col][j]) - pi_ab) * f;
            const double nu = 0.5 * (ca.kinematic_viscosity + cb.kinematic_viscosity);
            const double along_v = 4.0 * nu * r2 * f * inv_rho_sum * inv_r2;
            for (int d = 0; d < Dim; ++d) col[force_0 + d][j] = xab[d] * along_x + vab[d] * along_v;
            col[vx_f_col][j] = vx * f;  // v_ab . grad_a W_ab, the same seen from b
            // Density diffusion, less its hydrostatic part (rho^H_a - rho^H_b), each side with its own rho0/c0^2.
            const double laplacian = r2 * f * inv_r2;
            const double g_x = core::dot(g_hydrostatic, xab);
            const double rho_b_true = col[rho_b_true_col][j];
            col[diffusion_a_col][j] = (rho_a_true - rho_b_true) - scale_a * g_x;
            col[laplacian_col][j] = laplacian;
            col[diffusion_b_col][j] = ((rho_b_true - rho_a_true) + scale_b * g_x) * laplacian;
        }
        double dv[Dim] = {};
        double continuity = 0.0, diffusion = 0.0;
        const double m_a = m[a], volume_a = volume[a];
        for (Index j = 0; j < count; ++j) {
            const Index b = upper[first + j];
            const double m_b = m[b], volume_b = volume[b];
            for (int d = 0; d < Dim; ++d) dv[d] += m_b * col[force_0 + d][j];
            continuity += volume_b * col[vx_f_col][j];  // eq. (22)
            diffusion += volume_b * col[diffusion_a_col][j] * col[laplacian_col][j];
            Sum& sum_b = share(b);
            for (int d = 0; d < Dim; ++d) sum_b.dv[d] -= m_a * col[force_0 + d][j];
            sum_b.continuity += volume_a * col[vx_f_col][j];
            sum_b.diffusion += volume_a * col[diffusion_b_col][j];
        }

        // Walls and solids, one-sided: pressure (against a solid in the multi-phase form of Colagrossi &
        // Landrini 2003, repulsive only), artificial and laminar viscosity and continuity, no density
        // diffusion.
        const Index first_other = lists.other_begin(a), last_other = lists.other_end(a);
#pragma omp simd reduction(+ : dv[:Dim], continuity)
        for (Index k = first_other; k < last_other; ++k) {
            const Index b = other[k];
            const Vec xab = image(xa - x[b]);
            const double r2 = core::norm2(xab);
            const double f = kernel.gradient_factor(std::sqrt(r2));
            const Vec vab = va - v[b];
            const double vx = core::dot(vab, xab);
            const PairCoefficients& cb = coef[mat[b]];
            const double inv_r2 = 1.0 / (r2 + eps_h2);
            const double inv_rho_sum = 1.0 / (rho_a + rho[b]);
            continuity += volume[b] * vx * f;
            const double pi_ab = artificial_viscosity(h, vx, inv_r2, inv_rho_sum, ca, cb);
            const double ratio = rho[b] * inv_rho_a;  // rho_b / rho_a
            const double pressure = phase[b] == solid ? std::max(p_term_a / ratio + p_term[b] * ratio, 0.0)
                                                      : (p_term_a + p_term[b]);
            const double along_x = m[b] * (-pressure - pi_ab) * f;
            const double nu = 0.5 * (ca.kinematic_viscosity + cb.kinematic_viscosity);
            const double along_v = m[b] * 4.0 * nu * r2 * f * inv_rho_sum * inv_r2;
            for (int d = 0; d < Dim; ++d) dv[d] += xab[d] * along_x + vab[d] * along_v;
        }
        for (int d = 0; d < Dim; ++d) sum_a.dv[d] += dv[d];
        sum_a.continuity += continuity;
        sum_a.diffusion += diffusion;
    };
    auto finish = [&](Index i, const Sum& total) {
        Vec a = g;
        for (int d = 0; d < Dim; ++d) a[d] += total.dv[d];
        acc[i] = a;
        // With grains, d(rho_bar)/dt takes eps_i times the diffusion of rho.
        const double diffusion_scale = 2.0 * delta * h * coef[mat[i]].sound_speed;
        drho[i] = rho[i] * total.continuity + (porous ? porosity[i] : 1.0) * diffusion_scale * total.diffusion;
    };
    neighbors::sum_pairs_once(lists, pairs.own, pairs.spill, visit, finish);
}

}  // namespace

template <int Dim>
void prepare_sph_workspace(const particles::SphParticles<Dim>& ps, SphWorkspace& work) {
    const Index n = ps.size();
    const double* rho = ps.density();
    const double* p = ps.pressure();
    const double* m = ps.mass();
    work.pressure_term.resize(static_cast<std::size_t>(n));
    work.volume.resize(static_cast<std::size_t>(n));
    double* p_term = work.pressure_term.data();
    double* volume = work.volume.data();
    parallel::for_each(n, [&](Index i) {
        const double inv_rho = 1.0 / rho[i];
        p_term[i] = p[i] * inv_rho * inv_rho;
        volume[i] = m[i] * inv_rho;
    });
}

template <int Dim>
void compute_fluid_rates(particles::SphParticles<Dim>& particles, const neighbors::NeighborList<Dim>& neighbors,
                         const Kernel<Dim>& kernel, const FluidRateParameters<Dim>& parameters,
                         const SphWorkspace& workspace, FluidPairs<Dim>& pairs, const double* porosity,
                         const GradientCorrection<Dim>* L) {
    if (!L)
        pairs.lists.update(neighbors.offsets(), neighbors.indices(), neighbors.particle_count(), neighbors.version(),
                           particles.phase(), static_cast<std::int32_t>(Phase::fluid));
    // Whether every fluid particle has the material of the first.
    const Index n = particles.size();
    const std::int32_t* phase = particles.phase();
    const std::int32_t* mat = particles.material();
    const auto fluid = static_cast<std::int32_t>(Phase::fluid);
    const Index first_fluid = parallel::first_index(n, [&](Index i) { return phase[i] == fluid; });
    const bool one_material =
        first_fluid < 0 ||
        parallel::first_index(n, [&](Index i) { return phase[i] == fluid && mat[i] != mat[first_fluid]; }) < 0;
    std::visit(
        [&](const auto& k) {
            using KernelType = std::decay_t<decltype(k)>;
            neighbors::with_image(parameters.periodic_box, [&](const auto image) {
                if (porosity && L)
                    fluid_rates_loop<Dim, KernelType, true, true>(particles, neighbors, k, parameters, workspace,
                                                                  porosity, L, image);
                else if (L)
                    fluid_rates_loop<Dim, KernelType, false, true>(particles, neighbors, k, parameters, workspace,
                                                                   nullptr, L, image);
                else if (one_material)
                    fluid_rates_pairs_once<Dim, KernelType, true>(particles, k, parameters, workspace, porosity,
                                                                  pairs, image);
                else
                    fluid_rates_pairs_once<Dim, KernelType, false>(particles, k, parameters, workspace, porosity,
                                                                   pairs, image);
            });
        },
        kernel);
}

template void prepare_sph_workspace<2>(const particles::SphParticles<2>&, SphWorkspace&);
template void prepare_sph_workspace<3>(const particles::SphParticles<3>&, SphWorkspace&);
template void compute_fluid_rates<2>(particles::SphParticles<2>&, const neighbors::NeighborList<2>&,
                                     const Kernel<2>&, const FluidRateParameters<2>&, const SphWorkspace&,
                                     FluidPairs<2>&, const double*, const GradientCorrection<2>*);
template void compute_fluid_rates<3>(particles::SphParticles<3>&, const neighbors::NeighborList<3>&,
                                     const Kernel<3>&, const FluidRateParameters<3>&, const SphWorkspace&,
                                     FluidPairs<3>&, const double*, const GradientCorrection<3>*);

}  // namespace grit::sph
