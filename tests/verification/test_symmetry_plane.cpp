// The symmetry plane x = 0 (jet.symmetric, domain.symmetry; modules/symmetry_plane): the half of a
// symmetric set-up is the whole one. The water jet on the copper (the AWJ case without its grains) run
// on its x >= 0 half gives the whole run's stagnation pressure, crater, plastic strain and, halved, its
// kinetic energy and mass, to round-off (the sums add in another order); the images are mirror images
// of their sources at every step boundary and never reach an output; grains stay on their side. Grains on
// a mesh wall across the plane wear it as the whole set-up's grains do.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "grit/core/error.hpp"
#include "grit/modules/mesh_wear.hpp"
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

// The message of the InputError that setting up the case `spec()` makes raise ("" if none).
template <int Dim>
std::string refusal(const std::function<grit::io::CaseSpec()>& spec) {
    try {
        grit::sim::Simulation<Dim> sim(spec(), grit::testing::in_memory());
    } catch (const grit::core::InputError& e) {
        return e.what();
    }
    return "";
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

namespace {

// A plate 2 cells x 2 cells at z = 0 of square cells `cell` [m] wide, two triangles each (normals up), each
// cell at x < 0 the mirror image of its twin (the diagonals mirrored), as ASCII STL.
std::string symmetric_plate_stl(int cells = 4, double cell = 1e-3) {
    std::string out = "solid plate\n";
    auto facet = [&](std::array<std::array<double, 2>, 3> c) {
        out += "facet normal 0 0 1\nouter loop\n";
        for (const auto& p : c) out += fmt::format("vertex {:.9g} {:.9g} 0\n", p[0], p[1]);
        out += "endloop\nendfacet\n";
    };
    for (int i = -cells; i < cells; ++i)
        for (int j = -cells; j < cells; ++j) {
            const double x0 = cell * i, x1 = x0 + cell, y0 = cell * j, y1 = y0 + cell;
            if (i >= 0) {  // diagonal (x0, y0) - (x1, y1)
                facet({{{x0, y0}, {x1, y0}, {x1, y1}}});
                facet({{{x0, y0}, {x1, y1}, {x0, y1}}});
            } else {  // diagonal (x1, y0) - (x0, y1): the mirror image of the twin's
                facet({{{x1, y0}, {x0, y1}, {x0, y0}}});
                facet({{{x1, y0}, {x1, y1}, {x0, y1}}});
            }
        }
    return out + "endsolid plate\n";
}

// Grains striking the plate: a twin pair (x = +-1 mm, flying apart at 30 degrees from the plate) and one
// on the plane itself, flying along it; the half has the x >= 0 grain of the pair and the one on the plane.
std::string plate_case(bool half) {
    std::string text = R"(
[simulation]
title = "grains on a plate across a symmetry plane"
dimension = 3
[time]
end = 3.0e-4
[output]
interval = 1.0e-4
[physics]
gravity = [0.0, 0.0, -9.81]
[dem]
contact_law = "hertz"
[[grains]]
material = "sand"
arrangement = "single"
position = [1.0e-3, 0.5e-3, 1.5e-3]
diameter = 1.0e-3
velocity = [17.3205, 2.0, -10.0]
[[grains]]
material = "sand"
arrangement = "single"
position = [0.0, -2.0e-3, 1.5e-3]
diameter = 1.0e-3
velocity = [0.0, 5.0, -10.0]
[[mesh]]
name = "plate"
file = "grit_test_symmetric_plate.stl"
material = "steel"
wear_model = "finnie"
[domain]
min = [-0.03, -0.03, -0.01]
max = [0.03, 0.03, 0.03]
)";
    if (half) return text + "symmetry = [\"x\"]\n";
    return text + R"(
[[grains]]
material = "sand"
arrangement = "single"
position = [-1.0e-3, 0.5e-3, 1.5e-3]
diameter = 1.0e-3
velocity = [-17.3205, 2.0, -10.0]
)";
}

}  // namespace

