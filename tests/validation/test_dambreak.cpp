// 2D dam break vs Martin & Moyce (1952), and the 3D dam break vs 2D, at CI resolution.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>

#include "support/case_fixture.hpp"
#include "support/validation_figures.hpp"
#include "support/martin_moyce.hpp"

using grit::testing::in_memory;
using grit::testing::load_case;

namespace {

using grit::testing::FrontPoint;
using grit::testing::martin_moyce;

constexpr double L = 0.2, g = 9.81;

}  // namespace

// Tolerance 10 % on Z = z/L for the data with 1.5 <= T <= 2.5. The earlier points (T < 1.5) carry the
// experiment's gate-release delay: simulations run ahead there (docs/validation.md); they are
// reported and must at least lie ahead of the data by less than 20 %.
TEST(DamBreak, Front2DAgainstMartinMoyce) {
    const auto data = martin_moyce();
    ASSERT_GE(data.size(), 8u);
    grit::sim::Simulation<2> sim(load_case("dambreak_2d/case.toml", {"numerics.particle_spacing=0.005"}), in_memory());
    const double scale = std::sqrt(2.0 * g / L);
    std::vector<FrontPoint> sorted = data;
    std::sort(sorted.begin(), sorted.end(), [](auto a, auto b) { return a.T < b.T; });
    int checked = 0;
    double largest = 0.0;  // the largest error for 1.5 <= T <= 2.5, signed
    for (const auto& p : sorted) {
        if (p.T > 2.5) continue;
        sim.advance_to(p.T / scale);
        const double Z = sim.probe("front") / L;
        const double error = (Z - p.Z) / p.Z;
        std::printf("T = %.3f  Z_exp = %.3f  Z_sim = %.3f  error = %+.1f %%\n", p.T, p.Z, Z, 100.0 * error);
        if (p.T >= 1.5) {
            EXPECT_LT(std::abs(error), 0.10) << "T = " << p.T;
            if (std::abs(error) > std::abs(largest)) largest = error;
            ++checked;
        } else {
            EXPECT_GT(error, 0.0) << "T = " << p.T;
            EXPECT_LT(error, 0.20) << "T = " << p.T;
        }
    }
    EXPECT_GE(checked, 3);
    grit::testing::record_figure({"largest front error, 1.5 <= T <= 2.5, dx = 5 mm", 100.0 * largest, "%", "10 %",
                                  "Martin & Moyce (1952)"});
}

// The 3D dam break (cases/dambreak_3d) against the 2D case at the same spacing (fronts within 10 %), and
// the same column in a tank of wall particles laid along a closed STL box (cases/dambreak_mesh_3d) against
// the particle tank (fronts within 5 %, issue 13). One test, so CI runs the 3D particle tank once. To
// 0.25 s the two tanks' fronts agree to 0.1 mm (docs/validation.md); the STL tank stops at 0.1 s to
// spare CI.
TEST(DamBreak, Front3DAgreesWith2DAndWithAnStlTank) {
    grit::sim::Simulation<2> two(load_case("dambreak_2d/case.toml", {"numerics.particle_spacing=0.01"}), in_memory());
    grit::sim::Simulation<3> three(load_case("dambreak_3d/case.toml"), in_memory());
    grit::sim::Simulation<3> mesh(load_case("dambreak_mesh_3d/case.toml"), in_memory());
    for (double t : {0.05, 0.10}) {
        three.advance_to(t);
        mesh.advance_to(t);
        const double a = three.probe("front"), b = mesh.probe("front");
        std::printf("t = %.2f  front particle tank = %.4f m  STL tank = %.4f m\n", t, a, b);
        EXPECT_NEAR(b, a, 0.05 * a) << "t = " << t;
    }
    for (double t : {0.10, 0.15, 0.20, 0.25}) {
        two.advance_to(t);
        three.advance_to(t);
        const double f2 = two.probe("front"), f3 = three.probe("front");
        std::printf("t = %.2f  front 2D = %.4f m  3D = %.4f m\n", t, f2, f3);
        EXPECT_NEAR(f3, f2, 0.10 * f2) << "t = " << t;
    }
}
