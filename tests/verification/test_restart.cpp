// Checkpoint and restart: k steps, a checkpoint, a fresh Simulation loading it and N - k more steps give
// the same state, bit for bit, as N steps straight -- for every shipped case (inlets, outlets, clamps,
// grains with contact history, Johnson-Cook and JH-2 solids with damage and erosion). Also: what a
// checkpoint that does not fit the case is told.
#include <gtest/gtest.h>
#include <hdf5.h>

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <memory>

#include "grit/core/error.hpp"
#include "grit/parallel/parallel.hpp"
#include "support/case_fixture.hpp"

namespace {

namespace fs = std::filesystem;
using grit::sim::Simulation;
using grit::testing::all_cases;

fs::path scratch_file(const std::string& name) {
    const fs::path dir = fs::temp_directory_path() / "grit_restart_tests";
    fs::create_directories(dir);
    return dir / name;
}

// Every field of two particle sets, bit for bit.
void expect_same_fields(const grit::particles::FieldRegistry& a, const grit::particles::FieldRegistry& b,
                        const std::string& what) {
    ASSERT_EQ(a.size(), b.size()) << what;
    const auto fa = a.all(), fb = b.all();
    ASSERT_EQ(fa.size(), fb.size()) << what;
    for (std::size_t k = 0; k < fa.size(); ++k) {
        ASSERT_EQ(fa[k]->name(), fb[k]->name()) << what;
        EXPECT_TRUE(fa[k]->bytes() == fb[k]->bytes()) << what << ": field " << fa[k]->name() << " differs";
    }
}

template <int Dim>
void expect_same_state(Simulation<Dim>& a, Simulation<Dim>& b) {
    EXPECT_EQ(a.time(), b.time());
    EXPECT_EQ(a.steps(), b.steps());
    EXPECT_EQ(a.time_step(), b.time_step());
    EXPECT_EQ(a.mass_in(), b.mass_in());
    EXPECT_EQ(a.mass_out(), b.mass_out());
    EXPECT_EQ(a.eroded_mass(), b.eroded_mass());
    expect_same_fields(a.particles().fields(), b.particles().fields(), "SPH particles");
    ASSERT_EQ(a.grains() != nullptr, b.grains() != nullptr);
    if (a.grains()) expect_same_fields(a.grains()->grains().fields(), b.grains()->grains().fields(), "grains");
    EXPECT_EQ(a.impacts().total(), b.impacts().total());
    const auto va = a.output_values(), vb = b.output_values();
    ASSERT_EQ(va.size(), vb.size());
    for (std::size_t k = 0; k < va.size(); ++k)
        if (!(std::isnan(va[k].value) && std::isnan(vb[k].value))) {
            EXPECT_EQ(va[k].value, vb[k].value) << va[k].name;
        }
}

// To time `target`, or with `steps`, to step `target` counted from the primed start.
template <int Dim>
void advance(Simulation<Dim>& s, double target, bool steps) {
    if (!steps) return s.advance_to(target);
    s.advance_to(0.0);
    while (s.steps() < static_cast<long>(target)) s.step();
}

// Straight to `end`, writing a checkpoint at `middle` on the way, against a new Simulation loading that
// checkpoint and going on to `end`. With steps > 0, `middle` and `end` count steps from the primed
// start instead of times. Writing a checkpoint does not change the run it is taken from (the writing
// is const, Simulation::write_checkpoint_file); with `also_unsaved`, a third run that writes none checks it.
template <int Dim>
void check_restart(const grit::io::CaseSpec& spec, double middle, double end, bool steps,
                   const std::function<void(Simulation<Dim>&)>& at_middle = {}, bool also_unsaved = false) {
    const fs::path file = scratch_file(spec.name + ".h5");
    Simulation<Dim> straight(spec, grit::testing::in_memory());
    advance(straight, middle, steps);
    if (at_middle) at_middle(straight);
    straight.save_checkpoint(file);
    advance(straight, end, steps);
    Simulation<Dim> second(spec, grit::testing::in_memory());
    second.load_checkpoint(file);
    advance(second, end, steps);
    expect_same_state(straight, second);
    fs::remove(file);
    if (also_unsaved) {
        Simulation<Dim> unsaved(spec, grit::testing::in_memory());
        advance(unsaved, middle, steps);  // a step lands on `middle` as in the others
        advance(unsaved, end, steps);
        expect_same_state(unsaved, straight);
    }
}

}  // namespace