// The half books the wear its grains cause, and a triangle's wear is its own with its mirror image's,
// except for the grain on the plane (no twin), booked once: triangle by triangle the whole set-up's wear
// map, to round-off (the twins' contacts are mirrored computations), and the same totals.
TEST(SymmetryPlane, GrainsWearAMeshAcrossThePlaneAsTheWholeSetUpDoes) {
    std::ofstream(std::filesystem::temp_directory_path() / "grit_test_symmetric_plate.stl") << symmetric_plate_stl();
    auto run = [](bool half) {
        auto sim = std::make_unique<grit::sim::Simulation<3>>(
            grit::testing::read_case_text(plate_case(half), half ? "plate_half" : "plate_whole"),
            grit::testing::in_memory());
        sim->advance_to(3.0e-4);
        return sim;
    };
    const auto whole = run(false), half = run(true);
    std::filesystem::remove(std::filesystem::temp_directory_path() / "grit_test_symmetric_plate.stl");
    const auto w = whole->module<grit::modules::MeshWearModule<3>>()->wear_map();
    const auto h = half->module<grit::modules::MeshWearModule<3>>()->wear_map();
    ASSERT_EQ(w.size(), 128u);
    ASSERT_EQ(h.size(), w.size());
    EXPECT_EQ(whole->impacts().total(), 3u);
    EXPECT_EQ(half->impacts().total(), 2u);  // the log holds the half's grains' impacts
    double largest = 0.0;
    int struck = 0;
    for (std::size_t t = 0; t < w.size(); ++t) {
        largest = std::max(largest, w.mass(t));
        struck += w.impacts(t) > 0;
    }
    ASSERT_GT(largest, 0.0);
    EXPECT_GE(struck, 3);
    double differs = 0.0;
    for (std::size_t t = 0; t < w.size(); ++t) differs = std::max(differs, std::abs(h.mass(t) - w.mass(t)));
    std::printf("mesh across the plane: %d triangles struck, half against whole within %.2g of the largest wear\n",
                struck, differs / largest);
    for (std::size_t t = 0; t < w.size(); ++t) {
        EXPECT_NEAR(h.mass(t), w.mass(t), 1e-9 * largest) << "triangle " << t;
        EXPECT_EQ(h.impacts(t), w.impacts(t)) << "triangle " << t;
        EXPECT_NEAR(h.mean_angle(t), w.mean_angle(t), 1e-9 * 90.0) << "triangle " << t;
    }
    EXPECT_NEAR(grit::testing::output_value(*half, "wear_mass_total"),
                grit::testing::output_value(*whole, "wear_mass_total"), 1e-9 * largest);
}

// A mesh that reaches x < 0 must be symmetric about the plane: the plate shifted 0.5 mm is refused,
// naming the mesh and a triangle without its mirror image; so is a mesh that moves across the plane.
TEST(SymmetryPlane, MeshNotSymmetricAboutThePlaneIsRefused) {
    std::ofstream(std::filesystem::temp_directory_path() / "grit_test_symmetric_plate.stl") << symmetric_plate_stl();
    auto text = plate_case(true);
    text.replace(text.find("wear_model = \"finnie\""), 0, "translate = [0.5e-3, 0.0, 0.0]\n");
    const std::string what = refusal<3>([&] { return grit::testing::read_case_text(text, "plate_shifted"); });
    EXPECT_NE(what.find("mesh 'plate'"), std::string::npos) << what;
    EXPECT_NE(what.find("not symmetric about the plane x = 0"), std::string::npos) << what;
    EXPECT_NE(what.find("no mirror image"), std::string::npos) << what;
    // A symmetric mesh moving across the plane is refused; turning about an axis along x it is its own
    // mirror image.
    for (const auto& [motion, refused] : std::vector<std::pair<std::string, bool>>{
             {"velocity = [1.0, 0.0, 0.0]\n", true},
             {"angular_velocity = [0.0, 0.0, 10.0]\n", true},
             {"angular_velocity = [10.0, 0.0, 0.0]\ncentre = [0.002, 0.0, 0.0]\n", false}}) {
        SCOPED_TRACE(motion);
        auto moving = plate_case(true);
        moving.replace(moving.find("wear_model = \"finnie\""), 0, motion);
        const std::string moved = refusal<3>([&] { return grit::testing::read_case_text(moving, "plate_moving"); });
        EXPECT_EQ(!moved.empty(), refused) << moved;
        if (refused) {
            EXPECT_NE(moved.find("moves across the symmetry plane"), std::string::npos) << moved;
        }
    }
    std::filesystem::remove(std::filesystem::temp_directory_path() / "grit_test_symmetric_plate.stl");
}

