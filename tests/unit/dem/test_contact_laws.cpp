// Contact laws against hand-computed values (python, double precision), Coulomb caps, materials and the
// law names.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "grit/core/error.hpp"
#include "grit/dem/contact_laws.hpp"
#include "grit/dem/grain_integrator.hpp"
#include "grit/dem/grain_material.hpp"
#include "grit/dem/size_distribution.hpp"

using namespace grit::dem;
using grit::core::Vec;

namespace {

// E = 10 MPa, nu = 0.3, mu = 0.5, e = 0.5 for both bodies; R = 10 mm, m = 1 kg each.
PairMaterial test_pair() {
    const GrainMaterial m{"test", 2500.0, 1e7, 0.3, 0.5, 0.5, 0.0};
    return pair_material(m, m);
}
ContactKinematics test_contact() { return {1e-4, 0.1, 0.01, 0.01, 1.0, 1.0}; }

}  // namespace

TEST(ContactLaws, DampingRatioFromRestitution) {
    EXPECT_DOUBLE_EQ(damping_ratio(1.0), 0.0);
    EXPECT_NEAR(damping_ratio(0.5), 0.2154537619662468, 1e-15);
}

// First paper eqs. (2), (10), (11): k_n = E R = 1e5 N/m, k_t = E R nu = 3e4 N/m, m* = 0.5 kg,
// F_n = k_n delta + 2 xi sqrt(m* k_n) v_n = 19.635385155291733 N, d_t = 52.775177998036995 N s/m.
TEST(ContactLaws, LinearSpringDashpotMatchesHandValues) {
    const NormalContact n = LinearSpringDashpot{}.normal(test_contact(), test_pair());
    EXPECT_NEAR(n.force, 19.635385155291733, 1e-12);
    EXPECT_NEAR(n.tangential_stiffness, 3e4, 1e-9);
    EXPECT_NEAR(n.tangential_damping, 52.775177998036995, 1e-11);
}

// A wall is a body of infinite radius and mass: k_n = 2 E R (eq. 10 with R_b -> inf), m* = m.
TEST(ContactLaws, LinearAgainstWallUsesInfiniteRadiusAndMass) {
    ContactKinematics c = test_contact();
    c.radius_b = c.mass_b = std::numeric_limits<double>::infinity();
    const NormalContact n = LinearSpringDashpot{}.normal(c, test_pair());
    EXPECT_NEAR(n.force, 39.270770310583465, 1e-11);
    EXPECT_NEAR(LinearSpringDashpot{}.normal_stiffness(c, test_pair()), 2e5, 1e-9);
}

// Second paper eqs. (11)-(12) with LIGGGHTS' damping: Y* = E / (2 (1 - nu^2)), G* = E / (4 (2 - nu)(1 + nu)),
// R* = 5 mm: F_n = 2.9699128749103814 N, k_t = 6399.156390828485 N/m, gamma_t = 22.25050224451591 N s/m.
TEST(ContactLaws, HertzMindlinMatchesHandValues) {
    const PairMaterial p = test_pair();
    EXPECT_NEAR(p.youngs_effective, 5494505.494505494, 1e-6);
    EXPECT_NEAR(p.shear_effective, 1131221.7194570135, 1e-6);
    const NormalContact n = HertzMindlin{}.normal(test_contact(), p);
    EXPECT_NEAR(n.force, 2.9699128749103814, 1e-13);
    EXPECT_NEAR(n.tangential_stiffness, 6399.156390828485, 1e-9);
    EXPECT_NEAR(n.tangential_damping, 22.25050224451591, 1e-12);
}

TEST(ContactLaws, ElasticContactHasNoDamping) {
    GrainMaterial m{"elastic", 2500.0, 1e7, 0.3, 0.5, 1.0, 0.0};
    const PairMaterial p = pair_material(m, m);
    const ContactKinematics c = test_contact();
    EXPECT_DOUBLE_EQ(LinearSpringDashpot{}.normal(c, p).force, 1e5 * 1e-4);
    EXPECT_DOUBLE_EQ(HertzMindlin{}.normal(c, p).tangential_damping, 0.0);
}

// Eq. (3): below the cap F_t = -k_t delta_t - d_t v_t; above it |F_t| = mu |F_n| along the trial force,
// and the stored elongation gives back exactly the capped force.
TEST(ContactLaws, CoulombCapOfTheLinearLaw) {
    const NormalContact n{10.0, 1000.0, 2.0};
    const Vec<3> vt{{0.1, 0.0, 0.0}};
    const auto small = coulomb_total<3>(Vec<3>{{1e-3, 0.0, 0.0}}, vt, n, 0.5);
    EXPECT_DOUBLE_EQ(small.force[0], -1.0 - 0.2);
    const auto large = coulomb_total<3>(Vec<3>{{0.0, 0.1, 0.0}}, vt, n, 0.5);
    EXPECT_NEAR(grit::core::norm(large.force), 5.0, 1e-12);
    const Vec<3> back = large.history * (-1000.0) - vt * 2.0;
    EXPECT_NEAR(back[0], large.force[0], 1e-12);
    EXPECT_NEAR(back[1], large.force[1], 1e-12);
}