TEST(Restart, EveryCaseContinuesBitForBit) {
    grit::parallel::set_threads(2);
    const auto cases = all_cases();
    ASSERT_GE(cases.size(), 10u);
    for (const auto& path : cases) {
        SCOPED_TRACE(path.string());
        const auto spec = grit::io::read_case(path);
        if (spec.dimension == 2)
            check_restart<2>(spec, 25, 50, true);
        else
            check_restart<3>(spec, 15, 30, true);
    }
}

// The demo mid-run: the jet on the copper, garnet grains in penalty contact with it and logged impacts,
// Johnson-Cook damage and eroded particles, clamps and outlets all active at the checkpoint.
TEST(Restart, DemoMidRunContinuesBitForBit) {
    grit::parallel::set_threads(2);
    const auto spec = grit::io::read_case(fs::path(GRIT_SOURCE_DIR) / "cases" / "demo.toml", {"time.end=1.6e-5", "output.interval=1e-6"});
    check_restart<2>(spec, 1.1e-5, 1.6e-5, false);
}

// A checkpoint taken just after outlets or erosion removed particles: the neighbour lists were compacted,
// not rebuilt (or are still to be compacted), which a build from the saved positions would not reproduce.
TEST(Restart, CompactedNeighbourListsContinueBitForBit) {
    grit::parallel::set_threads(2);
    const auto spec = grit::io::read_case(fs::path(GRIT_SOURCE_DIR) / "cases" / "demo.toml", {"time.end=2e-5", "output.interval=1e-6"});
    long middle = -1;
    {
        Simulation<2> probe(spec, grit::testing::in_memory());
        probe.advance_to(0.0);
        const auto& neighbors = probe.state().neighbors;
        while (middle < 0 && probe.time() < 1.5e-5) {
            const long builds = neighbors.builds(), compactions = neighbors.compactions();
            probe.step();
            if (neighbors.compactions() > compactions && neighbors.builds() == builds) middle = probe.steps();
        }
    }
    ASSERT_GT(middle, 0) << "no step of the demo compacted its lists";
    check_restart<2>(spec, static_cast<double>(middle), static_cast<double>(middle + 60), true);
}

// JH-2 rock under the jet: cracks, bulking pressure and detached fragments at the checkpoint. Also a
// run that writes no checkpoint: writing one on the way changes nothing.
TEST(Restart, BrittleRockMidRunContinuesBitForBit) {
    grit::parallel::set_threads(2);
    const auto spec = grit::testing::load_case("waterjet_sandstone_2d/case.toml", {"time.end=6e-6"});
    check_restart<2>(spec, 4e-6, 6e-6, false, {}, true);
}

// Grains in a settled bed: grain-grain contacts with tangential (friction) history across the
// checkpoint, periodic axes, plane walls.
TEST(Restart, SettlingGrainsWithContactHistoryContinueBitForBit) {
    grit::parallel::set_threads(2);
    const auto spec = grit::testing::load_case("dem_settling_3d/case.toml", {"time.end=0.03"});
    check_restart<3>(spec, 0.02, 0.021, false, [](Simulation<3>& s) {
        EXPECT_GT(s.grains()->contact_history().active_pairs(), 100u) << "the bed has not formed at the checkpoint";
    });
}

// Grains settling on an STL mesh floor: mesh contacts with their tangential histories (grain fields) and
// the per-triangle wear map (LIGGGHTS' form, booked at every contact step) across the checkpoint.
TEST(Restart, GrainsOnAMeshWallWithWearContinueBitForBit) {
    grit::parallel::set_threads(2);
    const auto spec = grit::testing::settling_on_mesh_case("finnie_liggghts", {"time.end=0.03"});
    check_restart<3>(spec, 0.02, 0.022, false, [](Simulation<3>& s) {
        const auto* walls = s.grains()->meshes();
        int touching = 0;
        for (grit::Index i = 0; i < s.grains()->grains().size(); ++i) touching += walls->contact_count(i) > 0;
        EXPECT_GT(touching, 500) << "the bed does not rest on the mesh at the checkpoint";
        for (const auto& v : s.output_values()) {
            if (v.name == "wear_mass_floor") {
                EXPECT_GT(v.value, 0.0);
            }
        }
    });
}

