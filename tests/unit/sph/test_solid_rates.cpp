// The solid sums, which evaluate each solid-solid pair once and hand the partner its share, on a
// disordered block with random stresses (some in tension: artificial stress on) and velocities:
// momentum and energy (kinetic + internal) are conserved pair by pair, the corrected strain rate of a
// linear velocity field is exact at every particle, and 1 and 2 threads give the same bits.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "grit/neighbors/particle_neighbors.hpp"
#include "grit/parallel/parallel.hpp"
#include "grit/sph/solid_rates.hpp"

using grit::Index;
using grit::core::SymTensor3;

namespace {

template <int Dim>
struct Block {
    static constexpr double dx = 1e-4, h = 1.25 * dx;
    grit::particles::SphParticles<Dim> ps;
    grit::neighbors::ParticleNeighbors<Dim> nb;
    grit::sph::Kernel<Dim> kernel = grit::sph::CubicSpline<Dim>(h);
    grit::sph::SolidRateParameters<Dim> prm;
    grit::sph::SphWorkspace sph;
    grit::sph::SolidWorkspace<Dim> work;

    /// per_axis^Dim particles; velocity v = A x when `linear`, else random.
    Block(int per_axis, unsigned seed, bool linear) {
        std::mt19937 rng(seed);
        std::uniform_real_distribution<double> u(-1.0, 1.0);
        Index n = 1;
        for (int k = 0; k < Dim; ++k)
            n *= per_axis;
        ps.append(n);
        ps.fields().template add<SymTensor3>("deviatoric_stress", SymTensor3::zero(), false);
        for (Index i = 0; i < n; ++i) {
            Index rest = i;
            for (int k = 0; k < Dim; ++k) {
                ps.position()[i][k] = (static_cast<double>(rest % per_axis) + 0.5 + 0.2 * u(rng)) * dx;
                rest /= per_axis;
            }
            ps.phase()[i] = static_cast<std::int32_t>(grit::Phase::solid);
            ps.material()[i] = 0;
            ps.density()[i] = 8960.0 * (1.0 + 0.01 * u(rng));
            ps.mass()[i] = 8960.0 * std::pow(dx, Dim) * (1.0 + 0.1 * u(rng));
            ps.pressure()[i] = 1e8 * u(rng);  // negative: tension, where the artificial stress acts
        }
        nb.update(ps, 2.0 * h + 0.2 * dx, 0.2 * dx, true);
        auto* tau = ps.fields().template get<SymTensor3>("deviatoric_stress").data();
        const double a[3][3] = {{3.0, 1.0, -2.0}, {0.5, -1.0, 4.0}, {1.5, 2.5, 0.7}};  // v = A x [1/s]
        for (Index i = 0; i < n; ++i) {
            tau[i] = {1e8 * u(rng),
                      1e8 * u(rng),
                      Dim == 3 ? 1e8 * u(rng) : 0.0,
                      1e8 * u(rng),
                      Dim == 3 ? 1e8 * u(rng) : 0.0,
                      Dim == 3 ? 1e8 * u(rng) : 0.0};
            for (int r = 0; r < Dim; ++r) {
                double vr = 0.0;
                for (int c = 0; c < Dim; ++c)
                    vr += a[r][c] * ps.position()[i][c];
                ps.velocity()[i][r] = linear ? vr : 50.0 * u(rng);
            }
        }
        prm.spacing = dx;
        prm.materials = {{4700.0, 8960.0, 1.0, 1.0, 0.0}};
        grit::sph::prepare_sph_workspace(ps, sph);
    }

