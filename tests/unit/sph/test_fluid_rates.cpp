// The fluid sums, which evaluate each fluid-fluid pair once and hand the partner its share, against a
// plain gather over every particle's full list (the textbook form of eqs. 22-27 with density diffusion),
// on a disordered cloud of two fluids of unequal masses, with wall and solid neighbours, with and
// without grains' porosity; and bit-identical at 1 and 2 threads.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "grit/neighbors/particle_neighbors.hpp"
#include "grit/parallel/parallel.hpp"
#include "grit/sph/artificial_viscosity.hpp"
#include "grit/sph/fluid_rates.hpp"

using grit::Index;
using grit::Phase;

namespace {

/// A jittered lattice (per_axis^Dim particles, spacing dx) of two fluids (or one), a wall along the bottom
/// rows and a solid block in one corner; random velocities, densities, pressures and masses (+-20 %).
template <int Dim>
struct Cloud {
    static constexpr double dx = 0.01, h = 1.25 * dx;
    grit::particles::SphParticles<Dim> ps;
    grit::neighbors::ParticleNeighbors<Dim> nb;
    grit::sph::Kernel<Dim> kernel = grit::sph::CubicSpline<Dim>(h);
    grit::sph::FluidRateParameters<Dim> prm;
    std::vector<double> porosity;

    Cloud(int per_axis, unsigned seed, bool two_fluids = true) {
        std::mt19937 rng(seed);
        std::uniform_real_distribution<double> u(-1.0, 1.0);
        Index n = 1;
        for (int k = 0; k < Dim; ++k)
            n *= per_axis;
        ps.append(n);
        for (Index i = 0; i < n; ++i) {
            Index rest = i;
            int cell[Dim];
            for (int k = 0; k < Dim; ++k) {
                cell[k] = static_cast<int>(rest % per_axis);
                ps.position()[i][k] = (cell[k] + 0.5 + 0.3 * u(rng)) * dx;
                ps.velocity()[i][k] = 2.0 * u(rng);
                rest /= per_axis;
            }
            const bool wall = cell[Dim - 1] < 3;
            const bool solid = !wall && cell[0] < per_axis / 4 && cell[Dim - 1] < per_axis / 3;
            const int fluid_material = two_fluids && cell[0] % 3 == 0 ? 1 : 0;
            ps.phase()[i] = static_cast<std::int32_t>(wall ? Phase::wall : solid ? Phase::solid : Phase::fluid);
            ps.material()[i] = wall ? 2 : solid ? 3 : fluid_material;
            ps.density()[i] = (solid ? 2700.0 : 1000.0) * (1.0 + 0.02 * u(rng));
            ps.pressure()[i] = 1e4 * (1.0 + u(rng));
            ps.mass()[i] = (solid ? 2700.0 : 1000.0) * std::pow(dx, Dim) * (1.0 + 0.2 * u(rng));
        }
        nb.update(ps, 2.0 * h + 0.2 * dx, 0.2 * dx, true);
        // Two waters (the second stiffer, denser, more viscous), a wall and a solid.
        prm.materials = {{30.0, 1000.0, 0.1, 0.0, 1e-6},
                         {45.0, 1020.0, 0.2, 0.1, 3e-6},
                         {30.0, 1000.0, 0.1, 0.0, 1e-6},
                         {4000.0, 2700.0, 1.0, 1.0, 0.0}};
        prm.gravity[Dim - 1] = -9.81;
        prm.hydrostatic_gravity = prm.gravity;
        prm.density_diffusion = 0.1;
        porosity.resize(static_cast<std::size_t>(n));
        for (auto& e : porosity)
            e = 0.7 + 0.3 * std::abs(u(rng));
    }

