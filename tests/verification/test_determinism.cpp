// Every case in cases/ gives bit-identical particles at 1 and 2 threads (gather loops, fixed-order
// reductions), grains included: a race or an order-dependent sum would show here.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>

#include "grit/parallel/parallel.hpp"
#include "support/case_fixture.hpp"

using grit::testing::all_cases;

namespace {

template <int Dim>
struct RunState {
    grit::particles::SphParticles<Dim> particles;
    std::vector<grit::core::Vec<Dim>> grain_position, grain_velocity;  // in the grains' order
};

/// threads > 0: that many throughout; 0: 2 and 1 in turn, changed before every step (what the thread
/// governor of `grit run` may do).
template <int Dim>
RunState<Dim> run(const grit::io::CaseSpec& spec, int threads, int steps) {
    grit::parallel::set_threads(threads > 0 ? threads : 2);
    grit::sim::Simulation<Dim> sim(spec, grit::testing::in_memory());
    sim.advance_to(0.0);
    for (int k = 0; k < steps; ++k) {
        if (threads == 0) grit::parallel::set_threads(2 - k % 2);
        sim.step();
    }
    RunState<Dim> out{sim.particles(), {}, {}};
    if (auto* g = sim.grains()) {
        const auto& grains = g->grains();
        out.grain_position.assign(grains.position(), grains.position() + grains.size());
        out.grain_velocity.assign(grains.velocity(), grains.velocity() + grains.size());
    }
    return out;
}

template <int Dim>
void compare(const grit::io::CaseSpec& spec, int steps = 40, int threads = 2) {
    const auto one_run = run<Dim>(spec, 1, steps);
    const auto two_run = run<Dim>(spec, threads, steps);
    grit::parallel::set_threads(2);
    const auto& one = one_run.particles;
    const auto& two = two_run.particles;
    ASSERT_EQ(one.size(), two.size());
    ASSERT_GT(one.size() + static_cast<grit::Index>(one_run.grain_position.size()), 0);
    for (grit::Index i = 0; i < one.size(); ++i) {
        for (int k = 0; k < Dim; ++k) {
            ASSERT_EQ(one.position()[i][k], two.position()[i][k]) << "particle " << i;
            ASSERT_EQ(one.velocity()[i][k], two.velocity()[i][k]) << "particle " << i;
        }
        ASSERT_EQ(one.density()[i], two.density()[i]) << "particle " << i;
        ASSERT_EQ(one.pressure()[i], two.pressure()[i]) << "particle " << i;
    }
    ASSERT_EQ(one_run.grain_position.size(), two_run.grain_position.size());
    for (std::size_t i = 0; i < one_run.grain_position.size(); ++i)
        for (int k = 0; k < Dim; ++k) {
            ASSERT_EQ(one_run.grain_position[i][k], two_run.grain_position[i][k]) << "grain " << i;
            ASSERT_EQ(one_run.grain_velocity[i][k], two_run.grain_velocity[i][k]) << "grain " << i;
        }
}

}  // namespace

TEST(Determinism, EveryCaseIsIdenticalAtOneAndTwoThreads) {
    const auto cases = all_cases();
    ASSERT_GE(cases.size(), 6u);
    for (const auto& path : cases) {
        SCOPED_TRACE(path.string());
        const auto spec = grit::io::read_case(path);
        if (spec.dimension == 2)
            compare<2>(spec);
        else
            compare<3>(spec);
    }
}

// Grains settling on an STL mesh floor (the mesh contacts are gathered per grain).
TEST(Determinism, GrainsOnAMeshWallAreIdenticalAtOneAndTwoThreads) {
    // 1500 steps of 1e-5 s: the first layer lands on the mesh after about 1000.
    compare<3>(grit::testing::settling_on_mesh_case("finnie_liggghts"), 1500);
}

// The periodic channel with the fluid set moving fast along the periodic axis: within the 40 steps
// particles cross the periodic face and the lists are rebuilt over the periodic grid.
TEST(Determinism, PeriodicChannelAcrossTheFaceIsIdenticalAtOneAndTwoThreads) {
    const auto spec = grit::testing::load_case("poiseuille_periodic_2d/case.toml",
                                               {"fluid[0].velocity=[0.05, 0.0]", "materials.viscous_water.sound_speed=0.5"});
    compare<2>(spec);
}

// The thread count changed between steps (parallel::ThreadGovernor) changes nothing: the AWJ with
// grains, water and copper, and its half with the symmetry plane's images, 2 and 1 threads in turn.
TEST(Determinism, ThreadCountChangedBetweenStepsChangesNothing) {
    compare<2>(grit::testing::load_case("demo.toml"), 300, 0);
    compare<2>(grit::testing::load_case("demo.toml", {"jet.symmetric=true"}), 300, 0);
}

// Non-local damage (sph/nonlocal_damage.hpp): a garnet grain at 500 m/s into the x >= 0 half of a copper
// plate on a symmetry plane, the damage averaged over 3 spacings on its own pair list, images included;
// the damage field too, bit for bit.
TEST(Determinism, NonlocalDamageIsIdenticalAtOneAndTwoThreads) {
    const auto spec = grit::testing::load_case(
        "grain_impact_copper_2d/case.toml",
        {"grains[0].velocity=[0.0, -500.0]", "materials.OFHC_copper.damage_length=6e-5", "domain.symmetry=[\"x\"]",
         "solid[0].min=[0.0, -1.0e-3]"});
    const auto one = run<2>(spec, 1, 800), two = run<2>(spec, 2, 800);
    grit::parallel::set_threads(2);
    ASSERT_EQ(one.particles.size(), two.particles.size());
    ASSERT_GT(one.particles.image_count(), 0);
    const auto& f1 = one.particles.fields().get<double>("damage");
    const auto& f2 = two.particles.fields().get<double>("damage");
    const double* d1 = f1.data();
    const double* d2 = f2.data();
    double largest = 0.0;
    for (grit::Index i = 0; i < f1.size(); ++i) {
        ASSERT_EQ(one.particles.position()[i][0], two.particles.position()[i][0]) << "particle " << i;
        ASSERT_EQ(one.particles.position()[i][1], two.particles.position()[i][1]) << "particle " << i;
        ASSERT_EQ(d1[i], d2[i]) << "particle " << i;
        largest = std::max(largest, d1[i]);
    }
    EXPECT_GT(largest, 0.05);  // the grain has damaged the copper
}
