// Hydrostatic tanks (2D, 3D): after settling, p = rho g depth within 5 %, and no fluid leaves the tank.
// Also: the same run at 1 and 2 threads gives bit-identical particles (gather loops, fixed reductions).
#include <gtest/gtest.h>

#include <cstdio>

#include <array>
#include <cmath>

#include "grit/modules/probes_table.hpp"
#include "grit/parallel/parallel.hpp"
#include "support/case_fixture.hpp"
#include "support/validation_figures.hpp"

using grit::testing::in_memory;
using grit::testing::load_case;

namespace {

constexpr double rho0 = 1000.0, g = 9.81;

/// The case's probes ([[probe]], read by the probes module's table).
const std::vector<grit::analysis::ProbeSpec>& probes_of(const grit::io::CaseSpec& spec) {
    return spec.module_spec<grit::modules::ProbesSpec>(grit::modules::ProbesSpec::key)->probes;
}

template <int Dim>
void check_tank(grit::sim::Simulation<Dim>& sim, double surface, const std::vector<double>& tank_max) {
    const auto& spec = sim.spec();
    double largest = 0.0;  // the largest relative error over the probes, signed
    for (std::size_t k = 0; k < probes_of(spec).size(); ++k) {
        const double depth = surface - probes_of(spec)[k].position[Dim - 1];
        const double expected = rho0 * g * depth;
        EXPECT_NEAR(sim.probe(k), expected, 0.05 * expected) << probes_of(spec)[k].name << " at depth " << depth;
        const double error = sim.probe(k) / expected - 1.0;
        if (std::abs(error) > std::abs(largest)) largest = error;
    }
    grit::testing::record_figure({"largest probe error", 100.0 * largest, "%", "5 % per probe", "p = rho g depth"});
    // No leakage: every fluid particle is inside the tank's inner box.
    auto& ps = sim.particles();
    for (grit::Index i = 0; i < ps.size(); ++i) {
        if (ps.phase()[i] != 0) continue;
        for (int k = 0; k < Dim; ++k) {
            ASSERT_GE(ps.position()[i][k], 0.0) << "fluid particle " << i << " left through a wall";
            ASSERT_LE(ps.position()[i][k], tank_max[static_cast<std::size_t>(k)]) << "fluid particle " << i;
        }
    }
    const auto d = grit::analysis::compute_diagnostics(ps);
    EXPECT_LT(d.max_velocity, 0.02) << "the tank has not settled";
}

}  // namespace

TEST(Hydrostatic, Tank2D) {
    grit::sim::Simulation<2> sim(load_case("hydrostatic_2d/case.toml"), in_memory());
    sim.advance_to(sim.spec().end_time);
    check_tank<2>(sim, 0.3, {0.4, 0.4});
}

TEST(Hydrostatic, Tank3D) {
    grit::sim::Simulation<3> sim(load_case("hydrostatic_3d/case.toml", {"time.end=0.3"}), in_memory());
    sim.advance_to(sim.spec().end_time);
    check_tank<3>(sim, 0.2, {0.2, 0.1, 0.3});
}

// The same tank walled by particles laid along a closed STL box (issue 13: within 5 % of rho g depth).
TEST(Hydrostatic, TankFromAnStlMesh3D) {
    grit::sim::Simulation<3> sim(load_case("hydrostatic_mesh_3d/case.toml", {"time.end=0.3"}), in_memory());
    sim.advance_to(sim.spec().end_time);
    for (std::size_t k = 0; k < probes_of(sim.spec()).size(); ++k)
        std::printf("%s: %.1f Pa (rho g depth %.1f Pa)\n", probes_of(sim.spec())[k].name.c_str(), sim.probe(k),
                    rho0 * g * (0.2 - probes_of(sim.spec())[k].position[2]));
    check_tank<3>(sim, 0.2, {0.2, 0.1, 0.3});
}

// Two levels across a membrane of zero thickness (issue 13: particles on the two sides of a thin wall
// must not interact; second paper, sec. 3.2): each side's pressure is rho g times its own depth within
// 5 %, and no particle crosses the membrane.
TEST(Hydrostatic, TwoLevelsAcrossAThinMembrane3D) {
    grit::sim::Simulation<3> sim(load_case("hydrostatic_membrane_3d/case.toml"), in_memory());
    auto sides = [&] {
        std::array<int, 2> count{0, 0};
        const auto& ps = sim.particles();
        for (grit::Index i = 0; i < ps.size(); ++i)
            if (ps.phase()[i] == 0) ++count[ps.position()[i][0] < 0.05 ? 0 : 1];
        return count;
    };
    const auto before = sides();
    sim.advance_to(sim.spec().end_time);
    const double surface[3] = {0.1, 0.1, 0.05};  // the probes: two on the left, one on the right
    for (std::size_t k = 0; k < probes_of(sim.spec()).size(); ++k) {
        const double expected = rho0 * g * (surface[k] - probes_of(sim.spec())[k].position[2]);
        std::printf("%s: %.1f Pa (rho g depth %.1f Pa)\n", probes_of(sim.spec())[k].name.c_str(), sim.probe(k), expected);
        EXPECT_NEAR(sim.probe(k), expected, 0.05 * expected) << probes_of(sim.spec())[k].name;
    }
    const auto after = sides();
    EXPECT_EQ(after[0], before[0]) << "particles crossed the membrane";
    EXPECT_EQ(after[1], before[1]) << "particles crossed the membrane";
    EXPECT_LT(grit::analysis::compute_diagnostics(sim.particles()).max_velocity, 0.02) << "the tank has not settled";
}

TEST(Hydrostatic, OneAndTwoThreadsGiveIdenticalParticles) {
    auto run = [](int threads) {
        grit::parallel::set_threads(threads);
        grit::sim::Simulation<2> sim(load_case("hydrostatic_2d/case.toml", {"time.end=0.05"}), in_memory());
        sim.advance_to(sim.spec().end_time);
        return sim.particles();
    };
    const auto one = run(1);
    const auto two = run(2);
    grit::parallel::set_threads(2);
    ASSERT_EQ(one.size(), two.size());
    for (grit::Index i = 0; i < one.size(); ++i) {
        ASSERT_EQ(one.position()[i][0], two.position()[i][0]) << i;
        ASSERT_EQ(one.position()[i][1], two.position()[i][1]) << i;
        ASSERT_EQ(one.density()[i], two.density()[i]) << i;
        ASSERT_EQ(one.pressure()[i], two.pressure()[i]) << i;
    }
}