// An [[inlet]] whose section crosses the plane emits its x > 0 half: the water jet on a rigid wall
// (jet_on_wall_2d, the inlet centred on x = 0) run on its half gives the whole run's stagnation pressure
// and, halved, its mass and kinetic energy. Before, the whole section emitted into the half and its x < 0
// particles were reflected onto the others: twice the water, silently.
TEST(SymmetryPlane, InletAcrossThePlaneEmitsItsHalf) {
    grit::parallel::set_threads(2);
    Simulation<2> whole(grit::testing::load_case("jet_on_wall_2d/case.toml"), grit::testing::in_memory());
    Simulation<2> half(grit::testing::load_case("jet_on_wall_2d/case.toml",
                                                {"domain.symmetry=[\"x\"]", "wall[0].min=[0.0, -1.5e-4]"}),
                       grit::testing::in_memory());
    for (const double t : {1.2e-5, 1.6e-5}) {
        SCOPED_TRACE(t);
        whole.advance_to(t);
        half.advance_to(t);
        const auto w = values_of(whole), h = values_of(half);
        EXPECT_GT(w.at("p_stagnation"), 1e7);
        EXPECT_EQ(2.0 * h.at("mass_in"), w.at("mass_in"));
        EXPECT_LT(relative(h.at("p_stagnation"), w.at("p_stagnation"), w.at("p_stagnation")), 1e-9);
        EXPECT_LT(relative(2.0 * h.at("kinetic_energy"), w.at("kinetic_energy"), w.at("kinetic_energy")), 1e-9);
    }
}

// An inlet across the plane must be centred on it and aimed along it, and hold an even number of
// particle columns (an odd one puts a column on the plane).
TEST(SymmetryPlane, InletAcrossThePlaneMustBeSymmetricAboutIt) {
    const std::vector<std::string> half = {"domain.symmetry=[\"x\"]", "wall[0].min=[0.0, -1.5e-4]"};
    auto error_of = [&](std::vector<std::string> overrides) {
        overrides.insert(overrides.begin(), half.begin(), half.end());
        return refusal<2>([&] { return grit::testing::load_case("jet_on_wall_2d/case.toml", overrides); });
    };
    const std::string off = error_of({"inlet[0].position=[2.0e-4, 2.0e-3]"});
    EXPECT_NE(off.find("key 'inlet[0].position'"), std::string::npos) << off;
    EXPECT_NE(off.find("centred on the plane x = 0"), std::string::npos) << off;
    const std::string slanted = error_of({"inlet[0].direction=[0.1, -1.0]"});
    EXPECT_NE(slanted.find("aimed along it"), std::string::npos) << slanted;
    const std::string odd = error_of({"inlet[0].diameter=0.95e-3"});
    EXPECT_NE(odd.find("key 'inlet[0].diameter'"), std::string::npos) << odd;
    EXPECT_NE(odd.find("19 particle columns"), std::string::npos) << odd;
}