// LIGGGHTS' rule: the cap acts on the spring, the history is shortened to mu |F_n| / k_t, no damping.
TEST(ContactLaws, CoulombCapOfTheHertzLawActsOnTheSpring) {
    const NormalContact n{10.0, 1000.0, 2.0};
    const auto r = coulomb_spring<2>(Vec<2>{{0.02, 0.0}}, Vec<2>{{0.1, 0.0}}, n, 0.5);
    EXPECT_NEAR(r.force[0], -5.0, 1e-12);
    EXPECT_NEAR(r.history[0], 0.005, 1e-15);
    const auto s = coulomb_spring<2>(Vec<2>{{0.001, 0.0}}, Vec<2>{{0.1, 0.0}}, n, 0.5);
    EXPECT_DOUBLE_EQ(s.force[0], -1.0 - 0.2);
}

TEST(ContactLaws, SelectedByName) {
    EXPECT_TRUE(std::holds_alternative<LinearSpringDashpot>(make_contact_law("linear")));
    EXPECT_TRUE(std::holds_alternative<HertzMindlin>(make_contact_law("hertz")));
    EXPECT_EQ(law_name(make_contact_law("hertz")), "hertz");
    EXPECT_THROW(make_contact_law("hooke"), grit::core::InputError);
}

// Table 4 of the first paper.
TEST(GrainMaterials, GarnetOfTable4) {
    const auto g = find_grain_material("garnet");
    ASSERT_TRUE(g.has_value());
    EXPECT_DOUBLE_EQ(g->density, 4120.0);
    EXPECT_DOUBLE_EQ(g->diameter, 0.2e-3);
    EXPECT_DOUBLE_EQ(g->youngs_modulus, 248e9);
    EXPECT_DOUBLE_EQ(g->poisson_ratio, 0.3);
    EXPECT_DOUBLE_EQ(g->friction, 0.3);
    EXPECT_DOUBLE_EQ(g->restitution, 0.6);
    EXPECT_TRUE(find_grain_material("sand").has_value());  // quartz sand, the second paper's loading
    EXPECT_FALSE(find_grain_material("unobtainium").has_value());
}

// Eq. (51) for a garnet grain of Table 4, 3D: m = 1.7258e-8 kg, k_n = E R = 2.48e7 N/m,
// dt = 2 pi / 300 sqrt(m / k_n) = 5.5249e-10 s. (The paper quotes 6.34e-9 s, which its stated data do
// not give; see docs/theory.md.)
TEST(GrainTimeStep, Equation51ForGarnet) {
    EXPECT_NEAR(linear_time_step(garnet(), 0.1e-3), 5.524916e-10, 1e-15);
}

TEST(SizeDistributions, DrawInsideTheirBoundsAndRepeatWithTheSeed) {
    const SizeDistribution fixed = FixedSize{2e-4};
    const SizeDistribution uniform = UniformSize{1e-4, 3e-4};
    const SizeDistribution normal = NormalSize{2e-4, 0.5e-4, 1.5e-4, 2.5e-4};
    std::mt19937_64 rng(42);
    double su = 0.0, sn = 0.0;
    const int n = 20000;
    for (int k = 0; k < n; ++k) {
        EXPECT_EQ(draw_diameter(fixed, rng), 2e-4);
        const double u = draw_diameter(uniform, rng), g = draw_diameter(normal, rng);
        ASSERT_GE(u, 1e-4);
        ASSERT_LE(u, 3e-4);
        ASSERT_GE(g, 1.5e-4);
        ASSERT_LE(g, 2.5e-4);
        su += u;
        sn += g;
    }
    EXPECT_NEAR(su / n, 2e-4, 2e-6);  // standard error 0.4e-6
    EXPECT_NEAR(sn / n, 2e-4, 1e-6);  // symmetric cut-offs keep the mean
    std::mt19937_64 a(7), b(7);
    EXPECT_EQ(draw_diameter(normal, a), draw_diameter(normal, b));
    EXPECT_THROW(validate(UniformSize{3e-4, 1e-4}), grit::core::InputError);
    EXPECT_DOUBLE_EQ(largest_diameter(normal), 2.5e-4);
}
