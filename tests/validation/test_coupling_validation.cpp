// Validation of the unresolved fluid-grain coupling (eqs. 20-23, 42-50) on the cases of cases/:
//  - sedimentation_2d / sedimentation_3d: one glass grain settling in water reaches the terminal velocity
//    the Gidaspow law gives a lone grain (eps = 1), and (3D) approaches it as the grain's equation of
//    motion does;
//  - packed_bed_2d: a body force drives water through a lattice of fixed grains; the superficial
//    velocity against Ergun's equation at two body forces;
//  - a grain of the water's density at rest near the floor feels Archimedes' buoyancy, as in open water.
// References: scripts/terminal_velocity.py and scripts/ergun.py (reference/ of each case).
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "support/case_fixture.hpp"

using grit::testing::in_memory;
using grit::testing::load_case;

namespace {

template <int Dim>
double output(const grit::sim::Simulation<Dim>& sim, const std::string& name) {
    for (const auto& v : sim.output_values())
        if (v.name == name) return v.value;
    ADD_FAILURE() << "no output value '" << name << "'";
    return std::nan("");
}

// d = 100 um, rho_p = 2500, water rho_f = 1000, mu = 8.9e-4, g = 9.81, Gidaspow (Wen-Yu, eps = 1):
// `python3 scripts/terminal_velocity.py` (cases/sedimentation_2d/reference/terminal_velocity.txt).
constexpr double terminal = 8.056760e-3;          // [m/s], Re = 0.905
constexpr double relaxation = 1.560549e-3;        // rho_p d^2 / (18 mu) [s]
constexpr double approach_1 = 0.6939, approach_2 = 0.9098;  // v / v_t at t = tau, 2 tau (same script)

template <int Dim>
void sedimentation(double approach_tolerance) {
    const auto spec = load_case(Dim == 2 ? "sedimentation_2d/case.toml" : "sedimentation_3d/case.toml");
    grit::sim::Simulation<Dim> sim(spec, in_memory());
    sim.advance_to(relaxation);
    const double v1 = output(sim, "settling_velocity");
    sim.advance_to(2.0 * relaxation);
    const double v2 = output(sim, "settling_velocity");
    sim.advance_to(spec.end_time);
    const double vt = output(sim, "terminal_velocity");
    ::testing::Test::RecordProperty("terminal_velocity", std::to_string(vt));
    EXPECT_NEAR(vt, terminal, 0.03 * terminal) << "the issue's 3 %";
    if (approach_tolerance > 0.0) {
        EXPECT_NEAR(v1 / terminal, approach_1, approach_tolerance) << "at t = tau";
        EXPECT_NEAR(v2 / terminal, approach_2, approach_tolerance) << "at t = 2 tau";
    }
    // The grain stayed clear of the floor and no water was lost.
    EXPECT_EQ(sim.impacts().total(), 0u);
}

// The pressure force on a grain of the water's density at rest in the still column of sedimentation_3d,
// its centre at `height` above the floor, in units of rho_f g V (Archimedes), after 0.5 ms.
double buoyancy_at(double height) {
    auto spec = load_case("sedimentation_3d/case.toml");
    for (auto& m : spec.grain_materials) m.density = 1000.0;
    spec.grains[0].position = {1.0e-3, 1.0e-3, height};
    grit::sim::Simulation<3> sim(spec, in_memory());
    sim.advance_to(5e-4);
    const auto& fields = sim.state().grains->grains().fields();
    const double fz = fields.get<grit::core::Vec<3>>("fluid_force").data()[0][2];
    const double drag = fields.get<grit::core::Vec<3>>("drag_force").data()[0][2];
    const double d = spec.grain_materials[0].diameter;
    return (fz - drag) / (1000.0 * 9.81 * M_PI / 6.0 * d * d * d);
}

}  // namespace