namespace {

// Grains fed over a box symmetric about x = 0 (6 mm either side), with the plane or without.
std::string feed_case(bool half, const std::string& extra = "") {
    return std::string(R"(
[simulation]
title = "a grain feed across a symmetry plane"
dimension = 3
[time]
end = 1.0e-3
[output]
interval = 1.0e-3
[physics]
gravity = [0.0, 0.0, -9.81]
[dem]
contact_law = "hertz"
[[grain_feed]]
material = "sand"
diameter = 1.0e-3
min = [-0.006, -0.006, 0.010]
max = [0.006, 0.006, 0.026]
velocity = [0.0, 0.0, -20.0]
mass_flow_rate = 0.05
interval = 1.0e-4
seed = 3
)") + extra + R"(
[domain]
min = [-0.03, -0.03, -0.03]
max = [0.03, 0.03, 0.03]
)" + (half ? "symmetry = [\"x\"]\n" : "");
}

}  // namespace

// A grain feed whose box is symmetric about the plane feeds the box's x >= 0 half at half the rate (the
// grains the whole feed puts on the x < 0 side are the twins'); one that is not symmetric is refused, and
// so is a grain laid at x < 0.
TEST(SymmetryPlane, GrainFeedAcrossThePlaneFeedsItsHalf) {
    auto run = [](const std::string& text, const std::string& name) {
        Simulation<3> sim(grit::testing::read_case_text(text, name), grit::testing::in_memory());
        sim.advance_to(1.0e-3);
        return std::pair{grit::testing::output_value(sim, "grains_fed"), sim.grains()->grains().size()};
    };
    const auto [whole_fed, whole_grains] = run(feed_case(false), "feed_whole");
    const auto [half_fed, half_grains] = run(feed_case(true), "feed_half");
    std::printf("grain feed: the whole fed %g grains, the half %g\n", whole_fed, half_fed);
    EXPECT_GT(whole_fed, 15.0);
    EXPECT_NEAR(2.0 * half_fed, whole_fed, 2.0);  // each insertion rounds its carried fraction
    EXPECT_EQ(static_cast<double>(half_grains), half_fed);
    auto error_of = [](const std::string& text) {
        return refusal<3>([&] { return grit::testing::read_case_text(text, "feed_refused"); });
    };
    std::string shifted = feed_case(true);
    shifted.replace(shifted.find("max = [0.006, 0.006, 0.026]"), 27, "max = [0.008, 0.006, 0.026]");
    const std::string asymmetric = error_of(shifted);
    EXPECT_NE(asymmetric.find("key 'grain_feed[0].min'"), std::string::npos) << asymmetric;
    EXPECT_NE(asymmetric.find("symmetric about the plane"), std::string::npos) << asymmetric;
    const std::string odd = error_of(feed_case(true, "count = 7\n"));
    EXPECT_NE(odd.find("key 'grain_feed[0].count' = 7"), std::string::npos) << odd;
    const std::string laid = error_of(feed_case(true, R"(
[[grains]]
material = "sand"
arrangement = "single"
position = [-1.0e-3, 0.0, 0.0]
diameter = 1.0e-3
)"));
    EXPECT_NE(laid.find("starts at x = -0.001 m, on the mirrored side"), std::string::npos) << laid;
}

// A wall laid on a mesh across the plane lays its x >= 0 half, and a thin wall's sides hold there: the
// water jet at 200 m/s on a thin plate (jet_on_thin_plate_3d, its plate made symmetric: 8 x 8 cells of
// 1.5 mm, mirrored diagonals) run on its half puts no water through the plate (the lowest water above
// -0.5 spacings, as the whole run's test) and gives the whole run's stagnation pressure, and half its mass.
TEST(SymmetryPlane, ThinMeshWallAcrossThePlaneLaysItsHalf) {
    grit::parallel::set_threads(2);
    const auto plate = std::filesystem::temp_directory_path() / "grit_test_symmetric_thin_plate.stl";
    std::ofstream(plate) << symmetric_plate_stl(4, 1.5e-3);
    const std::vector<std::string> whole_set = {"wall[0].file=\"" + plate.string() + "\"", "wall[0].thin=true",
                                                "time.end=2.0e-5"};
    auto half_set = whole_set;
    half_set.push_back("domain.symmetry=[\"x\"]");
    grit::sim::Simulation<3> whole(grit::testing::load_case("jet_on_thin_plate_3d/case.toml", whole_set),
                                   grit::testing::in_memory());
    grit::sim::Simulation<3> half(grit::testing::load_case("jet_on_thin_plate_3d/case.toml", half_set),
                                  grit::testing::in_memory());
    std::filesystem::remove(plate);
    const double dx = half.spec().particle_spacing;
    double lowest = 1.0;
    half.advance_to(2.0e-5, [&] {
        const auto& ps = half.particles();
        for (Index i = 0; i < ps.size(); ++i)
            if (ps.phase()[i] == 0) lowest = std::min(lowest, ps.position()[i][2]);
    });
    whole.advance_to(2.0e-5);
    const double p_whole = grit::testing::output_value(whole, "p_stagnation");
    const double p_half = grit::testing::output_value(half, "p_stagnation");
    std::printf("thin plate across the plane: lowest water %.2f spacings; stagnation pressure %.4g Pa (whole %.4g, "
                "%+.2g relative)\n",
                lowest / dx, p_half, p_whole, (p_half - p_whole) / p_whole);
    EXPECT_GT(lowest, -0.5 * dx);
    EXPECT_GT(p_whole, 1e7);
    EXPECT_LT(std::abs(p_half - p_whole) / p_whole, 1e-9);
    EXPECT_EQ(2.0 * grit::testing::output_value(half, "mass_in"), grit::testing::output_value(whole, "mass_in"));
}

// A jet with sand on a mesh wall, on its half: the Pelton bucket (cases/pelton_jet_3d/half.toml: the bucket
// turned so that its splitter lies in x = 0). Without grains the half's water is the whole's (the same case
// with domain.symmetry = []); with them it runs, feeds the half's sand, keeps it on its side (a grain within
// its radius of the plane straddles it) and books wear on the bucket.
TEST(SymmetryPlane, PeltonBucketOnItsHalf) {
    grit::parallel::set_threads(2);
    const std::vector<std::string> water = {"time.end=3e-3", "grain_feed[0].start=1.0"};
    auto whole_set = water;
    whole_set.push_back("domain.symmetry=[]");
    grit::sim::Simulation<3> whole(grit::testing::load_case("pelton_jet_3d/half.toml", whole_set),
                                   grit::testing::in_memory());
    grit::sim::Simulation<3> half(grit::testing::load_case("pelton_jet_3d/half.toml", water), grit::testing::in_memory());
    whole.advance_to(3e-3);
    half.advance_to(3e-3);
    const double ke_whole = grit::testing::output_value(whole, "kinetic_energy");
    const double ke_half = grit::testing::output_value(half, "kinetic_energy");
    std::printf("Pelton bucket, 3 ms of water: kinetic energy %.10g, twice the half's %+.2g relative\n", ke_whole,
                (2.0 * ke_half - ke_whole) / ke_whole);
    EXPECT_LT(std::abs(2.0 * ke_half - ke_whole) / ke_whole, 1e-9);
    EXPECT_EQ(2.0 * grit::testing::output_value(half, "mass_in"), grit::testing::output_value(whole, "mass_in"));

    grit::sim::Simulation<3> sand(grit::testing::load_case("pelton_jet_3d/half.toml", {"time.end=3e-3"}),
                                  grit::testing::in_memory());
    sand.advance_to(3e-3);
    const auto& g = sand.grains()->grains();
    ASSERT_GT(g.size(), 10);
    for (Index k = 0; k < g.size(); ++k) EXPECT_GE(g.position()[k][0], 0.0) << "grain " << k;
    EXPECT_GT(sand.impacts().total(), 0u);
    EXPECT_GT(grit::testing::output_value(sand, "wear_mass_total"), 0.0);
}
