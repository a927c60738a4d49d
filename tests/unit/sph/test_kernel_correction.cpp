// Kernel-gradient correction (second seed paper eq. 8) and the Shepard density
// filter on disordered particle sets: the corrected gradient of a linear field
// is exact (the plain SPH gradient is not), and the Shepard filter keeps a
// uniform density and smooths a noisy one.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "grit/neighbors/particle_neighbors.hpp"
#include "grit/sph/kernel_correction.hpp"
#include "grit/sph/shepard_filter.hpp"

using grit::Index;

namespace {

/// A lattice of spacing dx filling [0, 1)^Dim, each particle shifted at random
/// by up to `jitter` dx per axis; density 1000 (times 1 + noise), mass rho0
/// dx^Dim. Sorted, with lists at radius 2h + skin.
template <int Dim>
struct Cloud {
    static constexpr double dx = 0.1, h = 1.3 * dx;
    grit::particles::SphParticles<Dim> ps;
    grit::neighbors::ParticleNeighbors<Dim> nb;
    grit::sph::Kernel<Dim> kernel = grit::sph::WendlandC2<Dim>(h);

    Cloud(double jitter, double density_noise, unsigned seed) {
        std::mt19937 rng(seed);
        std::uniform_real_distribution<double> u(-1.0, 1.0);
        const int per_axis = 10;
        const Index n = Dim == 2 ? per_axis * per_axis : per_axis * per_axis * per_axis;
        ps.append(n);
        for (Index i = 0; i < n; ++i) {
            Index rest = i;
            for (int k = 0; k < Dim; ++k) {
                ps.position()[i][k] = (static_cast<double>(rest % per_axis) + 0.5 + jitter * u(rng)) * dx;
                rest /= per_axis;
            }
            ps.density()[i] = 1000.0 * (1.0 + density_noise * u(rng));
            ps.mass()[i] = 1000.0 * std::pow(dx, Dim);
            ps.phase()[i] = 0;
        }
        nb.update(ps, 2.0 * h + 0.1 * dx, 0.1 * dx, true);
    }

    /// sum_b V_b (phi_b - phi_a) G_ab for phi = c . x, with G_ab = L_a grad W_ab
    /// or grad W_ab.
    grit::core::Vec<Dim> gradient(Index a, const grit::core::Vec<Dim>& c,
                                  const std::vector<grit::sph::GradientCorrection<Dim>>* L) const {
        const auto& nl = nb.list();
        const auto* x = ps.position();
        auto out = grit::core::Vec<Dim>::zero();
        for (Index e = nl.begin(a); e < nl.end(a); ++e) {
            const Index b = nl.indices()[e];
            const auto xab = x[a] - x[b];
            const double f =
                std::get<grit::sph::WendlandC2<Dim>>(kernel).gradient_factor(std::sqrt(grit::core::norm2(xab)));
            const auto grad = (L ? (*L)[static_cast<std::size_t>(a)].apply(xab) : xab) * f;
            out += grad * (ps.mass()[b] / ps.density()[b] * grit::core::dot(c, x[b] - x[a]));
        }
        return out;
    }
};

template <int Dim>
void check_linear_field_exact() {
    Cloud<Dim> cloud(0.3, 0.0, 7);
    std::vector<grit::sph::GradientCorrection<Dim>> L;
    grit::sph::compute_gradient_correction(cloud.ps, cloud.nb.list(), cloud.kernel, {}, grit::Phase::fluid,
                                           grit::sph::phase_bit(grit::Phase::fluid), L);
    grit::core::Vec<Dim> c;
    for (int k = 0; k < Dim; ++k)
        c[k] = 1.0 + 2.0 * k;  // phi = x + 3 y (+ 5 z)
    double worst_corrected = 0.0, worst_plain = 0.0;
    for (Index a = 0; a < cloud.ps.size(); ++a) {  // every particle, those at the cloud's edges included
        worst_corrected =
            std::max(worst_corrected, grit::core::norm(cloud.gradient(a, c, &L) - c) / grit::core::norm(c));
        worst_plain = std::max(worst_plain, grit::core::norm(cloud.gradient(a, c, nullptr) - c) / grit::core::norm(c));
    }
    EXPECT_LT(worst_corrected, 1e-12);
    // The plain gradient is off by O(1) at the edges and by percents inside: the
    // test can fail.
    EXPECT_GT(worst_plain, 0.1);
}

}  // namespace

TEST(KernelCorrection, LinearFieldGradientExactOnDisorderedParticles2D) {
    check_linear_field_exact<2>();
}
TEST(KernelCorrection, LinearFieldGradientExactOnDisorderedParticles3D) {
    check_linear_field_exact<3>();
}

TEST(KernelCorrection, IsolatedParticleGetsTheIdentity) {
    Cloud<2> cloud(0.0, 0.0, 1);
    cloud.ps.position()[0] = {{50.0, 50.0}};  // far from the others: no neighbours
    cloud.nb.update(cloud.ps, 2.0 * Cloud<2>::h + 0.01, 0.01, true);
    std::vector<grit::sph::GradientCorrection<2>> L;
    grit::sph::compute_gradient_correction(cloud.ps, cloud.nb.list(), cloud.kernel, {}, grit::Phase::fluid,
                                           grit::sph::phase_bit(grit::Phase::fluid), L);
    for (Index a = 0; a < cloud.ps.size(); ++a) {
        if (cloud.nb.list().begin(a) != cloud.nb.list().end(a)) continue;
        EXPECT_EQ(L[static_cast<std::size_t>(a)].m[0][0], 1.0);
        EXPECT_EQ(L[static_cast<std::size_t>(a)].m[0][1], 0.0);
        EXPECT_EQ(L[static_cast<std::size_t>(a)].m[1][1], 1.0);
    }
}

TEST(ShepardFilter, KeepsAUniformDensity) {
    Cloud<2> cloud(0.3, 0.0, 3);
    std::vector<double> rho;
    grit::sph::shepard_density(cloud.ps, cloud.nb.list(), cloud.kernel, {}, rho);
    for (double r : rho)
        EXPECT_NEAR(r, 1000.0, 1e-9);
}

TEST(ShepardFilter, SmoothsANoisyDensity) {
    Cloud<2> cloud(0.1, 0.05, 5);
    std::vector<double> rho;
    grit::sph::shepard_density(cloud.ps, cloud.nb.list(), cloud.kernel, {}, rho);
    auto spread = [](const double* r, std::size_t n) {
        double mean = 0.0, var = 0.0;
        for (std::size_t i = 0; i < n; ++i)
            mean += r[i] / static_cast<double>(n);
        for (std::size_t i = 0; i < n; ++i)
            var += (r[i] - mean) * (r[i] - mean) / static_cast<double>(n);
        return std::sqrt(var);
    };
    const double before = spread(cloud.ps.density(), rho.size()), after = spread(rho.data(), rho.size());
    std::printf("density spread: %.2f -> %.2f kg/m^3\n", before, after);
    EXPECT_LT(after, 0.5 * before);
}
