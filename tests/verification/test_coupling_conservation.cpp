// The fluid-grain coupling exchanges momentum without creating any: a free blob of water with grains
// inside it, and a closed periodic box of water and grains (no walls, no gravity, so nothing outside
// acts), keep the total momentum of fluid and grains to round-off, the fluid's mass exactly once the
// coupling has taken the grains' volume out of it, and give the same state at 1 and 2 threads.
#include <gtest/gtest.h>

#include <cmath>

#include "grit/parallel/parallel.hpp"
#include "support/case_fixture.hpp"

using grit::testing::in_memory;
using grit::testing::load_case;

namespace {

template <int Dim>
grit::io::CaseSpec blob_with_grains() {
    std::vector<std::string> overrides = {"time.end=0.004"};
    if (Dim == 3) overrides.push_back("numerics.particle_spacing=0.012");
    auto spec = grit::testing::free_blob_case<Dim>(overrides);
    spec.materials[0].dynamic_viscosity = 1e-3;
    // Garnet grains of 0.8 fluid spacings, moving across the swirling fluid.
    auto garnet = grit::dem::garnet();
    garnet.diameter = 0.8 * spec.particle_spacing;
    spec.grain_materials = {garnet};
    grit::io::GrainBlockSpec block;
    block.key = "grains[0]";
    block.arrangement = "random";
    block.min.assign(Dim, 0.07);
    block.max.assign(Dim, 0.13);
    block.count = 6;
    block.size = grit::dem::FixedSize{garnet.diameter};
    block.seed = 3;
    block.velocity.assign(Dim, 0.0);
    block.velocity[0] = 0.5;
    spec.grains = {block};
    spec.coupling.radius = 3.0;
    return spec;
}

// Water filling a box periodic along every axis (sedimentation_2d/3d's column without its floor), with
// grains that cross the periodic faces: the pairs and weights across the faces take the nearest image.
template <int Dim>
grit::io::CaseSpec periodic_box_with_grains() {
    auto spec = load_case(Dim == 2 ? "sedimentation_2d/case.toml" : "sedimentation_3d/case.toml",
                          {"time.end=0.004", "numerics.particle_spacing=2.0e-4", "coupling.radius=4.0"});
    spec.gravity.assign(Dim, 0.0);
    spec.walls.clear();
    spec.fluids[0].hydrostatic = false;
    spec.fluids[0].shape.min.assign(Dim, 0.0);
    spec.fluids[0].shape.max.assign(Dim, 2.4e-3);
    spec.domain_min.assign(Dim, 0.0);
    spec.domain_max.assign(Dim, 2.4e-3);
    spec.periodic.assign(Dim, true);
    grit::io::GrainBlockSpec block = spec.grains[0];
    block.arrangement = "random";
    block.min.assign(Dim, 0.0);
    block.max.assign(Dim, 2.4e-3);
    block.count = 8;
    block.seed = 5;
    block.velocity.assign(Dim, 0.0);
    block.velocity[0] = 0.3;  // crosses the periodic face x = 2.4 mm within the run
    block.velocity[Dim - 1] = -0.2;
    spec.grains = {block};
    return spec;
}

template <int Dim>
grit::core::Vec<Dim> total_momentum(grit::sim::Simulation<Dim>& sim) {
    auto p = grit::analysis::compute_diagnostics(sim.particles()).momentum;
    return p + sim.grains()->momentum();
}

template <int Dim>
void check_momentum_and_mass(const grit::io::CaseSpec& spec, double swirl, double centre) {
    grit::sim::Simulation<Dim> sim(spec, in_memory());
    auto& ps = sim.particles();
    for (grit::Index i = 0; i < ps.size(); ++i) {  // a swirl, so the grains move through the water
        auto x = ps.position()[i];
        grit::core::Vec<Dim> v = grit::core::Vec<Dim>::zero();
        v[0] = -(x[1] - centre) * swirl;
        v[1] = (x[0] - centre) * swirl;
        ps.velocity()[i] = v;
        ps.velocity_half()[i] = v;
    }
    sim.advance_to(1e-3 * spec.end_time);  // the first step takes the grains' volume out of the fluid's mass (eq. 21)
    const double mass = grit::analysis::compute_diagnostics(ps).mass;
    const auto before = total_momentum(sim);
    double scale = 0.0;
    for (grit::Index i = 0; i < ps.size(); ++i) scale += ps.mass()[i] * grit::core::norm(ps.velocity()[i]);
    sim.advance_to(spec.end_time);
    EXPECT_GT(sim.steps(), 100);
    // The coupling acted: the grains' fluid force is not zero.
    const auto& grains = sim.grains()->grains();
    const auto* f = grains.fields().template get<grit::core::Vec<Dim>>("fluid_force").data();
    double fmax = 0.0;
    for (grit::Index i = 0; i < grains.size(); ++i) fmax = std::max(fmax, grit::core::norm(f[i]));
    EXPECT_GT(fmax, 0.0);
    EXPECT_EQ(grit::analysis::compute_diagnostics(ps).mass, mass);
    const auto after = total_momentum(sim);
    for (int k = 0; k < Dim; ++k) EXPECT_NEAR(after[k], before[k], 1e-13 * scale) << "component " << k;
}

}  // namespace

TEST(CouplingConservation, FreeBlobWithGrainsMomentum2D) { check_momentum_and_mass<2>(blob_with_grains<2>(), 10.0, 0.1); }
TEST(CouplingConservation, FreeBlobWithGrainsMomentum3D) { check_momentum_and_mass<3>(blob_with_grains<3>(), 10.0, 0.1); }
TEST(CouplingConservation, PeriodicBoxWithGrainsMomentum2D) {
    check_momentum_and_mass<2>(periodic_box_with_grains<2>(), 0.0, 0.0);
}
TEST(CouplingConservation, PeriodicBoxWithGrainsMomentum3D) {
    check_momentum_and_mass<3>(periodic_box_with_grains<3>(), 0.0, 0.0);
}

template <class Spec>
void same_state_at_one_and_two_threads(const Spec& spec) {
    const int threads_before = grit::parallel::max_threads();
    std::vector<double> grain_x[2];
    std::vector<double> fluid_v[2];
    for (int threads : {1, 2}) {
        grit::parallel::set_threads(threads);
        grit::sim::Simulation<2> sim(spec, in_memory());
        sim.advance_to(spec.end_time);
        const auto& g = sim.grains()->grains();
        for (grit::Index i = 0; i < g.size(); ++i)
            for (int k = 0; k < 2; ++k) grain_x[threads - 1].push_back(g.position()[i][k]);
        const auto& ps = sim.particles();
        for (grit::Index i = 0; i < ps.size(); ++i)
            for (int k = 0; k < 2; ++k) fluid_v[threads - 1].push_back(ps.velocity()[i][k]);
    }
    grit::parallel::set_threads(threads_before);
    EXPECT_EQ(grain_x[0], grain_x[1]);
    EXPECT_EQ(fluid_v[0], fluid_v[1]);
}

TEST(CouplingConservation, SameStateAtOneAndTwoThreads) { same_state_at_one_and_two_threads(blob_with_grains<2>()); }
TEST(CouplingConservation, PeriodicBoxSameStateAtOneAndTwoThreads) {
    same_state_at_one_and_two_threads(periodic_box_with_grains<2>());
}