// A grain near a wall feels the same buoyancy as in the open water: the wall particles complete its
// coupling kernel (their Adami pressure continues the water's). 2 d above the floor (its kernel, R_c =
// 5 d, reaches 3 d into the wall) it read 0.68 rho_f g V before, with the wall's share of the kernel
// counted as air; now 1.030, as at 10 d (1.033). Tolerance 5 % of Archimedes' rho_f g V.
TEST(Buoyancy, NearTheFloorAsInOpenWater3D) {
    const double near_floor = buoyancy_at(2.0e-4), open_water = buoyancy_at(1.0e-3);
    RecordProperty("near_floor", std::to_string(near_floor));
    RecordProperty("open_water", std::to_string(open_water));
    EXPECT_NEAR(open_water, 1.0, 0.05);
    EXPECT_NEAR(near_floor, 1.0, 0.05);
    EXPECT_NEAR(near_floor, open_water, 0.02);
}

// 2D: 7.950e-3 m/s at 7.7 tau (-1.3 %). The approach is slower than the grain's equation of motion
// (v(2 tau) / v_t = 0.82 against 0.91) and the velocity does not stay: it falls to 7.3e-3 by 13 tau
// (docs/validation.md, "Sedimentation"); the approach is recorded, not checked.
TEST(Sedimentation, TerminalVelocity2D) { sedimentation<2>(0.0); }
// 3D: 7.949e-3 m/s (-1.3 %); v(tau) / v_t = 0.67, v(2 tau) / v_t = 0.88 (ODE 0.69, 0.91).
TEST(Sedimentation, TerminalVelocityAndApproach3D) { sedimentation<3>(0.05); }

namespace {

// Ergun (1952) at the bed's porosity 0.59929 (discs of d = 1 mm on a square lattice of 1.4 mm), water:
// `python3 scripts/ergun.py` (cases/packed_bed_2d/reference/ergun.txt).
void packed_bed(const std::string& solver) {
    const double ergun[2] = {7.359232e-3, 4.082807e-2};  // [m/s] at rho g = 1e3, 1e4 Pa/m
    const double body_force[2] = {1.0, 10.0};
    for (int k = 0; k < 2; ++k) {
        const std::string gravity = "physics.gravity=[" + std::to_string(body_force[k]) + ", 0.0]";
        const auto spec = load_case("packed_bed_2d/case.toml", {gravity, "fluid.solver=" + solver});
        grit::sim::Simulation<2> sim(spec, in_memory());
        sim.advance_to(spec.end_time);
        const double u = output(sim, "superficial_velocity");
        const double eps = output(sim, "bed_porosity");
        const double gradient = output(sim, "pressure_gradient");
        EXPECT_NEAR(eps, 0.59929, 1e-4) << "the lattice's porosity, 1 - pi / (4 * 1.4^2)";
        // Steady: the bed carries the fluid's weight along the flow, rho_f g.
        EXPECT_NEAR(gradient, 1000.0 * body_force[k], 0.01 * 1000.0 * body_force[k]);
        // The issue asks for 10 %; the bed is uniform, so the coupling reproduces its drag law closely.
        EXPECT_NEAR(u, ergun[k], 0.02 * ergun[k]) << "body force " << body_force[k];
        // The grains did not move.
        const auto& g = sim.grains()->grains();
        for (grit::Index i = 0; i < g.size(); ++i) ASSERT_EQ(grit::core::norm(g.velocity()[i]), 0.0);
    }
}

}  // namespace

// WCSPH: 7.3620e-3 m/s at rho g = 1e3 Pa/m (+0.04 %).
TEST(PackedBed, SuperficialVelocityFollowsErgunAtTwoBodyForces) { packed_bed("wcsph"); }
// ISPH (fluid.solver = "isph"): the grains' reaction in v*, the projection aiming the summation density
// at eps rho0, the pressure's level pinned (no free surface in the periodic bed): 7.3631e-3 and
// 4.0841e-2 m/s (+0.05 %, +0.03 %).
TEST(PackedBed, SuperficialVelocityFollowsErgunWithIsph) { packed_bed("isph"); }