// Grains poured onto the chute: the feed's insertions (their draws keyed by insertion, the mass carried
// between them) and the chute's wear map across the checkpoint, with insertions after it.
TEST(Restart, PouredGrainsOnTheChuteContinueBitForBit) {
    grit::parallel::set_threads(2);
    const auto spec = grit::testing::load_case("chute_wear_3d/case.toml", {"time.end=0.15"});
    check_restart<3>(spec, 0.105, 0.135, false, [](Simulation<3>& s) {
        EXPECT_GT(s.grains()->grains().size(), 100);
        for (const auto& v : s.output_values()) {
            if (v.name == "wear_mass_chute") {
                EXPECT_GT(v.value, 0.0);
            }
        }
    });
}

// The periodic channel with the fluid moving fast along the periodic axis: particles have crossed the
// periodic face and the lists have been rebuilt over the periodic grid before the checkpoint, and both
// go on after it (the lists are rebuilt on load from their reference positions, on the periodic grid).
TEST(Restart, PeriodicChannelAcrossTheFaceContinuesBitForBit) {
    grit::parallel::set_threads(2);
    const auto spec = grit::testing::load_case("poiseuille_periodic_2d/case.toml",
                                               {"fluid[0].velocity=[0.05, 0.0]", "materials.viscous_water.sound_speed=0.5"});
    check_restart<2>(spec, 30, 60, true, [](Simulation<2>& s) {
        EXPECT_GE(s.state().neighbors.builds(), 3) << "the lists were not rebuilt before the checkpoint";
        const auto& ps = s.particles();
        bool crossed = false;  // a fluid particle that started in the last column now lies in the first
        for (grit::Index i = 0; i < ps.size(); ++i)
            crossed |= ps.phase()[i] == 0 && ps.position()[i][0] < 0.5 * 2.5e-5;
        EXPECT_TRUE(crossed) << "no particle crossed the periodic face before the checkpoint";
    });
}

// A periodic run's checkpoint does not continue in a case without periodic axes.
TEST(Restart, CheckpointWithOtherPeriodicAxesIsRefused) {
    const fs::path file = scratch_file("periodic.h5");
    {
        Simulation<2> s(grit::testing::load_case("poiseuille_periodic_2d/case.toml"), grit::testing::in_memory());
        s.advance_to(0.0);
        s.save_checkpoint(file);
    }
    Simulation<2> open(grit::testing::load_case("poiseuille_periodic_2d/case.toml", {"domain.periodic=[]"}),
                       grit::testing::in_memory());
    try {
        open.load_checkpoint(file);
        FAIL() << "a periodic checkpoint was accepted by a case without periodic axes";
    } catch (const grit::core::InputError& e) {
        EXPECT_NE(std::string(e.what()).find("domain.periodic"), std::string::npos) << e.what();
    }
    fs::remove(file);
}

// A checkpoint of an earlier format (version 3 had 32-bit ids counted in creation order) is refused with
// the version that wrote it, not read in part.
TEST(Restart, CheckpointOfAnEarlierFormatIsRefusedNamingTheGritThatWroteIt) {
    const fs::path file = scratch_file("earlier.h5");
    {
        Simulation<2> s(grit::testing::load_case("hydrostatic_2d/case.toml"), grit::testing::in_memory());
        s.advance_to(0.0);
        s.save_checkpoint(file);
    }
    {  // as an earlier grit would have stamped it
        const hid_t f = H5Fopen(file.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
        ASSERT_GE(f, 0);
        const hid_t a = H5Aopen(f, "format_version", H5P_DEFAULT);
        ASSERT_GE(a, 0);
        const std::int64_t three = 3;
        ASSERT_GE(H5Awrite(a, H5T_NATIVE_INT64, &three), 0);
        H5Aclose(a);
        H5Fclose(f);
    }
    Simulation<2> s(grit::testing::load_case("hydrostatic_2d/case.toml"), grit::testing::in_memory());
    try {
        s.load_checkpoint(file);
        FAIL() << "a checkpoint of format version 3 was accepted";
    } catch (const grit::core::InputError& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("format version 3, written by grit "), std::string::npos) << what;
        EXPECT_NE(what.find("reads format version 4 only"), std::string::npos) << what;
    }
    fs::remove(file);
}