    /// acceleration and density rate of fluid particle a, summed over its full list.
    std::pair<grit::core::Vec<Dim>, double> gather(Index a, const grit::sph::SphWorkspace& work,
                                                   const double* eps) const {
        const auto& nl = nb.list();
        const auto* x = ps.position();
        const auto* v = ps.velocity();
        const double* rho = ps.density();
        const double* m = ps.mass();
        const auto& k = std::get<grit::sph::CubicSpline<Dim>>(kernel);
        const auto& ca = prm.materials[static_cast<std::size_t>(ps.material()[a])];
        const double rho_a_true = eps ? rho[a] / eps[a] : rho[a];
        auto dv = prm.gravity;
        double continuity = 0.0, diffusion = 0.0;
        for (Index e = nl.begin(a); e < nl.end(a); ++e) {
            const Index b = nl.indices()[e];
            const auto& cb = prm.materials[static_cast<std::size_t>(ps.material()[b])];
            const auto xab = x[a] - x[b];
            const auto vab = v[a] - v[b];
            const double r2 = grit::core::norm2(xab);
            const double f = k.gradient_factor(std::sqrt(r2));
            const double vx = grit::core::dot(vab, xab);
            const double inv_r2 = 1.0 / (r2 + 0.01 * h * h), inv_rho_sum = 1.0 / (rho[a] + rho[b]);
            continuity += work.volume[b] * vx * f;
            const double pa = work.pressure_term[a], pb = work.pressure_term[b];
            const double pressure = ps.phase()[b] == static_cast<std::int32_t>(Phase::solid)
                                        ? pa * rho[a] / rho[b] + pb * rho[b] / rho[a]
                                        : pa + pb;
            const double pi = grit::sph::artificial_viscosity(h, vx, inv_r2, inv_rho_sum, ca, cb);
            const double nu = 0.5 * (ca.kinematic_viscosity + cb.kinematic_viscosity);
            dv += xab * (m[b] * (-pressure - pi) * f) + vab * (m[b] * 4.0 * nu * r2 * f * inv_rho_sum * inv_r2);
            if (ps.phase()[b] == static_cast<std::int32_t>(Phase::fluid)) {
                const double rho_b_true = eps ? rho[b] / eps[b] : rho[b];
                const double hydrostatic =
                    ca.reference_density / (ca.sound_speed * ca.sound_speed) * grit::core::dot(prm.gravity, xab);
                diffusion += work.volume[b] * (rho_a_true - rho_b_true - hydrostatic) * r2 * f * inv_r2;
            }
        }
        const double drho =
            rho[a] * continuity + (eps ? eps[a] : 1.0) * 2.0 * prm.density_diffusion * h * ca.sound_speed * diffusion;
        return {dv, drho};
    }

    void check_against_gather(bool with_porosity) {
        grit::sph::SphWorkspace work;
        grit::sph::prepare_sph_workspace(ps, work);
        grit::sph::FluidPairs<Dim> pairs;
        const double* eps = with_porosity ? porosity.data() : nullptr;
        grit::sph::compute_fluid_rates(ps, nb.list(), kernel, prm, work, pairs, eps);
        double acc_scale = 0.0, drho_scale = 0.0;
        std::vector<std::pair<grit::core::Vec<Dim>, double>> expected(static_cast<std::size_t>(ps.size()));
        for (Index a = 0; a < ps.size(); ++a) {
            if (ps.phase()[a] != static_cast<std::int32_t>(Phase::fluid)) continue;
            expected[static_cast<std::size_t>(a)] = gather(a, work, eps);
            acc_scale = std::max(acc_scale, grit::core::norm(expected[static_cast<std::size_t>(a)].first));
            drho_scale = std::max(drho_scale, std::abs(expected[static_cast<std::size_t>(a)].second));
        }
        Index fluid = 0;
        for (Index a = 0; a < ps.size(); ++a) {
            if (ps.phase()[a] != static_cast<std::int32_t>(Phase::fluid)) continue;
            ++fluid;
            const auto& [acc, drho] = expected[static_cast<std::size_t>(a)];
            // Round-off of sums of ~20 terms in another order.
            ASSERT_LT(grit::core::norm(ps.acceleration()[a] - acc), 1e-12 * acc_scale) << "particle " << a;
            ASSERT_LT(std::abs(ps.density_rate()[a] - drho), 1e-12 * drho_scale) << "particle " << a;
        }
        EXPECT_GT(fluid, ps.size() / 2);
    }
};

}  // namespace

TEST(FluidRates, EachPairOnceEqualsTheGatherSums2D) {
    Cloud<2> cloud(30, 3);
    cloud.check_against_gather(false);
    cloud.check_against_gather(true);
}

TEST(FluidRates, EachPairOnceEqualsTheGatherSums3D) {
    Cloud<3> cloud(10, 4);
    cloud.check_against_gather(false);
    cloud.check_against_gather(true);
}

