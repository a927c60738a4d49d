// The solid SPH sums, one gather loop over solid particles, dispatched once on the kernel type.
#include "grit/sph/solid_rates.hpp"

#include <algorithm>
#include <cmath>

#include "grit/parallel/parallel.hpp"
#include <Eigen/Dense>

#include "grit/sph/artificial_stress.hpp"
#include "grit/sph/artificial_viscosity.hpp"
#include "grit/sph/tensor_ops.hpp"

namespace grit::sph {

namespace {

template <int Dim, class K>
void solid_rates_loop(particles::SphParticles<Dim>& ps, const neighbors::NeighborList<Dim>& nl, const K& kernel,
                      const SolidRateParameters<Dim>& prm, const SphWorkspace& sph, SolidWorkspace& work) {
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
    parallel::for_each(n, [&](Index i) {
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
    // Kernel gradient correction (Randles & Libersky 1996; second seed paper eq. 8), per solid particle:
    // L = [sum_b V_b grad_a W_ab (x) (x_b - x_a)]^-1 over solid neighbours. With it, eq. (31) is exact
    // for linear velocity fields and the stress divergence exact for linear stress fields, also at free
    // surfaces, where plain sums see half a kernel and halve tangential derivatives (a bending plate
    // then turns soft).
    work.correction.resize(static_cast<std::size_t>(n));
    SymTensor3* corr = work.correction.data();
    // The kernel is evaluated once per pair here, for the main pass too (it was 20 % of that pass).
    const double inv_w_dx = 1.0 / kernel.value(prm.spacing);
    const double as_n = prm.artificial_stress_exponent;
    const auto entries = static_cast<std::size_t>(nl.begin(n));
    work.pair_gradient.resize(entries);
    work.pair_stress_weight.resize(eps_as > 0.0 ? entries : 0);
    double* pair_f = work.pair_gradient.data();
    double* pair_w = work.pair_stress_weight.data();
    parallel::for_each_dynamic(n, [&](Index a) {
        if (phase[a] != solid) return;
        double mm[3][3] = {{0.0, 0.0, 0.0}, {0.0, 0.0, 0.0}, {0.0, 0.0, 0.0}};
        for (Index k = nl.begin(a); k < nl.end(a); ++k) {
            const Index b = nbr[k];
            const Vec xab = x[a] - x[b];
            const double r = std::sqrt(core::norm2(xab));
            const double f = kernel.gradient_factor(r);
            pair_f[k] = f;
            if (has_art[a] | has_art[b]) {  // the weight only matters where a pair has R != 0 (tension)
                const double ratio = kernel.value(r) * inv_w_dx;
                const double ratio2 = ratio * ratio;
                pair_w[k] = as_n == 4.0 ? ratio2 * ratio2 : std::pow(ratio, as_n);
            }
            if (phase[b] != solid) continue;
            for (int i = 0; i < Dim; ++i)
                for (int j = 0; j < Dim; ++j) mm[i][j] -= volume[b] * f * xab[i] * xab[j];
        }
        SymTensor3 l = SymTensor3::identity();  // where the moment matrix is singular (an isolated particle)
        if constexpr (Dim == 2) {
            const double det = mm[0][0] * mm[1][1] - mm[0][1] * mm[1][0];
            if (std::abs(det) > 1e-6) l = {mm[1][1] / det, mm[0][0] / det, 1.0, -mm[0][1] / det, 0.0, 0.0};
        } else {
            Eigen::Matrix3d m3;
            m3 << mm[0][0], mm[0][1], mm[0][2], mm[1][0], mm[1][1], mm[1][2], mm[2][0], mm[2][1], mm[2][2];
            if (std::abs(m3.determinant()) > 1e-6) {
                const Eigen::Matrix3d inv = m3.inverse();
                l = {inv(0, 0), inv(1, 1), inv(2, 2), inv(0, 1), inv(1, 2), inv(2, 0)};
            }
        }
        corr[a] = l;
        // M = (sigma_a / rho_a^2) L_a, sigma = -p I + tau.
        const SymTensor3 st = (tau[a] - SymTensor3::identity() * p[a]) * (1.0 / (rho[a] * rho[a]));
        const double sm[3][3] = {{st.xx, st.xy, st.zx}, {st.xy, st.yy, st.yz}, {st.zx, st.yz, st.zz}};
        const double lm[3][3] = {{l.xx, l.xy, l.zx}, {l.xy, l.yy, l.yz}, {l.zx, l.yz, l.zz}};
        double* out = packed_m + static_cast<std::size_t>(a) * mm_size;
        for (int i = 0; i < Dim; ++i)
            for (int j = 0; j < Dim; ++j) {
                double sum = 0.0;
                for (int k = 0; k < Dim; ++k) sum += sm[i][k] * lm[k][j];
                out[i * Dim + j] = sum;
            }
    });
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

    parallel::for_each_dynamic(n, [&](Index a) {
        if (phase[a] != solid) return;
        const Vec xa = x[a];
        const Vec va = v[a];
        const std::uint8_t has_art_a = has_art[a];
        const double rho_a = rho[a];
        const double p_term_a = p_term[a];
        const PairCoefficients& ca = coef[mat[a]];
        const SymTensor3 la = corr[a];
        const double* m_a = packed_m + static_cast<std::size_t>(a) * mm_size;  // (sigma_a / rho_a^2) L_a
        const double* r_a = packed_r + static_cast<std::size_t>(a) * r_size;

        Vec dv = Vec::zero();
        double continuity = 0.0, work_rate = 0.0;
        SymTensor3 grad_v_sym = SymTensor3::zero();
        material::Spin w{};
        for (Index k = nl.begin(a); k < nl.end(a); ++k) {
            const Index b = nbr[k];
            const double f = pair_f[k];
            if (f == 0.0) continue;
            const Vec xab = xa - x[b];
            const double r2 = core::norm2(xab);
            const Vec vab = va - v[b];
            const double vx = core::dot(vab, xab);
            const double volume_b = volume[b];
            const PairCoefficients& cb = coef[mat[b]];

            // Artificial viscosity with every neighbour (eq. 29), along the plain kernel gradient; zero for
            // receding pairs, which skip its two divisions.
            if (vx < 0.0) {
                const double pi_ab = artificial_viscosity(h, vx, 1.0 / (r2 + eps_h2), 1.0 / (rho_a + rho[b]), ca, cb);
                dv += xab * (-m[b] * pi_ab * f);
                work_rate += 0.5 * m[b] * pi_ab * vx * f;
            }

            if (phase[b] != solid) {
                // Pressure from fluid and wall neighbours; the multi-phase form (p_a + p_b)/(rho_a rho_b)
                // of Colagrossi & Landrini (2003) across a fluid-solid interface.
                const bool is_wall = phase[b] == wall;
                const double pressure = is_wall ? (p_term_a + p_term[b])
                                                : (p_term_a * rho_a / rho[b] + p_term[b] * rho[b] / rho_a);
                dv += xab * (-m[b] * pressure * f);
                work_rate += 0.5 * m[b] * pressure * vx * f;
                if (is_wall) continuity += volume_b * vx * f;  // eq. (28) against walls
                continue;
            }
            // Between solids, eq. (29) with the corrected kernel gradient of each particle:
            // sum_b m_b [sigma_a/rho_a^2 L_a + sigma_b/rho_b^2 L_b] grad W (antisymmetric per pair, so
            // momentum is conserved), plus the artificial stress (zero where both R are: compression).
            const Vec grad = xab * f;
            const Vec ca_grad = dot(la, grad);  // L_a grad W
            const Vec own = m_dot(m_a, grad);   // sigma_a/rho_a^2 L_a grad W
            Vec force = own + m_dot(packed_m + static_cast<std::size_t>(b) * mm_size, grad);
            if (has_art_a | has_art[b]) {
                const Vec as_force = r_sum_dot(r_a, packed_r + static_cast<std::size_t>(b) * r_size, pair_w[k], grad);
                force += as_force;
                // Its work, shared by the pair like the artificial viscosity's, keeps energy booked.
                work_rate -= 0.5 * m[b] * core::dot(as_force, vab);
            }
            dv += force * m[b];
            // The matching internal-energy rate, -m_b sigma_a/rho_a^2 : (v_ab (x) L_a grad W): with the
            // momentum above, kinetic + internal energy is conserved pair by pair.
            work_rate -= m[b] * core::dot(vab, own);

            // Strain rate and spin, eq. (31), with v_ba = -v_ab and the corrected gradient L_a grad W.
            const Vec u = vab * (-volume_b);
            add_symmetric_outer(grad_v_sym, u, ca_grad);
            add_skew_outer(w, u, ca_grad);
        }
        drho[a] = rho_a * (continuity - grad_v_sym.trace());
        acc[a] = dv + g;
        strain_rate[a] = grad_v_sym;
        spin[a] = w;
        // Internal energy: work of the stresses and artificial-viscosity heating.
        de[a] = work_rate;
    });
}

}  // namespace

template <int Dim>
void compute_solid_rates(particles::SphParticles<Dim>& particles, const neighbors::NeighborList<Dim>& neighbors,
                         const Kernel<Dim>& kernel, const SolidRateParameters<Dim>& parameters,
                         const SphWorkspace& sph, SolidWorkspace& workspace) {
    std::visit([&](const auto& k) { solid_rates_loop(particles, neighbors, k, parameters, sph, workspace); }, kernel);
}

template void compute_solid_rates<2>(particles::SphParticles<2>&, const neighbors::NeighborList<2>&, const Kernel<2>&,
                                     const SolidRateParameters<2>&, const SphWorkspace&, SolidWorkspace&);
template void compute_solid_rates<3>(particles::SphParticles<3>&, const neighbors::NeighborList<3>&, const Kernel<3>&,
                                     const SolidRateParameters<3>&, const SphWorkspace&, SolidWorkspace&);

}  // namespace grit::sph