TEST(Restart, CheckpointOfAnotherCaseIsRefused) {
    const fs::path file = scratch_file("foreign.h5");
    {
        Simulation<2> s(grit::testing::load_case("hydrostatic_2d/case.toml"), grit::testing::in_memory());
        s.advance_to(0.0);
        s.save_checkpoint(file);
    }
    Simulation<2> other(grit::testing::load_case("dambreak_2d/case.toml"), grit::testing::in_memory());
    try {
        other.load_checkpoint(file);
        FAIL() << "a foreign checkpoint was accepted";
    } catch (const grit::core::InputError& e) {
        EXPECT_NE(std::string(e.what()).find("written by case 'hydrostatic_2d'"), std::string::npos) << e.what();
    }
    Simulation<2> finer(grit::testing::load_case("hydrostatic_2d/case.toml", {"numerics.particle_spacing=0.0125"}),
                        grit::testing::in_memory());
    try {
        finer.load_checkpoint(file);
        FAIL() << "a checkpoint with another spacing was accepted";
    } catch (const grit::core::InputError& e) {
        EXPECT_NE(std::string(e.what()).find("numerics.particle_spacing"), std::string::npos) << e.what();
    }
    fs::remove(file);
}

// A checkpoint of a grit that did not analyse the crater in the case (3D AWJ runs before the crater map):
// it has no 'crater' module group; the run continues, the crater's files starting at the restart.
TEST(Restart, CheckpointWithoutTheCraterModuleContinues) {
    const fs::path file = scratch_file("no_crater.h5");
    {
        auto spec = grit::testing::load_case("awj_copper_2d/case.toml");
        spec.jet.crater.reset();  // as the older grit built it
        Simulation<2> s(spec, grit::testing::in_memory());
        s.advance_to(0.0);
        s.save_checkpoint(file);
    }
    Simulation<2> s(grit::testing::load_case("awj_copper_2d/case.toml"), grit::testing::in_memory());
    EXPECT_NO_THROW(s.load_checkpoint(file));
    s.step();
    EXPECT_EQ(grit::testing::output_value(s, "crater_depth"), 0.0);
    fs::remove(file);
}

TEST(Restart, TruncatedOrMissingCheckpointIsRefused) {
    const fs::path file = scratch_file("truncated.h5");
    {
        Simulation<2> s(grit::testing::load_case("hydrostatic_2d/case.toml"), grit::testing::in_memory());
        s.advance_to(0.0);
        s.save_checkpoint(file);
    }
    fs::resize_file(file, fs::file_size(file) / 2);
    Simulation<2> s(grit::testing::load_case("hydrostatic_2d/case.toml"), grit::testing::in_memory());
    EXPECT_THROW(s.load_checkpoint(file), grit::core::InputError);
    EXPECT_THROW(s.load_checkpoint(scratch_file("missing.h5")), grit::core::InputError);
    std::ofstream(scratch_file("text.h5")) << "not hdf5\n";
    EXPECT_THROW(s.load_checkpoint(scratch_file("text.h5")), grit::core::InputError);
    fs::remove(file);
}

// The half AWJ on its symmetry plane, grains in the water and on the copper: the images (saved with
// the particles) and the grains' frictionless plane across the checkpoint.
TEST(Restart, SymmetryPlaneMidRunContinuesBitForBit) {
    grit::parallel::set_threads(2);
    const auto spec = grit::testing::load_case("awj_copper_2d/case.toml",
                                               {"jet.symmetric=true", "time.end=1.2e-5", "output.interval=1e-6"});
    check_restart<2>(spec, 1.0e-5, 1.2e-5, false, [](Simulation<2>& s) {
        EXPECT_GT(s.particles().image_count(), 100);
        EXPECT_GT(s.grains()->grains().size(), 0);
    });
}

// Non-local damage (a garnet grain at 500 m/s into the x >= 0 half of a copper plate on a symmetry
// plane): the pair list of the damage average is not saved; rebuilt from the loaded positions it gives
// the same sums (they take the pairs within the length in ascending index), images included.
TEST(Restart, NonlocalDamageOnASymmetryPlaneContinuesBitForBit) {
    grit::parallel::set_threads(2);
    const auto spec = grit::testing::load_case(
        "grain_impact_copper_2d/case.toml",
        {"grains[0].velocity=[0.0, -500.0]", "materials.OFHC_copper.damage_length=6e-5", "domain.symmetry=[\"x\"]",
         "solid[0].min=[0.0, -1.0e-3]", "time.end=8e-7", "output.interval=1e-7"});
    check_restart<2>(spec, 5e-7, 8e-7, false, [](Simulation<2>& s) {
        EXPECT_GT(s.particles().image_count(), 50);
        const auto& damage = s.particles().fields().get<double>("damage");
        EXPECT_GT(*std::max_element(damage.data(), damage.data() + damage.size()), 0.05);
    });
}

