// Conservation: mass exactly; momentum to round-off for a free blob (no walls, no gravity) and for a
// closed periodic box; and the jet's books: mass in = mass out + mass in the domain.
#include <gtest/gtest.h>

#include <cmath>

#include "grit/modules/probes_table.hpp"
#include "support/case_fixture.hpp"

using grit::testing::in_memory;
using grit::testing::load_case;

namespace {

template <int Dim>
void free_blob(const std::vector<std::string>& geometry) {
    // The hydrostatic case's material and numerics, with a free disc of fluid instead of the tank.
    std::vector<std::string> overrides = {"time.end=0.02"};
    overrides.insert(overrides.end(), geometry.begin(), geometry.end());
    const auto spec = grit::testing::free_blob_case<Dim>(overrides);
    grit::sim::Simulation<Dim> sim(spec, in_memory());
    auto& ps = sim.particles();
    // A swirling, compressing, uneven velocity field.
    for (grit::Index i = 0; i < ps.size(); ++i) {
        auto x = ps.position()[i];
        grit::core::Vec<Dim> v = grit::core::Vec<Dim>::zero();
        v[0] = -(x[1] - 0.1) * 20.0 + 0.3 * std::sin(40.0 * x[0]);
        v[1] = (x[0] - 0.1) * 20.0 - 0.5 * (x[1] - 0.1) * 10.0;
        if (Dim == 3) v[Dim - 1] = 0.2 * std::cos(30.0 * x[1]);
        ps.velocity()[i] = v;
        ps.velocity_half()[i] = v;
    }
    const auto before = grit::analysis::compute_diagnostics(ps);
    double scale = 0.0;
    for (grit::Index i = 0; i < ps.size(); ++i) scale += ps.mass()[i] * grit::core::norm(ps.velocity()[i]);
    sim.advance_to(spec.end_time);
    EXPECT_GT(sim.steps(), 100);
    const auto after = grit::analysis::compute_diagnostics(ps);
    EXPECT_EQ(after.mass, before.mass);
    for (int k = 0; k < Dim; ++k) EXPECT_NEAR(after.momentum[k], before.momentum[k], 1e-13 * scale) << "component " << k;
    EXPECT_LT(after.kinetic_energy, before.kinetic_energy);  // viscosity only removes energy
}

// A closed periodic box: fluid filling a box periodic along every axis (no walls, no gravity), moving
// with a drift (particles cross every face) and a periodic swirl. Pair terms through the periodic faces
// are antisymmetric like the others, so momentum is conserved to round-off.
template <int Dim>
void periodic_box(double length, const std::vector<std::string>& numerics) {
    std::vector<std::string> overrides = {"physics.gravity=[" + std::string(Dim == 2 ? "0.0, 0.0" : "0.0, 0.0, 0.0") + "]",
                                          "time.end=0.02"};
    overrides.insert(overrides.end(), numerics.begin(), numerics.end());
    auto spec = load_case(Dim == 2 ? "hydrostatic_2d/case.toml" : "hydrostatic_3d/case.toml", overrides);
    spec.walls.clear();
    spec.module_specs.erase(grit::modules::ProbesSpec::key);
    spec.fluids[0].hydrostatic = false;
    spec.fluids[0].shape.min.assign(Dim, 0.0);
    spec.fluids[0].shape.max.assign(Dim, length);
    spec.domain_min.assign(Dim, 0.0);
    spec.domain_max.assign(Dim, length);
    spec.periodic.assign(Dim, true);
    grit::sim::Simulation<Dim> sim(spec, in_memory());
    auto& ps = sim.particles();
    const double k = 2.0 * 3.141592653589793 / length;
    for (grit::Index i = 0; i < ps.size(); ++i) {
        const auto x = ps.position()[i];
        grit::core::Vec<Dim> v = grit::core::Vec<Dim>::zero();
        v[0] = 1.5 + 0.8 * std::sin(k * x[1]);
        v[1] = -0.7 + 0.6 * std::cos(k * x[0]) + 0.2 * std::sin(2.0 * k * x[1]);  // compresses along y too
        if (Dim == 3) v[2] = 0.9 + 0.5 * std::sin(k * x[0] + k * x[1]);
        ps.velocity()[i] = v;
        ps.velocity_half()[i] = v;
    }
    const grit::Index count = ps.size();
    const auto before = grit::analysis::compute_diagnostics(ps);
    double scale = 0.0;
    for (grit::Index i = 0; i < ps.size(); ++i) scale += ps.mass()[i] * grit::core::norm(ps.velocity()[i]);
    sim.advance_to(spec.end_time);
    EXPECT_GT(sim.steps(), 100);
    const auto after = grit::analysis::compute_diagnostics(ps);
    ASSERT_EQ(ps.size(), count);
    EXPECT_EQ(after.mass, before.mass);
    for (int d = 0; d < Dim; ++d) EXPECT_NEAR(after.momentum[d], before.momentum[d], 1e-13 * scale) << "component " << d;
    EXPECT_LT(after.kinetic_energy, before.kinetic_energy);
    for (grit::Index i = 0; i < ps.size(); ++i)
        for (int d = 0; d < Dim; ++d)
            ASSERT_TRUE(ps.position()[i][d] >= 0.0 && ps.position()[i][d] < length) << "particle " << i;
    EXPECT_GT(sim.state().neighbors.builds(), 2);  // the drift (1.5 m/s over 0.02 s = 3 spacings) moved them on
}

}  // namespace

TEST(Conservation, FreeBlobMomentum2D) { free_blob<2>({}); }
TEST(Conservation, FreeBlobMomentum3D) { free_blob<3>({"numerics.particle_spacing=0.012"}); }

TEST(Conservation, ClosedPeriodicBoxMomentum2D) { periodic_box<2>(0.2, {}); }
TEST(Conservation, ClosedPeriodicBoxMomentum3D) { periodic_box<3>(0.12, {"numerics.particle_spacing=0.012"}); }

TEST(Conservation, JetMassBooks) {
    grit::sim::Simulation<2> sim(load_case("jet_on_wall_2d/case.toml", {"numerics.particle_spacing=1e-4"}),
                                 in_memory());
    for (double t = 1e-5; t <= 6e-5 + 1e-12; t += 1e-5) {
        sim.advance_to(t);
        const auto d = grit::analysis::compute_diagnostics(sim.particles());
        EXPECT_NEAR(d.mass + sim.mass_out(), sim.mass_in(), 1e-12 * sim.mass_in()) << "t = " << t;
    }
    EXPECT_GT(sim.mass_out(), 0.0);  // the outlets have started to book outflow
}