// One fluid material: the pair loop takes a's coefficients for both sides instead of gathering b's.
TEST(FluidRates, EachPairOnceEqualsTheGatherSumsWithOneFluid) {
    Cloud<2> flat(30, 6, false);
    flat.check_against_gather(false);
    flat.check_against_gather(true);
    Cloud<3> box(10, 7, false);
    box.check_against_gather(false);
    box.check_against_gather(true);
}

// Several blocks with spills (about 3600 particles, 70,000 pairs): the same bits at 1 and 2 threads.
TEST(FluidRates, OneAndTwoThreadsGiveTheSameBits) {
    Cloud<2> cloud(60, 5);
    grit::sph::SphWorkspace work;
    grit::sph::prepare_sph_workspace(cloud.ps, work);
    std::vector<std::vector<double>> out(2);
    const int before = grit::parallel::max_threads();
    for (int threads : {1, 2}) {
        grit::parallel::set_threads(threads);
        grit::sph::FluidPairs<2> pairs;
        grit::sph::compute_fluid_rates(cloud.ps, cloud.nb.list(), cloud.kernel, cloud.prm, work, pairs,
                                       cloud.porosity.data());
        EXPECT_GT(pairs.lists.block_count(), 2);
        EXPECT_GT(pairs.lists.spill_rows(), 0u);
        for (Index a = 0; a < cloud.ps.size(); ++a) {
            if (cloud.ps.phase()[a] != 0) continue;
            out[static_cast<std::size_t>(threads - 1)].push_back(cloud.ps.acceleration()[a][0]);
            out[static_cast<std::size_t>(threads - 1)].push_back(cloud.ps.acceleration()[a][1]);
            out[static_cast<std::size_t>(threads - 1)].push_back(cloud.ps.density_rate()[a]);
        }
    }
    grit::parallel::set_threads(before);
    ASSERT_EQ(out[0].size(), out[1].size());
    for (std::size_t i = 0; i < out[0].size(); ++i)
        ASSERT_EQ(out[0][i], out[1][i]) << "value " << i;
}

// Across a fluid-solid interface the pressure term is repulsive only: copper in tension beside water
// (p_water + p_solid < 0) does not pull the water into itself (docs/theory.md, "Water inside a solid");
// water at a higher pressure than the copper's tension still pushes it away.
TEST(FluidRates, SolidInTensionDoesNotPullWater) {
    constexpr double dx = 1e-4, h = 1.25 * dx;
    auto water_acceleration = [&](double p_water, double p_solid) {
        grit::particles::SphParticles<2> ps;
        ps.append(2);
        ps.position()[0] = {0.0, 0.8 * dx};  // water above
        ps.position()[1] = {0.0, 0.0};       // copper below
        ps.phase()[0] = static_cast<std::int32_t>(Phase::fluid);
        ps.phase()[1] = static_cast<std::int32_t>(Phase::solid);
        ps.material()[0] = 0;
        ps.material()[1] = 1;
        ps.density()[0] = 1000.0;
        ps.density()[1] = 8960.0;
        ps.pressure()[0] = p_water;
        ps.pressure()[1] = p_solid;
        ps.mass()[0] = 1000.0 * dx * dx;
        ps.mass()[1] = 8960.0 * dx * dx;
        for (Index i = 0; i < 2; ++i) ps.velocity()[i] = {0.0, 0.0};
        grit::neighbors::ParticleNeighbors<2> nb;
        nb.update(ps, 2.0 * h + 0.2 * dx, 0.2 * dx, true);
        grit::sph::FluidRateParameters<2> prm;
        prm.materials = {{1480.0, 1000.0, 0.1, 0.1, 1e-6}, {3940.0, 8960.0, 1.0, 1.0, 0.0}};
        grit::sph::SphWorkspace work;
        grit::sph::prepare_sph_workspace(ps, work);
        grit::sph::FluidPairs<2> pairs;
        grit::sph::compute_fluid_rates(ps, nb.list(), grit::sph::Kernel<2>(grit::sph::CubicSpline<2>(h)), prm, work,
                                       pairs, nullptr);
        return ps.acceleration()[0][1];
    };
    EXPECT_EQ(water_acceleration(1.0e6, -1.0e9), 0.0);  // would pull the water down into the copper
    EXPECT_GT(water_acceleration(1.0e9, -1.0e6), 0.0);  // the water's pressure wins: pushed up
    EXPECT_GT(water_acceleration(1.0e6, 1.0e6), 0.0);
}
