// Validation of the unresolved fluid-grain coupling (eqs. 20-23, 42-50) on the cases of cases/:
//  - sedimentation_2d / sedimentation_3d: one glass grain settling in water reaches the terminal velocity
//    the Gidaspow law gives a lone grain (eps = 1), and (3D) approaches it as the grain's equation of
//    motion does;
//  - packed_bed_2d: a body force drives water through a lattice of fixed grains; the superficial
//    velocity against Ergun's equation at two body forces;
//  - a grain of the water's density at rest near the floor feels Archimedes' buoyancy, as in open water;
//  - a grain moving along the surface of an SPH solid (an AWJ's target) or a wall is wholly immersed:
//    the same drag as in open water.
// References: scripts/terminal_velocity.py and scripts/ergun.py (reference/ of each case).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "support/case_fixture.hpp"
#include "support/validation_figures.hpp"
#include "support/case_text.hpp"

using grit::testing::in_memory;
using grit::testing::load_case;
using grit::testing::read_case_text;
using grit::testing::replaced;

namespace {

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
    const double v1 = grit::testing::output_value(sim, "settling_velocity");
    sim.advance_to(2.0 * relaxation);
    const double v2 = grit::testing::output_value(sim, "settling_velocity");
    sim.advance_to(spec.end_time);
    const double vt = grit::testing::output_value(sim, "terminal_velocity");
    ::testing::Test::RecordProperty("terminal_velocity", std::to_string(vt));
    EXPECT_NEAR(vt, terminal, 0.03 * terminal) << "the issue's 3 %";
    grit::testing::record_figure({"terminal velocity", 100.0 * (vt / terminal - 1.0), "%", "3 %",
                                  "Wen-Yu drag, scripts/terminal_velocity.py"});
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

namespace {

// The drag force on a grain of the water's density moving at 0.01 m/s along x through still water
// (2D, no gravity), its centre `height` above y = 0, after 1e-5 s (a few steps): `floor` is "solid"
// (a soft elastic block, y < 0), "wall" (wall particles) or "none" (water below y = 0 too).
double drag_along_x(double height, const std::string& floor) {
    std::string text = R"([simulation]
dimension = 2
[time]
end = 1.0e-5
[output]
interval = 1.0e-5
[numerics]
particle_spacing = 2.0e-4
[physics]
gravity = [0.0, 0.0]
[materials.water]
base = "water_tait"
sound_speed = 20.0
dynamic_viscosity = 8.9e-4
artificial_viscosity_alpha = 0.0
artificial_viscosity_beta = 0.0
[materials.gel]
eos = "tait"
gamma = 1.0
reference_density = 1000.0
sound_speed = 20.0
model = "elastic"
shear_modulus = 1.0e5
[grain_materials.light]
density = 1000.0
youngs_modulus = 1.0e6
poisson_ratio = 0.3
friction = 0.3
restitution = 0.5
diameter = 1.0e-4
[[fluid]]
shape = "box"
min = [0.0, 0.0]
max = [4.0e-3, 4.0e-3]
material = "water"
[[grains]]
material = "light"
position = [2.0e-3, HEIGHT]
velocity = [0.01, 0.0]
[coupling]
radius = 5.0
drag = "gidaspow"
[domain]
min = [-1.0e-3, -2.0e-3]
max = [5.0e-3, 6.0e-3]
)";
    text = replaced(text, "HEIGHT", std::to_string(height));
    const std::string below = "min = [0.0, -1.2e-3]\nmax = [4.0e-3, 0.0]\n";
    if (floor == "none") text = replaced(text, "min = [0.0, 0.0]", "min = [0.0, -1.2e-3]");
    if (floor == "solid") text += "[[solid]]\nshape = \"box\"\n" + below + "material = \"gel\"\n";
    if (floor == "wall") text += "[[wall]]\nshape = \"box\"\n" + below;
    grit::sim::Simulation<2> sim(read_case_text(text, "immersed_" + floor), in_memory());
    sim.advance_to(1.0e-5);
    return sim.state().grains->grains().fields().get<grit::core::Vec<2>>("drag_force").data()[0][0];
}

}  // namespace

// A grain 2 d above an SPH solid (its coupling kernel, R_c = 5 d, reaches 3 d into it) is wholly
// immersed: the solid particles complete its kernel's immersed fraction as wall particles do, so it
// takes the drag it would take in open water (and near a wall): 1.004 of it. With the water alone
// counted it took the water's share of its kernel, 0.946. Tolerance 2 % of the open-water drag.
TEST(Immersion, GrainAtASolidSurfaceTakesTheOpenWaterDrag2D) {
    const double open_water = drag_along_x(2.0e-4, "none");
    const double near_solid = drag_along_x(2.0e-4, "solid");
    const double near_wall = drag_along_x(2.0e-4, "wall");
    std::printf("drag along x: open water %.4g N/m, 2 d above a solid %.4g (%.3f), above a wall %.4g (%.3f)\n",
                open_water, near_solid, near_solid / open_water, near_wall, near_wall / open_water);
    ASSERT_LT(open_water, 0.0);  // against the grain's motion
    EXPECT_NEAR(near_solid / open_water, 1.0, 0.02);
    EXPECT_NEAR(near_wall / open_water, 1.0, 0.02);
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
        const double u = grit::testing::output_value(sim, "superficial_velocity");
        const double eps = grit::testing::output_value(sim, "bed_porosity");
        const double gradient = grit::testing::output_value(sim, "pressure_gradient");
        EXPECT_NEAR(eps, 0.59929, 1e-4) << "the lattice's porosity, 1 - pi / (4 * 1.4^2)";
        // Steady: the bed carries the fluid's weight along the flow, rho_f g.
        EXPECT_NEAR(gradient, 1000.0 * body_force[k], 0.01 * 1000.0 * body_force[k]);
        // The issue asks for 10 %; the bed is uniform, so the coupling reproduces its drag law closely.
        EXPECT_NEAR(u, ergun[k], 0.02 * ergun[k]) << "body force " << body_force[k];
        grit::testing::record_figure({"superficial velocity at rho g = " + std::to_string(static_cast<int>(1000.0 * body_force[k])) +
                                          " Pa/m",
                                      100.0 * (u / ergun[k] - 1.0), "%", "2 %", "Ergun (1952), scripts/ergun.py"});
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