// A checkpoint of the half run does not continue the whole set-up, nor the other way round.
TEST(Restart, CheckpointOfTheOtherSideOfASymmetryPlaneIsRefused) {
    const fs::path file = scratch_file("symmetry_refused.h5");
    const std::vector<std::string> brief = {"time.end=2e-7", "output.interval=1e-7"};
    auto half_keys = brief;
    half_keys.push_back("jet.symmetric=true");
    for (const bool from_half : {true, false}) {
        SCOPED_TRACE(from_half ? "half into whole" : "whole into half");
        {
            Simulation<2> s(grit::testing::load_case("awj_copper_2d/case.toml", from_half ? half_keys : brief),
                            grit::testing::in_memory());
            s.advance_to(1e-7);
            s.save_checkpoint(file);
        }
        Simulation<2> other(grit::testing::load_case("awj_copper_2d/case.toml", from_half ? brief : half_keys),
                            grit::testing::in_memory());
        try {
            other.load_checkpoint(file);
            ADD_FAILURE() << "loaded";
        } catch (const grit::core::InputError& e) {
            EXPECT_NE(std::string(e.what()).find("domain.symmetry"), std::string::npos) << e.what();
        }
    }
    fs::remove(file);
}

namespace {

std::string file_text(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// The demo with outputs every 2.5 us: 3 x 2.5e-6 = 7.500000000000001e-06 lies one unit in the last
// place above the end 7.5e-6 a user writes, so a run ending there and one passing it aimed their steps
// at different doubles while output times were a running sum and the end was not snapped onto them.
grit::io::CaseSpec extension_case(const std::string& end) {
    return grit::io::read_case(fs::path(GRIT_SOURCE_DIR) / "cases" / "demo.toml",
                               {"output.interval=2.5e-6", "output.snapshots=false", "time.end=" + end});
}

// Runs `spec` into `dir` with files, fresh or continuing the run there; returns the simulation.
std::unique_ptr<Simulation<2>> run_into(const grit::io::CaseSpec& spec, const fs::path& dir, bool restart) {
    grit::sim::RunOptions options;
    options.output_dir = dir;
    options.quiet = true;
    if (restart) options.restart = dir;
    auto s = std::make_unique<Simulation<2>>(spec, options);
    s->run();
    return s;
}

}  // namespace

// A finished run extended (--restart DIR --set time.end=...) continues as if it had never stopped: end
// at T, extend to 2T and to 3T (two extensions), or at once to 3T (one), against a run straight to 3T
// that passes T and 2T: the same state bit for bit and the same series.csv.
TEST(Restart, ExtendingAFinishedRunIsBitIdenticalToARunThatNeverStopped) {
    grit::parallel::set_threads(2);
    const fs::path root = fs::temp_directory_path() / "grit_restart_extension";
    fs::remove_all(root);
    const auto straight = run_into(extension_case("2.25e-5"), root / "straight", false);
    const std::string straight_series = file_text(root / "straight" / "series.csv");

    run_into(extension_case("7.5e-6"), root / "twice", false);
    run_into(extension_case("1.5e-5"), root / "twice", true);
    const std::string halfway = file_text(root / "twice" / "series.csv");
    EXPECT_EQ(straight_series.compare(0, halfway.size(), halfway), 0) << "series.csv at 2T differs";
    const auto twice = run_into(extension_case("2.25e-5"), root / "twice", true);
    expect_same_state(*straight, *twice);
    EXPECT_EQ(file_text(root / "twice" / "series.csv"), straight_series);

    run_into(extension_case("7.5e-6"), root / "once", false);
    const auto once = run_into(extension_case("2.25e-5"), root / "once", true);
    expect_same_state(*straight, *once);
    EXPECT_EQ(file_text(root / "once" / "series.csv"), straight_series);
    fs::remove_all(root);
}
