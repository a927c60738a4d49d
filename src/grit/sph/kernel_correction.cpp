// Kernel-gradient correction matrices, a gather loop; the inverse by Eigen's
// fixed-size inverse.
#include "grit/sph/kernel_correction.hpp"

#include <Eigen/Dense>
#include <cmath>

#include "grit/parallel/parallel.hpp"

namespace grit::sph {

template <int Dim>
void compute_gradient_correction(const particles::SphParticles<Dim>& ps, const neighbors::NeighborList<Dim>& nl,
                                 const Kernel<Dim>& kernel, const neighbors::PeriodicBox<Dim>& box, Phase phase,
                                 unsigned neighbour_phases, std::vector<GradientCorrection<Dim>>& out) {
    using Vec = core::Vec<Dim>;
    const Index n = ps.size();
    out.resize(static_cast<std::size_t>(n));
    const Vec* x = ps.position();
    const double* rho = ps.density();
    const double* m = ps.mass();
    const std::int32_t* ph = ps.phase();
    const Index* nbr = nl.indices();
    const auto want = static_cast<std::int32_t>(phase);
    GradientCorrection<Dim>* L = out.data();
    std::visit(
        [&](const auto& k) {
            neighbors::with_image(box, [&](const auto image) {
                parallel::for_each(n, [&](Index a) {
                    if (ph[a] != want) {
                        L[a] = GradientCorrection<Dim>::identity();
                        return;
                    }
                    // M = sum_b V_b grad W_ab (x) (x_b - x_a) = -sum_b V_b f_ab x_ab
                    // x_ab^T
                    Eigen::Matrix<double, Dim, Dim> M = Eigen::Matrix<double, Dim, Dim>::Zero();
                    for (Index e = nl.begin(a); e < nl.end(a); ++e) {
                        const Index b = nbr[e];
                        if (!(neighbour_phases & (1u << static_cast<unsigned>(ph[b])))) continue;
                        const Vec xab = image(x[a] - x[b]);
                        const double f = k.gradient_factor(std::sqrt(core::norm2(xab)));
                        const double w = -m[b] / rho[b] * f;
                        for (int i = 0; i < Dim; ++i)
                            for (int j = 0; j < Dim; ++j)
                                M(i, j) += w * xab[i] * xab[j];
                    }
                    if (!(M.determinant() > min_correction_determinant)) {
                        L[a] = GradientCorrection<Dim>::identity();
                        return;
                    }
                    const Eigen::Matrix<double, Dim, Dim> inv = M.inverse();
                    for (int i = 0; i < Dim; ++i)
                        for (int j = 0; j < Dim; ++j)
                            L[a].m[i][j] = inv(i, j);
                });
            });
        },
        kernel);
}

template void compute_gradient_correction<2>(const particles::SphParticles<2>&, const neighbors::NeighborList<2>&,
                                             const Kernel<2>&, const neighbors::PeriodicBox<2>&, Phase, unsigned,
                                             std::vector<GradientCorrection<2>>&);
template void compute_gradient_correction<3>(const particles::SphParticles<3>&, const neighbors::NeighborList<3>&,
                                             const Kernel<3>&, const neighbors::PeriodicBox<3>&, Phase, unsigned,
                                             std::vector<GradientCorrection<3>>&);

}  // namespace grit::sph
