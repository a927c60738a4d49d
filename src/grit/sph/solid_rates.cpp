// The solid SPH sums, each solid-solid pair once (neighbors::sum_pairs_once), dispatched once on the
// kernel type.
#include "grit/sph/solid_rates.hpp"

#include <algorithm>
#include <cmath>

#include "grit/neighbors/half_lists.hpp"
#include "grit/parallel/parallel.hpp"

#include "grit/sph/artificial_stress.hpp"
#include "grit/sph/artificial_viscosity.hpp"
#include "grit/sph/correction_matrix.hpp"
#include "grit/sph/tensor_ops.hpp"

namespace grit::sph {

namespace {

// `image` takes x_a - x_b to its nearest periodic image; without periodic axes it is OpenImage, the loop as
// it was before periodic axes.
template <int Dim, class K, class Image>
void solid_rates_loop(particles::SphParticles<Dim>& ps, const neighbors::NeighborList<Dim>& nl, const K& kernel,
                      const SolidRateParameters<Dim>& prm, const SphWorkspace& sph, SolidWorkspace<Dim>& work,
                      const Image image) {
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
    const PairCoefficients* coef = prm.materials.data();
    const double* p_term = sph.pressure_term.data();
    const double* volume = sph.volume.data();
    const auto solid = static_cast<std::int32_t>(Phase::solid);

    // Sized, not cleared: the loops below write every entry they (or the stress update) read. A serial
    // clear of these arrays each step was 8 % of a solid step at 77k particles.
    work.strain_rate.resize(static_cast<std::size_t>(n));
    work.spin.resize(static_cast<std::size_t>(n));
    work.energy_rate.resize(static_cast<std::size_t>(n));
    SymTensor3* strain_rate = work.strain_rate.data();
    material::Spin* spin = work.spin.data();
    double* de = work.energy_rate.data();

    // Packed per solid particle for the pair pass, so a neighbour costs 7 doubles (2D), not 18:
    // M = (sigma / rho^2) L (Dim x Dim, row-major; written by the correction pass) and the in-plane
    // artificial stress R (xx, yy, xy[, zz, yz, zx]; written here).
    constexpr int mm_size = Dim * Dim, r_size = Dim * (Dim + 1) / 2;
    work.stress_correction.resize(static_cast<std::size_t>(n) * mm_size);
    work.plane_artificial_stress.resize(static_cast<std::size_t>(n) * r_size);
    double* packed_m = work.stress_correction.data();
    double* packed_r = work.plane_artificial_stress.data();
    const double eps_as = prm.artificial_stress;
    // Whether a particle's R is non-zero (tension): pairs of two compressed particles skip the term.
    // Read for every neighbour, so written for every particle (0 for fluid and walls).
    work.has_artificial_stress.resize(static_cast<std::size_t>(n));
    std::uint8_t* has_art = work.has_artificial_stress.data();
    parallel::for_each_dynamic(n, [&](Index i) {
        has_art[i] = 0;
        if (phase[i] != solid) return;
        const SymTensor3 art = eps_as > 0.0 ? artificial_stress(tau[i] - SymTensor3::identity() * p[i], rho[i],
                                                                 eps_as, Dim == 2)
                                            : SymTensor3::zero();
        has_art[i] = art.xx != 0.0 || art.yy != 0.0 || art.zz != 0.0 || art.xy != 0.0 || art.yz != 0.0 ||
                     art.zx != 0.0;
        double* r = packed_r + static_cast<std::size_t>(i) * r_size;
        r[0] = art.xx;
        r[1] = art.yy;
        r[2] = art.xy;
        if constexpr (Dim == 3) {
            r[3] = art.zz;
            r[4] = art.yz;
            r[5] = art.zx;
        }
    });
    // Each solid-solid pair once (neighbors::sum_pairs_once): the solid neighbours of higher index, and
    // the fluid and wall neighbours, one-sided. The kernel is evaluated once per pair, in the correction
    // pass, for the main pass too (it was 20 % of that pass).
    neighbors::HalfLists& lists = work.lists;
    lists.update(nl.offsets(), nl.indices(), n, nl.version(), phase, solid);
    const Index* upper = lists.upper();
    const Index* other = lists.other();
    const double inv_w_dx = 1.0 / kernel.value(prm.spacing);
    const double as_n = prm.artificial_stress_exponent;
    work.upper_gradient.resize(lists.upper_size());
    work.upper_stress_weight.resize(eps_as > 0.0 ? lists.upper_size() : 0);
    work.other_gradient.resize(lists.other_size());
    double* upper_f = work.upper_gradient.data();
    double* upper_w = work.upper_stress_weight.data();
    double* other_f = work.other_gradient.data();

    // Kernel gradient correction (Randles & Libersky 1996; second seed paper eq. 8), per solid particle:
    // L = [sum_b V_b grad_a W_ab (x) (x_b - x_a)]^-1 over solid neighbours. With it, eq. (31) is exact
    // for linear velocity fields and the stress divergence exact for linear stress fields, also at free
    // surfaces, where plain sums see half a kernel and halve tangential derivatives (a bending plate
    // then turns soft). The moment x_ab (x) x_ab f is the same seen from b: each pair adds it once,
    // times V_b to a and V_a to b.
    work.correction.resize(static_cast<std::size_t>(n));
    SymTensor3* corr = work.correction.data();
    auto moment_visit = [&](Index a, MomentSum<Dim>& sum_a, auto&& share) {
        const Vec xa = x[a];
        for (Index k = lists.upper_begin(a); k < lists.upper_end(a); ++k) {
            const Index b = upper[k];
            const Vec xab = image(xa - x[b]);
            const double r = std::sqrt(core::norm2(xab));
            const double f = kernel.gradient_factor(r);
            upper_f[k] = f;
            if (has_art[a] | has_art[b]) {  // the weight only matters where a pair has R != 0 (tension)
                const double ratio = kernel.value(r) * inv_w_dx;
                const double ratio2 = ratio * ratio;
                upper_w[k] = as_n == 4.0 ? ratio2 * ratio2 : std::pow(ratio, as_n);
            }
            MomentSum<Dim>& sum_b = share(b);
            int e = 0;
            for (int i = 0; i < Dim; ++i)
                for (int j = i; j < Dim; ++j, ++e) {
                    const double moment = f * xab[i] * xab[j];
                    sum_a.m[e] -= volume[b] * moment;
                    sum_b.m[e] -= volume[a] * moment;
                }
        }
        for (Index k = lists.other_begin(a); k < lists.other_end(a); ++k)
            other_f[k] = kernel.gradient_factor(std::sqrt(core::norm2(image(xa - x[other[k]]))));
    };
    auto moment_finish = [&](Index a, const MomentSum<Dim>& sum) {
        double mm[3][3] = {{0.0, 0.0, 0.0}, {0.0, 0.0, 0.0}, {0.0, 0.0, 0.0}};
        int e = 0;
        for (int i = 0; i < Dim; ++i)
            for (int j = i; j < Dim; ++j, ++e) mm[i][j] = mm[j][i] = sum.m[e];
        // M^-1 with M's eigenvalues bounded below: a fragment of a few particles keeps a bounded L.
        const SymTensor3 l = bounded_correction<Dim>(mm);
        corr[a] = l;
        // M = (sigma_a / rho_a^2) L_a, sigma = -p I + tau.
        const SymTensor3 st = (tau[a] - SymTensor3::identity() * p[a]) * (1.0 / (rho[a] * rho[a]));
        const double sm[3][3] = {{st.xx, st.xy, st.zx}, {st.xy, st.yy, st.yz}, {st.zx, st.yz, st.zz}};
        const double lm[3][3] = {{l.xx, l.xy, l.zx}, {l.xy, l.yy, l.yz}, {l.zx, l.yz, l.zz}};
        double* out = packed_m + static_cast<std::size_t>(a) * mm_size;
        for (int i = 0; i < Dim; ++i)
            for (int j = 0; j < Dim; ++j) {
                double sum_ij = 0.0;
                for (int k = 0; k < Dim; ++k) sum_ij += sm[i][k] * lm[k][j];
                out[i * Dim + j] = sum_ij;
            }
    };
    neighbors::sum_pairs_once(lists, work.moment_own, work.moment_spill, moment_visit, moment_finish);

    // M . g and (R_a + R_b) . g over the packed layouts.
    auto m_dot = [](const double* mm, const Vec& grad) {
        Vec out;
        for (int i = 0; i < Dim; ++i) {
            double sum = 0.0;
            for (int j = 0; j < Dim; ++j) sum += mm[i * Dim + j] * grad[j];
            out[i] = sum;
        }
        return out;
    };
    auto r_sum_dot = [](const double* ra, const double* rb, double weight, const Vec& grad) {
        Vec out;
        const double xx = (ra[0] + rb[0]) * weight, yy = (ra[1] + rb[1]) * weight, xy = (ra[2] + rb[2]) * weight;
        if constexpr (Dim == 2) {
            out[0] = xx * grad[0] + xy * grad[1];
            out[1] = xy * grad[0] + yy * grad[1];
        } else {
            const double zz = (ra[3] + rb[3]) * weight, yz = (ra[4] + rb[4]) * weight, zx = (ra[5] + rb[5]) * weight;
            out[0] = xx * grad[0] + xy * grad[1] + zx * grad[2];
            out[1] = xy * grad[0] + yy * grad[1] + yz * grad[2];
            out[2] = zx * grad[0] + yz * grad[1] + zz * grad[2];
        }
        return out;
    };

    const double h = kernel.h;
    const double eps_h2 = 0.01 * h * h;
    const Vec g = prm.gravity;
    const auto wall = static_cast<std::int32_t>(Phase::wall);

    auto visit = [&](Index a, SolidSum<Dim>& sum_a, auto&& share) {
        const Vec xa = x[a];
        const Vec va = v[a];
        const std::uint8_t has_art_a = has_art[a];
        const double rho_a = rho[a];
        const double p_term_a = p_term[a];
        const double m_a = m[a], volume_a = volume[a];
        const PairCoefficients& ca = coef[mat[a]];
        const SymTensor3 la = corr[a];
        const double* m_pack_a = packed_m + static_cast<std::size_t>(a) * mm_size;  // (sigma_a / rho_a^2) L_a
        const double* r_a = packed_r + static_cast<std::size_t>(a) * r_size;

        Vec dv = Vec::zero();
        double continuity = 0.0, work_rate = 0.0;
        SymTensor3 grad_v_sym = SymTensor3::zero();
        material::Spin w{};
        // Between solids, eq. (29) with the corrected kernel gradient of each particle:
        // sum_b m_b [sigma_a/rho_a^2 L_a + sigma_b/rho_b^2 L_b] grad W, plus the artificial viscosity and
        // stress: the same force per unit mass of the partner on both sides, with opposite signs.
        for (Index k = lists.upper_begin(a); k < lists.upper_end(a); ++k) {
            const double f = upper_f[k];
            if (f == 0.0) continue;
            const Index b = upper[k];
            const Vec xab = image(xa - x[b]);
            const double r2 = core::norm2(xab);
            const Vec vab = va - v[b];
            const double vx = core::dot(vab, xab);
            const double m_b = m[b];
            SolidSum<Dim>& sum_b = share(b);
            if (vx < 0.0) {  // artificial viscosity (eq. 29), zero for receding pairs
                const double pi_ab =
                    artificial_viscosity(h, vx, 1.0 / (r2 + eps_h2), 1.0 / (rho_a + rho[b]), ca, coef[mat[b]]);
                const Vec along = xab * (pi_ab * f);
                dv -= along * m_b;
                sum_b.dv += along * m_a;
                work_rate += 0.5 * m_b * pi_ab * vx * f;
                sum_b.work += 0.5 * m_a * pi_ab * vx * f;
            }
            const Vec grad = xab * f;
            const double* m_pack_b = packed_m + static_cast<std::size_t>(b) * mm_size;
            const Vec own_a = m_dot(m_pack_a, grad);  // sigma_a/rho_a^2 L_a grad W
            const Vec own_b = m_dot(m_pack_b, grad);  // minus b's own term (grad_b W_ba = -grad)
            Vec force = own_a + own_b;
            if (has_art_a | has_art[b]) {
                const Vec as_force = r_sum_dot(r_a, packed_r + static_cast<std::size_t>(b) * r_size, upper_w[k], grad);
                force += as_force;
                // Its work, shared by the pair like the artificial viscosity's, keeps energy booked.
                const double as_work = core::dot(as_force, vab);
                work_rate -= 0.5 * m_b * as_work;
                sum_b.work -= 0.5 * m_a * as_work;
            }
            dv += force * m_b;
            sum_b.dv -= force * m_a;
            // The matching internal-energy rates, -m_b sigma_a/rho_a^2 : (v_ab (x) L_a grad W) and b's
            // likewise: with the momentum above, kinetic + internal energy is conserved pair by pair.
            work_rate -= m_b * core::dot(vab, own_a);
            sum_b.work -= m_a * core::dot(vab, own_b);

            // Strain rate and spin, eq. (31), each with its own corrected gradient: a with v_ba = -v_ab
            // and L_a grad W, b with v_ab and L_b grad_b W_ba = -L_b grad W.
            const Vec u_a = vab * (-volume[b]);
            const Vec grad_a = dot(la, grad);
            add_symmetric_outer(grad_v_sym, u_a, grad_a);
            add_skew_outer(w, u_a, grad_a);
            const Vec u_b = vab * (-volume_a);
            const Vec grad_b = dot(corr[b], grad);
            add_symmetric_outer(sum_b.grad_v, u_b, grad_b);
            add_skew_outer(sum_b.spin, u_b, grad_b);
        }
        // Fluid and wall neighbours, one-sided: pressure, in the multi-phase form (p_a + p_b)/(rho_a rho_b)
        // of Colagrossi & Landrini (2003) across a fluid-solid interface, and artificial viscosity.
        for (Index k = lists.other_begin(a); k < lists.other_end(a); ++k) {
            const double f = other_f[k];
            if (f == 0.0) continue;
            const Index b = other[k];
            const Vec xab = image(xa - x[b]);
            const double r2 = core::norm2(xab);
            const Vec vab = va - v[b];
            const double vx = core::dot(vab, xab);
            if (vx < 0.0) {
                const double pi_ab =
                    artificial_viscosity(h, vx, 1.0 / (r2 + eps_h2), 1.0 / (rho_a + rho[b]), ca, coef[mat[b]]);
                dv += xab * (-m[b] * pi_ab * f);
                work_rate += 0.5 * m[b] * pi_ab * vx * f;
            }
            const bool is_wall = phase[b] == wall;
            // Against water repulsive only, as in the fluid's sums (docs/theory.md, "Water inside a solid").
            const double pressure = is_wall ? (p_term_a + p_term[b])
                                            : std::max(p_term_a * rho_a / rho[b] + p_term[b] * rho[b] / rho_a, 0.0);
            dv += xab * (-m[b] * pressure * f);
            work_rate += 0.5 * m[b] * pressure * vx * f;
            if (is_wall) continuity += volume[b] * vx * f;  // eq. (28) against walls
        }
        sum_a.dv += dv;
        sum_a.continuity += continuity;
        sum_a.grad_v += grad_v_sym;
        sum_a.spin.xy += w.xy;
        sum_a.spin.yz += w.yz;
        sum_a.spin.zx += w.zx;
        sum_a.work += work_rate;
    };
    auto finish = [&](Index a, const SolidSum<Dim>& total) {
        drho[a] = rho[a] * (total.continuity - total.grad_v.trace());
        acc[a] = total.dv + g;
        strain_rate[a] = total.grad_v;
        spin[a] = total.spin;
        // Internal energy: work of the stresses and artificial-viscosity heating.
        de[a] = total.work;
    };
    neighbors::sum_pairs_once(lists, work.own, work.spill, visit, finish);
}

}  // namespace

template <int Dim>
void compute_solid_rates(particles::SphParticles<Dim>& particles, const neighbors::NeighborList<Dim>& neighbors,
                         const Kernel<Dim>& kernel, const SolidRateParameters<Dim>& parameters,
                         const SphWorkspace& sph, SolidWorkspace<Dim>& workspace) {
    std::visit(
        [&](const auto& k) {
            neighbors::with_image(parameters.periodic_box, [&](const auto image) {
                solid_rates_loop(particles, neighbors, k, parameters, sph, workspace, image);
            });
        },
        kernel);
}

template void compute_solid_rates<2>(particles::SphParticles<2>&, const neighbors::NeighborList<2>&, const Kernel<2>&,
                                     const SolidRateParameters<2>&, const SphWorkspace&, SolidWorkspace<2>&);
template void compute_solid_rates<3>(particles::SphParticles<3>&, const neighbors::NeighborList<3>&, const Kernel<3>&,
                                     const SolidRateParameters<3>&, const SphWorkspace&, SolidWorkspace<3>&);

}  // namespace grit::sph
