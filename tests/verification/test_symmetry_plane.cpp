// The symmetry plane x = 0 (jet.symmetric, domain.symmetry; modules/symmetry_plane): the half of a
// symmetric set-up is the whole one. The water jet on the copper (the AWJ case without its grains) run
// on its x >= 0 half gives the whole run's stagnation pressure, crater, plastic strain and, halved, its
// kinetic energy and mass, to round-off (the sums add in another order); the images are mirror images
// of their sources at every step boundary and never reach an output; grains stay on their side.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <string>
#include <vector>

#include "grit/parallel/parallel.hpp"
#include "support/case_fixture.hpp"

namespace {

using grit::Index;
using grit::sim::Simulation;

std::map<std::string, double> values_of(const Simulation<2>& s) {
    std::map<std::string, double> out;
    for (const auto& v : s.output_values()) out[v.name] = v.value;
    return out;
}

// Relative difference, against `scale` where the value itself may be near zero.
double relative(double a, double b, double scale) { return std::abs(a - b) / std::max(std::abs(scale), 1e-300); }

}  // namespace

TEST(SymmetryPlane, HalfWaterJetOnCopperIsTheWholeOne) {
    grit::parallel::set_threads(2);
    // The jet lands at 4 us: the water hammer (1.7 GPa), then the first plastic strain under the jet.
    const std::vector<std::string> no_grains = {"abrasive.start=1.0", "time.end=6e-6"};
    auto half_overrides = no_grains;
    half_overrides.push_back("jet.symmetric=true");
    Simulation<2> whole(grit::testing::load_case("awj_copper_2d/case.toml", no_grains), grit::testing::in_memory());
    Simulation<2> half(grit::testing::load_case("awj_copper_2d/case.toml", half_overrides), grit::testing::in_memory());
    for (const double t : {4e-6, 6e-6}) {
        SCOPED_TRACE(t);
        whole.advance_to(t);
        half.advance_to(t);
        ASSERT_EQ(whole.steps(), half.steps());
        auto w = values_of(whole), h = values_of(half);
        EXPECT_GT(w.at("p_stagnation"), 1e8);
        EXPECT_GT(w.at("max_plastic_strain"), 1e-3);
        // The same to round-off (1e-9 of the value; measured: 1e-15 to 1e-12).
        EXPECT_LT(relative(h.at("p_stagnation"), w.at("p_stagnation"), w.at("p_stagnation")), 1e-9);
        EXPECT_LT(relative(h.at("max_plastic_strain"), w.at("max_plastic_strain"), w.at("max_plastic_strain")), 1e-9);
        EXPECT_LT(relative(h.at("crater_depth"), w.at("crater_depth"), 1e-4), 1e-9);
        EXPECT_EQ(h.at("crater_width"), w.at("crater_width"));
        EXPECT_LT(relative(2.0 * h.at("kinetic_energy"), w.at("kinetic_energy"), w.at("kinetic_energy")), 1e-9);
        EXPECT_LT(relative(2.0 * h.at("mass_total"), w.at("mass_total"), w.at("mass_total")), 1e-12);
        EXPECT_EQ(2.0 * h.at("mass_in"), w.at("mass_in"));
        EXPECT_EQ(2.0 * h.at("particles"), w.at("particles"));
        EXPECT_LT(relative(2.0 * h.at("internal_energy"), w.at("internal_energy"), w.at("internal_energy")), 1e-9);
    }
}

// At a step boundary every image is its source mirrored (position, velocity, stress) and carries the
// source's id as image_id; snapshots and the particle count leave the images out. The grains of the
// half jet stay on their side of the plane (a frictionless wall for them).
TEST(SymmetryPlane, ImagesMirrorTheirSourcesAndStayOutOfOutputs) {
    grit::parallel::set_threads(2);
    Simulation<2> half(grit::testing::load_case("awj_copper_2d/case.toml", {"jet.symmetric=true", "time.end=1.2e-5"}),
                       grit::testing::in_memory());
    half.advance_to(1.2e-5);
    const auto& ps = half.particles();
    const Index images = ps.image_count();
    ASSERT_GT(images, 100);
    std::map<grit::domain::ParticleId, Index> by_id;
    for (Index i = 0; i < ps.size(); ++i)
        if (!ps.is_image(i)) by_id[ps.id()[i]] = i;
    const auto* x = ps.position();
    const auto* v = ps.velocity();
    const auto& tau = ps.fields().get<grit::core::SymTensor3>("deviatoric_stress");
    for (Index i = 0; i < ps.size(); ++i) {
        if (!ps.is_image(i)) {
            EXPECT_GE(x[i][0], 0.0) << "particle " << ps.id()[i] << " is on the mirrored side";
            continue;
        }
        const auto it = by_id.find(grit::particles::SphParticles<2>::image_source(ps.id()[i]));
        ASSERT_NE(it, by_id.end()) << "image without its source";
        const Index s = it->second;
        EXPECT_EQ(x[i][0], -x[s][0]);
        EXPECT_EQ(x[i][1], x[s][1]);
        EXPECT_EQ(v[i][0], -v[s][0]);
        EXPECT_EQ(v[i][1], v[s][1]);
        EXPECT_EQ(tau[i].xy, -tau[s].xy);
        EXPECT_EQ(tau[i].xx, tau[s].xx);
        EXPECT_EQ(ps.pressure()[i], ps.pressure()[s]);
    }
    const auto cloud = ps.snapshot();
    EXPECT_EQ(static_cast<Index>(cloud.points.size() / 3), ps.size() - images);
    for (const auto& value : half.output_values())
        if (value.name == "particles") {
            EXPECT_EQ(value.value, static_cast<double>(ps.size() - images));
        }
    ASSERT_NE(half.grains(), nullptr);
    const auto& g = half.grains()->grains();
    ASSERT_GT(g.size(), 0);
    for (Index k = 0; k < g.size(); ++k) EXPECT_GE(g.position()[k][0], 0.9 * g.radius()[k]) << "grain " << k;
}