    void compute() { grit::sph::compute_solid_rates(ps, nb.list(), kernel, prm, sph, work); }
};

template <int Dim>
void check_conservation() {
    Block<Dim> block(Dim == 2 ? 30 : 10, 21, false);
    block.compute();
    double momentum[Dim] = {}, momentum_scale = 0.0, power = 0.0, power_scale = 0.0;
    for (Index a = 0; a < block.ps.size(); ++a) {
        const double m = block.ps.mass()[a];
        for (int k = 0; k < Dim; ++k) {
            momentum[k] += m * block.ps.acceleration()[a][k];
            momentum_scale = std::max(momentum_scale, std::abs(m * block.ps.acceleration()[a][k]));
        }
        const double kinetic = m * grit::core::dot(block.ps.velocity()[a], block.ps.acceleration()[a]);
        const double internal = m * block.work.energy_rate[static_cast<std::size_t>(a)];
        power += kinetic + internal;
        power_scale = std::max({power_scale, std::abs(kinetic), std::abs(internal)});
    }
    // Round-off of N ~ 1000 sums: every pair adds equal and opposite forces, and its work both ways.
    for (int k = 0; k < Dim; ++k)
        EXPECT_LT(std::abs(momentum[k]), 1e-10 * momentum_scale) << "axis " << k;
    EXPECT_LT(std::abs(power), 1e-10 * power_scale);
    // The artificial stress took part (tension somewhere).
    EXPECT_GT(std::count(block.work.has_artificial_stress.begin(), block.work.has_artificial_stress.end(), 1), 0);
}

template <int Dim>
void check_linear_strain_rate() {
    Block<Dim> block(Dim == 2 ? 20 : 8, 22, true);
    block.compute();
    const double a[3][3] = {{3.0, 1.0, -2.0}, {0.5, -1.0, 4.0}, {1.5, 2.5, 0.7}};
    for (Index i = 0; i < block.ps.size(); ++i) {  // edges and corners included
        const SymTensor3& d = block.work.strain_rate[static_cast<std::size_t>(i)];
        EXPECT_NEAR(d.xx, a[0][0], 1e-9) << i;
        EXPECT_NEAR(d.yy, a[1][1], 1e-9) << i;
        EXPECT_NEAR(d.xy, 0.5 * (a[0][1] + a[1][0]), 1e-9) << i;
        EXPECT_NEAR(block.work.spin[static_cast<std::size_t>(i)].xy, 0.5 * (a[0][1] - a[1][0]), 1e-9) << i;
        if constexpr (Dim == 3) {
            EXPECT_NEAR(d.zz, a[2][2], 1e-9) << i;
            EXPECT_NEAR(d.yz, 0.5 * (a[1][2] + a[2][1]), 1e-9) << i;
            EXPECT_NEAR(d.zx, 0.5 * (a[2][0] + a[0][2]), 1e-9) << i;
        }
    }
}

}  // namespace

TEST(SolidRates, MomentumAndEnergyConservedPairByPair2D) {
    check_conservation<2>();
}
TEST(SolidRates, MomentumAndEnergyConservedPairByPair3D) {
    check_conservation<3>();
}
TEST(SolidRates, CorrectedStrainRateOfALinearFieldIsExact2D) {
    check_linear_strain_rate<2>();
}
TEST(SolidRates, CorrectedStrainRateOfALinearFieldIsExact3D) {
    check_linear_strain_rate<3>();
}

// Several blocks with spills: the same bits at 1 and 2 threads.
TEST(SolidRates, OneAndTwoThreadsGiveTheSameBits) {
    Block<2> block(70, 23, false);
    std::vector<std::vector<double>> out(2);
    const int before = grit::parallel::max_threads();
    for (int threads : {1, 2}) {
        grit::parallel::set_threads(threads);
        block.work = {};
        block.compute();
        EXPECT_GT(block.work.lists.block_count(), 2);
        auto& o = out[static_cast<std::size_t>(threads - 1)];
        for (Index a = 0; a < block.ps.size(); ++a) {
            o.push_back(block.ps.acceleration()[a][0]);
            o.push_back(block.ps.acceleration()[a][1]);
            o.push_back(block.ps.density_rate()[a]);
            o.push_back(block.work.energy_rate[static_cast<std::size_t>(a)]);
            o.push_back(block.work.strain_rate[static_cast<std::size_t>(a)].xy);
        }
    }
    grit::parallel::set_threads(before);
    ASSERT_EQ(out[0].size(), out[1].size());
    for (std::size_t i = 0; i < out[0].size(); ++i)
        ASSERT_EQ(out[0][i], out[1][i]) << "value " << i;
}
