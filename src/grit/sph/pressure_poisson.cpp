// The ISPH pressure projection: free-surface detection, the divergence and
// gradient sums, and the sparse system (assembled row by row in a gather loop,
// solved by Eigen's BiCGSTAB).
// GCC 12 with -march=native (AVX-512) warns that a register in Eigen's vectorised sum inside
// BiCGSTAB "may be used uninitialized" (avx512fintrin.h); a false positive in the library's code.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif
#include "grit/sph/pressure_poisson.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "grit/parallel/parallel.hpp"

namespace grit::sph {

namespace {


/// The neighbours that take part in the projection: fluid and wall particles.
inline bool in_projection(std::int32_t phase) {
    return phase == fluid_phase || phase == wall_phase;
}

/// Runs f(kernel, image) with the concrete kernel type and periodic image.
template <int Dim, class F>
void dispatch(const Kernel<Dim>& kernel, const neighbors::PeriodicBox<Dim>& box, F&& f) {
    std::visit([&](const auto& k) { neighbors::with_image(box, [&](const auto image) { f(k, image); }); }, kernel);
}

}  // namespace

template <int Dim>
void position_divergence(const particles::SphParticles<Dim>& ps, const neighbors::NeighborList<Dim>& nl,
                         const Kernel<Dim>& kernel, const neighbors::PeriodicBox<Dim>& box,
                         std::vector<double>& divergence, std::vector<double>& summation_density) {
    using Vec = core::Vec<Dim>;
    const Index n = ps.size();
    divergence.assign(static_cast<std::size_t>(n), 0.0);
    summation_density.assign(static_cast<std::size_t>(n), 0.0);
    const Vec* x = ps.position();
    const double* rho = ps.density();
    const double* m = ps.mass();
    const std::int32_t* ph = ps.phase();
    const Index* nbr = nl.indices();
    dispatch(kernel, box, [&](const auto& k, const auto image) {
        parallel::for_each(n, [&](Index a) {
            if (ph[a] != fluid_phase) return;
            double div = 0.0, mass_sum = m[a] * k.value(0.0);
            for (Index e = nl.begin(a); e < nl.end(a); ++e) {
                const Index b = nbr[e];
                if (!in_projection(ph[b])) continue;
                const Vec xab = image(x[a] - x[b]);
                const double r = std::sqrt(core::norm2(xab));
                const double vf = m[b] / rho[b] * k.gradient_factor(r);
                div -= vf * r * r;
                mass_sum += m[b] * k.value(r);
            }
            divergence[static_cast<std::size_t>(a)] = div;
            summation_density[static_cast<std::size_t>(a)] = mass_sum;
        });
    });
}

template <int Dim>
void velocity_divergence(const particles::SphParticles<Dim>& ps, const neighbors::NeighborList<Dim>& nl,
                         const Kernel<Dim>& kernel, const neighbors::PeriodicBox<Dim>& box, const core::Vec<Dim>* v,
                         const GradientCorrection<Dim>* correction, std::vector<double>& out) {
    using Vec = core::Vec<Dim>;
    const Index n = ps.size();
    out.assign(static_cast<std::size_t>(n), 0.0);
    const Vec* x = ps.position();
    const double* rho = ps.density();
    const double* m = ps.mass();
    const std::int32_t* ph = ps.phase();
    const Index* nbr = nl.indices();
    dispatch(kernel, box, [&](const auto& k, const auto image) {
        parallel::for_each_dynamic(n, [&](Index a) {
            if (ph[a] != fluid_phase) return;
            double sum = 0.0;
            for (Index e = nl.begin(a); e < nl.end(a); ++e) {
                const Index b = nbr[e];
                if (!in_projection(ph[b])) continue;
                const Vec xab = image(x[a] - x[b]);
                const Vec grad =
                    (correction ? correction[a].apply(xab) : xab) * k.gradient_factor(std::sqrt(core::norm2(xab)));
                sum += m[b] * core::dot(v[a] - v[b], grad);
            }
            out[static_cast<std::size_t>(a)] = -sum / rho[a];
        });
    });
}

template <int Dim>
void pressure_acceleration(const particles::SphParticles<Dim>& ps, const neighbors::NeighborList<Dim>& nl,
                           const Kernel<Dim>& kernel, const neighbors::PeriodicBox<Dim>& box,
                           const GradientCorrection<Dim>* correction, std::vector<core::Vec<Dim>>& out) {
    using Vec = core::Vec<Dim>;
    const Index n = ps.size();
    out.assign(static_cast<std::size_t>(n), Vec::zero());
    const Vec* x = ps.position();
    const double* rho = ps.density();
    const double* p = ps.pressure();
    const double* m = ps.mass();
    const std::int32_t* ph = ps.phase();
    const Index* nbr = nl.indices();
    dispatch(kernel, box, [&](const auto& k, const auto image) {
        parallel::for_each_dynamic(n, [&](Index a) {
            if (ph[a] != fluid_phase) return;
            Vec sum = Vec::zero();
            for (Index e = nl.begin(a); e < nl.end(a); ++e) {
                const Index b = nbr[e];
                if (!in_projection(ph[b])) continue;
                const Vec xab = image(x[a] - x[b]);
                const double f = m[b] / rho[b] * (p[b] - p[a]) * k.gradient_factor(std::sqrt(core::norm2(xab)));
                sum += (correction ? correction[a].apply(xab) : xab) * f;
            }
            sum *= 1.0 / rho[a];
            out[static_cast<std::size_t>(a)] = -sum;
        });
    });
}

template <int Dim>
ProjectionResult PressureProjection<Dim>::solve(particles::SphParticles<Dim>& ps,
                                                const neighbors::NeighborList<Dim>& nl, const Kernel<Dim>& kernel,
                                                const ProjectionSettings<Dim>& s, const core::Vec<Dim>* v_star,
                                                const GradientCorrection<Dim>* correction, double dt,
                                                double relaxation_time, std::int32_t* free_surface,
                                                const double* porosity, const domain::Halo<Dim>* ghosts) {
    using Vec = core::Vec<Dim>;
    const Index n = ps.size();
    const auto un = static_cast<std::size_t>(n);
    position_divergence(ps, nl, kernel, s.periodic_box, divergence_r_, summation_density_);
    velocity_divergence(ps, nl, kernel, s.periodic_box, v_star, correction, divergence_v_);
    velocity_divergence(ps, nl, kernel, s.periodic_box, ps.velocity(), correction, divergence_v0_);

    const Vec* x = ps.position();
    const double* rho = ps.density();
    double* p = ps.pressure();
    const double* m = ps.mass();
    const std::int32_t* ph = ps.phase();
    const std::int32_t* mat = ps.material();
    const Index* nbr = nl.indices();
    const double eps_h2 = 0.01 * std::visit([](const auto& k) { return k.h * k.h; }, kernel);
    const auto on_surface = [&](Index a) {
        return divergence_r_[static_cast<std::size_t>(a)] < s.free_surface_divergence;
    };
    // The unknown each particle's pressure is: its own, or for a ghost its owner's (a mirror image's
    // pressure is its source's). A ghost's own row would read a kernel that the ghosts end in.
    owner_.resize(un);
    for (Index a = 0; a < n; ++a) owner_[static_cast<std::size_t>(a)] = a;
    if (ghosts)
        for (std::size_t k = 0; k < ghosts->size(); ++k)
            owner_[static_cast<std::size_t>(ghosts->ghosts()[k])] = ghosts->owners()[k];
    const auto is_ghost = [&](Index a) { return owner_[static_cast<std::size_t>(a)] != a; };
    const auto unknown = [&](Index j) { return static_cast<int>(owner_[static_cast<std::size_t>(j)]); };

    // Rows in padded storage: row a has room for its diagonal and every listed
    // neighbour.
    row_count_.assign(un, 0);
    const std::size_t padded = nl.pair_count() + un;
    padded_columns_.resize(padded);
    padded_values_.resize(padded);
    rhs_.resize(n);
    guess_.resize(n);
    const double inv_dt = 1.0 / dt;
    const double relaxation = s.density_relaxation / (relaxation_time * relaxation_time);
    // Only the free surface's p = 0 fixes the pressure's level: the fluid rows are a Laplacian and the
    // wall rows an average. Fluid without a free surface (a closed or periodic box) leaves the system
    // singular, and BiCGSTAB ran off to a residual of 1e33 in the periodic packed bed; then the first
    // fluid particle keeps its pressure, and the others follow from it.
    Index pinned = -1;
    {
        bool surface = false;
        for (Index a = 0; a < n && !surface; ++a) {
            if (ph[a] != fluid_phase || is_ghost(a)) continue;
            if (pinned < 0) pinned = a;
            surface = on_surface(a);
        }
        if (surface) pinned = -1;
    }

    // The surface row's terms d n . grad p_a = d sum_b V_b (p_b - p_a) n . L_a grad W_ab, n the
    // outward normal -sum_b V_b grad W_ab / |...|. Kept at p = 0 (nothing added) for a particle with
    // no normal, one whose gradient is not corrected (a surge's tip), or whose corrected gradient
    // turns the normal inwards (n . L_a sum_b V_b grad W_ab >= 0: a splash's stray L_a), where the
    // extrapolation would not be one.
    // f(j, x_aj, r^2) for each fluid or wall neighbour j of a within the kernel's support.
    const auto for_each_in_support = [&](Index a, const auto image, double support2, auto&& f) {
        for (Index e = nl.begin(a); e < nl.end(a); ++e) {
            const Index j = nbr[e];
            if (!in_projection(ph[j])) continue;
            const Vec xab = image(x[a] - x[j]);
            const double r2 = core::norm2(xab);
            if (r2 < support2) f(j, xab, r2);
        }
    };
    const auto add_surface_row = [&](Index a, const auto& k, const auto image, double support2, int* col, double* val,
                                     Index& count, double& diagonal) {
        if (!(s.surface_offset > 0.0)) return;
        if (correction && correction[a].determinant() > s.max_surface_correction) return;
        Vec colour = Vec::zero();
        for_each_in_support(a, image, support2, [&](Index j, const Vec& xab, double r2) {
            colour += xab * (m[j] / rho[j] * k.gradient_factor(std::sqrt(r2)));
        });
        const double length = std::sqrt(core::norm2(colour));
        if (!(length > 0.0)) return;
        const Vec normal = colour * (-1.0 / length);
        const Vec corrected_colour = correction ? correction[a].apply(colour) : colour;
        if (core::dot(normal, corrected_colour) >= 0.0) return;
        for_each_in_support(a, image, support2, [&](Index j, const Vec& xab, double r2) {
            const Vec grad = (correction ? correction[a].apply(xab) : xab) * k.gradient_factor(std::sqrt(r2));
            const double c = s.surface_offset * m[j] / rho[j] * core::dot(normal, grad);
            diagonal -= c;
            col[count] = unknown(j);
            val[count] = c;
            ++count;
        });
    };

    dispatch(kernel, s.periodic_box, [&](const auto& k, const auto image) {
        const double support2 = k.support() * k.support();
        parallel::for_each_dynamic(n, [&](Index a) {
            const std::size_t start = static_cast<std::size_t>(nl.begin(a)) + static_cast<std::size_t>(a);
            int* col = padded_columns_.data() + start;
            double* val = padded_values_.data() + start;
            Index count = 1;  // the diagonal first
            double diagonal = 0.0, b = 0.0;
            guess_[a] = p[a];
            if (free_surface) free_surface[a] = 0;
            if (is_ghost(a)) {
                diagonal = 1.0;  // keeps its pressure until its owner's is forwarded to it
                b = p[a];
            } else if (ph[a] == fluid_phase) {
                for (Index e = nl.begin(a); e < nl.end(a); ++e) {
                    const Index j = nbr[e];
                    if (!in_projection(ph[j])) continue;
                    const Vec xab = image(x[a] - x[j]);
                    const double r2 = core::norm2(xab);
                    if (r2 >= support2) continue;
                    const double rho_sum = rho[a] + rho[j];
                    // -(m_b 8/(rho_a+rho_b)^2 x_ab . grad W_ab / (r^2 + eta^2)) >= 0
                    const double coef =
                        -m[j] * 8.0 / (rho_sum * rho_sum) * r2 * k.gradient_factor(std::sqrt(r2)) / (r2 + eps_h2);
                    diagonal += coef;
                    col[count] = unknown(j);
                    val[count] = -coef;
                    ++count;
                }
                if (a == pinned) {
                    count = 1;
                    diagonal = 1.0;
                    b = p[a];
                } else if (on_surface(a)) {
                    // Free surface: p = 0 where the particle's volume ends, d = surface_offset out
                    // along its normal n: p_a + d n . grad p_a = 0, grad p_a the gradient the
                    // correction applies (L_a, the difference form). p = 0 on the particle itself
                    // (Cummins & Rudman 1999; Lind et al. 2012) put the surface half a spacing low:
                    // the tank's shallowest probe read 5.6 % low. The hydrostatic value half a
                    // spacing deep tried before used gravity, which a moving surface does not feel.
                    if (free_surface) free_surface[a] = 1;
                    count = 1;
                    diagonal = 1.0;
                    b = 0.0;
                    add_surface_row(a, k, image, support2, col, val, count, diagonal);
                } else {
                    // -(div v^n/tau + (div v* - div v^n)/dt + gamma (rho0 - rho_s)/(rho_s tau^2)),
                    // tau the relaxation time (>= dt), rho_s = sum_b m_b W_ab, on every particle
                    // off the free surface. The rows just under the surface miss part of their
                    // kernel, but without the invariance nothing holds their spacing: it was left
                    // to drift, the top rows thinned by 5-12 % and the surface of the tank at rest
                    // carried waves of 1-3 cm/s (docs/validation.md).
                    // With grains the particles carry the fluid mass of their mixture volume, so
                    // the sum aims at eps_a rho0 (eq. 21).
                    const auto ia = static_cast<std::size_t>(a);
                    const double rho0 = s.reference_density[static_cast<std::size_t>(mat[a])] *
                                        (porosity ? porosity[a] : 1.0);
                    const double rho_s = summation_density_[ia];
                    const double invariance = (rho0 - rho_s) / rho_s;
                    const double carried = divergence_v0_[ia];
                    b = -(carried / relaxation_time + (divergence_v_[ia] - carried) * inv_dt + relaxation * invariance);
                }
            } else if (ph[a] == wall_phase) {
                // p_w = sum_f W_wf (p_f + rho_f g . x_wf) / sum_f W_wf (Adami et al. 2012;
                // the walls are fixed), an unknown of the same system. Not (v*_f - v_w)/dt in
                // place of g: that sucked fluid leaving a wall back onto it (a layer climbed the
                // dam break's left wall) and drove the pressure to 60 kPa.
                for (Index e = nl.begin(a); e < nl.end(a); ++e) {
                    const Index j = nbr[e];
                    if (ph[j] != fluid_phase) continue;
                    const Vec xwf = image(x[a] - x[j]);
                    const double r2 = core::norm2(xwf);
                    if (r2 >= support2) continue;
                    const double w = k.value(std::sqrt(r2));
                    diagonal += w;
                    const double rho_fluid = porosity ? rho[j] / porosity[j] : rho[j];
                    b += rho_fluid * core::dot(s.gravity, xwf) * w;
                    col[count] = unknown(j);
                    val[count] = -w;
                    ++count;
                }
                if (!(diagonal > 0.0)) {  // no fluid near: p_w = 0
                    diagonal = 1.0;
                    b = 0.0;
                }
            } else {
                diagonal = 1.0;  // not in the projection: keeps its pressure
                b = p[a];
            }
            // Every row divided by its diagonal: the residual is then in pascals in every row. The
            // wall rows (weights W ~ 1/h^2) otherwise outweighed the fluid rows (m/rho^2 |grad W|/r
            // ~ 1e-3 of them) in |b - A p|, and the fluid's smooth pressure mode drifted by a
            // kilopascal inside the tolerance.
            const double inv_diagonal = 1.0 / diagonal;
            for (Index c = 1; c < count; ++c)
                val[c] *= inv_diagonal;
            b *= inv_diagonal;
            diagonal = 1.0;
            col[0] = static_cast<int>(a);
            val[0] = diagonal;
            rhs_[a] = b;
            // Sorted columns, as Eigen's compressed storage expects (insertion sort:
            // a row is short).
            for (Index c = 1; c < count; ++c) {
                const int key = col[c];
                const double value = val[c];
                Index d = c;
                for (; d > 0 && col[d - 1] > key; --d) {
                    col[d] = col[d - 1];
                    val[d] = val[d - 1];
                }
                col[d] = key;
                val[d] = value;
            }
            // A particle near a mirror plane reads its own image, and two particles each other's: one
            // entry per unknown.
            Index merged = 1;
            for (Index c = 1; c < count; ++c) {
                if (col[c] == col[merged - 1]) {
                    val[merged - 1] += val[c];
                } else {
                    col[merged] = col[c];
                    val[merged] = val[c];
                    ++merged;
                }
            }
            count = merged;
            row_count_[static_cast<std::size_t>(a)] = count;
        });
    });

    // Compress the padded rows into the matrix.
    row_start_.resize(un + 1);
    row_start_[0] = 0;
    for (std::size_t a = 0; a < un; ++a)
        row_start_[a + 1] = row_start_[a] + row_count_[a];
    const Index nnz = row_start_[un];
    matrix_.resize(n, n);
    matrix_.resizeNonZeros(nnz);
    int* outer = matrix_.outerIndexPtr();
    int* inner = matrix_.innerIndexPtr();
    double* values = matrix_.valuePtr();
    for (std::size_t a = 0; a <= un; ++a)
        outer[a] = static_cast<int>(row_start_[a]);
    parallel::for_each(n, [&](Index a) {
        const std::size_t from = static_cast<std::size_t>(nl.begin(a)) + static_cast<std::size_t>(a);
        const auto to = static_cast<std::size_t>(row_start_[static_cast<std::size_t>(a)]);
        std::copy_n(padded_columns_.data() + from, row_count_[static_cast<std::size_t>(a)], inner + to);
        std::copy_n(padded_values_.data() + from, row_count_[static_cast<std::size_t>(a)], values + to);
    });

    // Jacobi-preconditioned: an incomplete LU (fill 1) cut the iterations of the
    // 2D dam break from ~450 to ~35 a solve but took longer (its serial
    // factorisation each step): docs/performance.md.
    Eigen::BiCGSTAB<Eigen::SparseMatrix<double, Eigen::RowMajor, int>, Eigen::DiagonalPreconditioner<double>> solver;
    solver.setTolerance(s.tolerance);
    solver.setMaxIterations(s.max_iterations);
    solver.compute(matrix_);
    solution_ = solver.solveWithGuess(rhs_, guess_);
    ProjectionResult result;
    result.iterations = static_cast<int>(solver.iterations());
    result.residual = solver.error();
    result.converged = solver.info() == Eigen::Success && solution_.allFinite();
    if (!solution_.allFinite()) {
        for (Index a = 0; a < n && result.bad_row < 0; ++a) {
            bool finite = std::isfinite(rhs_[a]);
            for (int c = outer[a]; c < outer[a + 1]; ++c) finite = finite && std::isfinite(values[c]);
            if (!finite) result.bad_row = a;
        }
        if (result.bad_row < 0) {
            // BiCGSTAB broke down (r0 . v = 0: its shadow residual r0 = b - A p_guess became
            // orthogonal to the search space). A start from p = 0 takes another shadow residual.
            result.restarted = true;
            solution_ = solver.solve(rhs_);
            result.iterations += static_cast<int>(solver.iterations());
            result.residual = solver.error();
            result.converged = solver.info() == Eigen::Success && solution_.allFinite();
        }
    }
    for (Index a = 0; a < n; ++a)
        if (ph[a] == fluid_phase && on_surface(a) && !is_ghost(a))
            ++result.surface_particles;
    if (result.converged) {
        parallel::for_each(n, [&](Index a) {
            if (in_projection(ph[a])) p[a] = solution_[a];
        });
        if (ghosts) {
            ghosts->forward(p);
            if (free_surface) ghosts->forward(free_surface);
        }
    }
    return result;
}

template void position_divergence<2>(const particles::SphParticles<2>&, const neighbors::NeighborList<2>&,
                                     const Kernel<2>&, const neighbors::PeriodicBox<2>&, std::vector<double>&,
                                     std::vector<double>&);
template void position_divergence<3>(const particles::SphParticles<3>&, const neighbors::NeighborList<3>&,
                                     const Kernel<3>&, const neighbors::PeriodicBox<3>&, std::vector<double>&,
                                     std::vector<double>&);
template void velocity_divergence<2>(const particles::SphParticles<2>&, const neighbors::NeighborList<2>&,
                                     const Kernel<2>&, const neighbors::PeriodicBox<2>&, const core::Vec<2>*,
                                     const GradientCorrection<2>*, std::vector<double>&);
template void velocity_divergence<3>(const particles::SphParticles<3>&, const neighbors::NeighborList<3>&,
                                     const Kernel<3>&, const neighbors::PeriodicBox<3>&, const core::Vec<3>*,
                                     const GradientCorrection<3>*, std::vector<double>&);
template void pressure_acceleration<2>(const particles::SphParticles<2>&, const neighbors::NeighborList<2>&,
                                       const Kernel<2>&, const neighbors::PeriodicBox<2>&, const GradientCorrection<2>*,
                                       std::vector<core::Vec<2>>&);
template void pressure_acceleration<3>(const particles::SphParticles<3>&, const neighbors::NeighborList<3>&,
                                       const Kernel<3>&, const neighbors::PeriodicBox<3>&, const GradientCorrection<3>*,
                                       std::vector<core::Vec<3>>&);
template class PressureProjection<2>;
template class PressureProjection<3>;

}  // namespace grit::sph
