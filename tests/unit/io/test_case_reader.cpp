// Unit tests of the case reader: every shipped case reads, a minimal case gives the expected CaseSpec,
// --set overrides take effect, and every bad input throws InputError naming the key, the value and why.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <exception>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <random>
#include <stdexcept>
#include <string>
#include <system_error>
#include <variant>
#include <vector>

#include "grit/core/error.hpp"
#include "grit/core/types.hpp"
#include "grit/modules/cracks_table.hpp"
#include "grit/modules/probes_table.hpp"
#include "grit/io/case_reader.hpp"
#include "grit/io/case_spec.hpp"
#include "support/case_text.hpp"
#include "grit/io/particle_budget.hpp"
#include "grit/wear/wear_models.hpp"

namespace {

namespace fs = std::filesystem;
using grit::core::InputError;
using grit::io::CaseSpec;
using grit::io::estimate_particles;
using grit::io::read_case;
using grit::io::shape_particle_bound;
using Overrides = std::vector<std::string>;

/// A small, valid 2D case: one fluid box of a case-defined material, a tank, two probes.
const std::string minimal_2d = R"(# minimal 2D case
[simulation]
title = "minimal"
dimension = 2

[time]
end = 0.5

[output]
interval = 0.125

[numerics]
particle_spacing = 0.015625

[physics]
gravity = [0.0, -9.75]

[materials.my_water]
base = "water_tait"
sound_speed = 25.0

[[fluid]]
shape = "box"
min = [0.0, 0.0]
max = [0.25, 0.125]
material = "my_water"

[[wall]]
shape = "tank"
min = [0.0, 0.0]
max = [0.5, 0.25]
layers = 2

[domain]
min = [-0.125, -0.125]
max = [0.625, 0.5]

[[probe]]
name = "p_bottom"
position = [0.125, 0.0625]

[[probe]]
name = "front"
kind = "front"
axis = "x"
)";

using grit::testing::replaced;

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

/// A fresh, uniquely named directory per test, removed afterwards.
class CaseReaderTest : public ::testing::Test {
protected:
    void SetUp() override {
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        std::random_device rd;
        const auto stamp = std::chrono::steady_clock::now().time_since_epoch().count();
        for (int attempt = 0; attempt < 100; ++attempt) {
            dir_ = fs::temp_directory_path() / (std::string("grit_case_reader_") + info->name() + "_" +
                                                std::to_string(stamp) + "_" + std::to_string(rd()));
            if (fs::create_directory(dir_)) return;
        }
        FAIL() << "could not create a fresh temporary directory";
    }
    void TearDown() override {
        std::error_code ec;
        fs::remove_all(dir_, ec);
    }

    /// Writes `text` to dir_/`name` and returns its path.
    fs::path write(const std::string& text, const std::string& name = "case.toml") const {
        const fs::path p = dir_ / name;
        std::ofstream out(p, std::ios::binary);
        out << text;
        return p;
    }

    /// Reads `text` (written as a case file); fails the test on any exception.
    CaseSpec read_ok(const std::string& text, const Overrides& overrides = {}) const {
        try {
            return read_case(write(text), overrides);
        } catch (const std::exception& e) {
            ADD_FAILURE() << "unexpected exception: " << e.what();
        }
        return {};
    }

    /// Expects read_case on `file` to throw InputError whose message contains every one of `parts`.
    static void expect_error_file(const fs::path& file, const Overrides& overrides, const std::vector<std::string>& parts) {
        try {
            (void)read_case(file, overrides);
            ADD_FAILURE() << "no InputError thrown; expected a message with '" << parts.front() << "'";
        } catch (const InputError& e) {
            const std::string what = e.what();
            for (const auto& part : parts) EXPECT_TRUE(contains(what, part)) << "'" << part << "' missing in: " << what;
            EXPECT_FALSE(contains(what, "\n")) << "the message should be one line: " << what;
        } catch (const std::exception& e) {
            ADD_FAILURE() << "expected InputError, got another exception: " << e.what();
        }
    }
    void expect_error(const std::string& text, const Overrides& overrides, const std::vector<std::string>& parts) const {
        expect_error_file(write(text), overrides, parts);
    }
    /// The message of the InputError read_case throws on `text` (empty, and a failure, if none).
    std::string error_of(const std::string& text, const Overrides& overrides) const {
        try {
            (void)read_case(write(text), overrides);
        } catch (const InputError& e) {
            return e.what();
        }
        ADD_FAILURE() << "no InputError thrown";
        return {};
    }

    fs::path dir_;
};

// ---------------------------------------------------------------------------------------------------
// The shipped cases

TEST_F(CaseReaderTest, EveryShippedCaseReads) {
    const fs::path cases = fs::path(GRIT_SOURCE_DIR) / "cases";
    ASSERT_TRUE(fs::is_directory(cases)) << cases;
    std::vector<fs::path> files;
    for (const auto& e : fs::directory_iterator(cases)) {
        if (e.is_directory() && fs::exists(e.path() / "case.toml")) files.push_back(e.path() / "case.toml");
        if (e.is_regular_file() && e.path().extension() == ".toml") files.push_back(e.path());  // e.g. demo.toml
    }
    std::sort(files.begin(), files.end());
    EXPECT_GE(files.size(), 4u) << "expected at least hydrostatic_2d/3d, dambreak_2d and jet_on_wall_2d";
    for (const auto& f : files) {
        SCOPED_TRACE(f.string());
        try {
            const CaseSpec c = read_case(f);
            const std::string expected_name =
                f.filename() == "case.toml" ? f.parent_path().filename().string() : f.stem().string();
            EXPECT_EQ(c.name, expected_name);
            EXPECT_TRUE(c.dimension == 2 || c.dimension == 3);
            EXPECT_GT(c.particle_spacing, 0.0);
            EXPECT_GT(c.output_interval, 0.0);
            EXPECT_EQ(c.gravity.size(), static_cast<std::size_t>(c.dimension));
            // SPH cases name their materials; grains-only cases (DEM) have grain materials instead.
            EXPECT_TRUE(!c.materials.empty() || (!c.has_sph() && !c.grain_materials.empty()));
            EXPECT_FALSE(c.fluids.empty() && c.inlets.empty() && c.solids.empty() && !c.has_grains());
        } catch (const std::exception& e) {
            ADD_FAILURE() << f << ": " << e.what();
        }
    }
}

TEST_F(CaseReaderTest, ShippedCaseAcceptsZeroEndTimeOverride) {
    const fs::path f = fs::path(GRIT_SOURCE_DIR) / "cases" / "hydrostatic_2d" / "case.toml";
    ASSERT_TRUE(fs::exists(f)) << f;
    const CaseSpec c = read_case(f, {"time.end=0"});
    EXPECT_EQ(c.end_time, 0.0);
    EXPECT_EQ(c.name, "hydrostatic_2d");
}

// ---------------------------------------------------------------------------------------------------
// A valid minimal case

TEST_F(CaseReaderTest, MinimalCaseGivesExpectedSpec) {
    const CaseSpec c = read_ok(minimal_2d);
    EXPECT_EQ(c.source, dir_ / "case.toml");
    EXPECT_EQ(c.name, dir_.filename().string());  // "case.toml" takes its folder's name
    EXPECT_EQ(c.title, "minimal");
    EXPECT_EQ(c.dimension, 2);
    EXPECT_DOUBLE_EQ(c.end_time, 0.5);
    EXPECT_DOUBLE_EQ(c.output_interval, 0.125);
    EXPECT_TRUE(c.write_snapshots);
    EXPECT_DOUBLE_EQ(c.particle_spacing, 0.015625);
    ASSERT_EQ(c.gravity.size(), 2u);
    EXPECT_DOUBLE_EQ(c.gravity[0], 0.0);
    EXPECT_DOUBLE_EQ(c.gravity[1], -9.75);

    // Defaults.
    EXPECT_DOUBLE_EQ(c.cfl, 0.2);
    EXPECT_DOUBLE_EQ(c.smoothing_ratio, 1.25);
    EXPECT_EQ(c.kernel, "cubic_spline");
    EXPECT_DOUBLE_EQ(c.density_diffusion, 0.1);
    EXPECT_FALSE(c.remove_leaving);

    // The material: its index and the EOS sound speed overriding the library's.
    ASSERT_EQ(c.materials.size(), 1u);
    EXPECT_EQ(c.materials[0].name, "my_water");
    EXPECT_EQ(c.materials[0].phase, grit::Phase::fluid);
    EXPECT_DOUBLE_EQ(c.materials[0].sound_speed(), 25.0);
    EXPECT_DOUBLE_EQ(c.materials[0].reference_density(), 1000.0);

    ASSERT_EQ(c.fluids.size(), 1u);
    EXPECT_EQ(c.fluids[0].key, "fluid[0]");
    EXPECT_EQ(c.fluids[0].shape.kind, "box");
    EXPECT_EQ(c.fluids[0].shape.min, (std::vector<double>{0.0, 0.0}));
    EXPECT_EQ(c.fluids[0].shape.max, (std::vector<double>{0.25, 0.125}));
    EXPECT_EQ(c.fluids[0].material, 0);
    EXPECT_EQ(c.fluids[0].velocity, (std::vector<double>{0.0, 0.0}));
    EXPECT_FALSE(c.fluids[0].hydrostatic);

    ASSERT_EQ(c.walls.size(), 1u);
    EXPECT_EQ(c.walls[0].shape.kind, "tank");
    EXPECT_EQ(c.walls[0].shape.layers, 2);
    EXPECT_EQ(c.walls[0].shape.open, (std::vector<std::string>{"top"}));
    EXPECT_EQ(c.walls[0].material, 0);  // walls default to the first fluid's material

    EXPECT_EQ(c.domain_min, (std::vector<double>{-0.125, -0.125}));
    EXPECT_EQ(c.domain_max, (std::vector<double>{0.625, 0.5}));

    // [[probe]] is the probes module's own table (modules/probes_table.cpp), read through the same reader.
    const auto& probes = c.module_spec<grit::modules::ProbesSpec>(grit::modules::ProbesSpec::key)->probes;
    ASSERT_EQ(probes.size(), 2u);
    EXPECT_EQ(probes[0].name, "p_bottom");
    EXPECT_EQ(probes[0].kind, "point");
    EXPECT_EQ(probes[0].quantity, "pressure");
    EXPECT_EQ(probes[0].position, (std::vector<double>{0.125, 0.0625}));
    EXPECT_EQ(probes[1].name, "front");
    EXPECT_EQ(probes[1].kind, "front");
    EXPECT_EQ(probes[1].axis, 0);
    EXPECT_FALSE(probes[1].has_region);
}

TEST_F(CaseReaderTest, NameComesFromTheFileStemUnlessCaseToml) {
    const CaseSpec c = read_case(write(minimal_2d, "my_run.toml"));
    EXPECT_EQ(c.name, "my_run");
}

TEST_F(CaseReaderTest, LibraryMaterialByNameAndZeroEndTime) {
    std::string text = replaced(minimal_2d, "material = \"my_water\"", "material = \"water\"");
    text = replaced(text, "end = 0.5", "end = 0.0");
    const CaseSpec c = read_ok(text);
    EXPECT_EQ(c.end_time, 0.0);  // zero end time writes the initial state only: allowed
    // "my_water" is defined but unused; only materials in use are listed.
    ASSERT_EQ(c.materials.size(), 1u);
    EXPECT_EQ(c.materials[0].name, "water");
    EXPECT_DOUBLE_EQ(c.materials[0].sound_speed(), 1480.0);
}

TEST_F(CaseReaderTest, ThreeDimensionalCase) {
    const std::string text = R"(
[simulation]
dimension = 3
[time]
end = 0.1
[output]
interval = 0.05
[numerics]
particle_spacing = 0.0625
kernel = "wendland_c2"
[physics]
gravity = [0.0, 0.0, -9.81]
[[fluid]]
shape = "sphere"
center = [0.5, 0.5, 0.5]
radius = 0.25
velocity = [1.0, 2.0, 3.0]
[domain]
min = [0.0, 0.0, 0.0]
max = [1.0, 1.0, 1.0]
on_exit = "remove"
)";
    const CaseSpec c = read_ok(text);
    EXPECT_EQ(c.dimension, 3);
    EXPECT_EQ(c.kernel, "wendland_c2");
    EXPECT_TRUE(c.remove_leaving);
    ASSERT_EQ(c.fluids.size(), 1u);
    EXPECT_EQ(c.fluids[0].shape.kind, "disc");  // "sphere" is the 3D name of a disc
    EXPECT_DOUBLE_EQ(c.fluids[0].shape.radius, 0.25);
    EXPECT_EQ(c.fluids[0].velocity, (std::vector<double>{1.0, 2.0, 3.0}));
    ASSERT_EQ(c.materials.size(), 1u);
    EXPECT_EQ(c.materials[0].name, "water");  // the default material
}

// ---------------------------------------------------------------------------------------------------
// --set overrides

TEST_F(CaseReaderTest, OverrideReplacesANumber) {
    const CaseSpec c = read_ok(minimal_2d, {"numerics.particle_spacing=0.02"});
    EXPECT_DOUBLE_EQ(c.particle_spacing, 0.02);
}

TEST_F(CaseReaderTest, OverrideTrimsSpacesAndTheLastOneWins) {
    const CaseSpec c = read_ok(minimal_2d, {" time.end = 0.25 ", "time.end=0.375"});
    EXPECT_DOUBLE_EQ(c.end_time, 0.375);
}

TEST_F(CaseReaderTest, OverrideCreatesNestedNewKeys) {
    // A new material defined entirely from the command line; a bare word is a string.
    const CaseSpec c =
        read_ok(minimal_2d, {"materials.foo.base=water_tait", "materials.foo.sound_speed=30", "fluid[0].material=foo"});
    ASSERT_EQ(c.materials.size(), 1u);
    EXPECT_EQ(c.materials[0].name, "foo");
    EXPECT_DOUBLE_EQ(c.materials[0].sound_speed(), 30.0);
    EXPECT_EQ(c.fluids[0].material, 0);
}

TEST_F(CaseReaderTest, OverrideChangesAMaterialOfTheCase) {
    const CaseSpec c = read_ok(minimal_2d, {"materials.my_water.sound_speed=40.5"});
    ASSERT_EQ(c.materials.size(), 1u);
    EXPECT_DOUBLE_EQ(c.materials[0].sound_speed(), 40.5);
}

TEST_F(CaseReaderTest, OverrideIndexedTableAndArrayValue) {
    const CaseSpec c = read_ok(minimal_2d, {"fluid[0].velocity=[1.0, 0.0]"});
    ASSERT_EQ(c.fluids.size(), 1u);
    EXPECT_EQ(c.fluids[0].velocity, (std::vector<double>{1.0, 0.0}));
}

TEST_F(CaseReaderTest, OverrideBareWordBecomesAString) {
    const CaseSpec c = read_ok(minimal_2d, {"numerics.kernel=wendland_c2", "simulation.title=a bare title"});
    EXPECT_EQ(c.kernel, "wendland_c2");
    EXPECT_EQ(c.title, "a bare title");
    const CaseSpec q = read_ok(minimal_2d, {"numerics.kernel=\"wendland_c2\""});
    EXPECT_EQ(q.kernel, "wendland_c2");
}

TEST_F(CaseReaderTest, OverrideBooleanAndInteger) {
    const CaseSpec c = read_ok(minimal_2d, {"output.snapshots=false", "numerics.check_interval=7"});
    EXPECT_FALSE(c.write_snapshots);
    EXPECT_EQ(c.check_interval, 7);
}

// ---------------------------------------------------------------------------------------------------
// Bad input: InputError naming the key (or file), the value and the reason

TEST_F(CaseReaderTest, UnknownTopLevelKey) {
    expect_error(minimal_2d + "\n[solver]\niterations = 3\n", {}, {"'solver'", "unknown key", "not valid here"});
    expect_error("speed = 3\n" + minimal_2d, {}, {"'speed'", "unknown key"});
    // A misspelt table is offered the nearest valid one.
    expect_error(minimal_2d + "\n[outptu]\nx = 1\n", {}, {"'outptu'", "unknown key", "did you mean 'output'?"});
}

TEST_F(CaseReaderTest, UnknownNestedKey) {
    // A misspelt optional key next to the right ones.
    expect_error(replaced(minimal_2d, "particle_spacing = 0.015625", "particle_spacing = 0.015625\nsmoothing_ratoi = 1.3"),
                 {}, {"numerics.smoothing_ratoi", "unknown key", "did you mean 'smoothing_ratio'?"});
    // The same typo through --set.
    expect_error(minimal_2d, {"numerics.particle_spacng=0.02"},
                 {"numerics.particle_spacng", "unknown key", "did you mean 'particle_spacing'?"});
    // Misspelt keys inside arrays of tables are found too.
    expect_error(replaced(minimal_2d, "layers = 2", "layers = 2\nlayer = 3"), {},
                 {"wall[0].layer", "unknown key", "did you mean 'layers'?"});
}

TEST_F(CaseReaderTest, MisspeltRequiredKeyIsReportedAsMissing) {
    // The required key is read (and found missing) before unknown keys are reported.
    // It names the misspelt key it found instead, and no valid key as unrecognised.
    const std::string message = error_of(replaced(minimal_2d, "particle_spacing =", "particle_spacng ="), {});
    EXPECT_NE(message.find("key 'numerics.particle_spacing': is required"), std::string::npos) << message;
    EXPECT_NE(message.find("the file has 'numerics.particle_spacng': did you mean 'particle_spacing'?"),
              std::string::npos) << message;
    EXPECT_EQ(message.find("not recognised"), std::string::npos) << message;
}

TEST_F(CaseReaderTest, WrongType) {
    expect_error(replaced(minimal_2d, "particle_spacing = 0.015625", "particle_spacing = \"0.01\""), {},
                 {"numerics.particle_spacing", "\"0.01\"", "must be a number"});
    expect_error(minimal_2d, {"time.end=soon"}, {"time.end", "\"soon\"", "must be a number"});
    expect_error(minimal_2d, {"output.snapshots=1"}, {"output.snapshots", "1", "true or false"});
    expect_error(minimal_2d, {"simulation.dimension=2.5"}, {"simulation.dimension", "2.5", "integer"});
}

TEST_F(CaseReaderTest, NegativeSpacing) {
    expect_error(replaced(minimal_2d, "particle_spacing = 0.015625", "particle_spacing = -0.01"), {},
                 {"numerics.particle_spacing", "-0.01", "must be positive"});
    expect_error(minimal_2d, {"numerics.particle_spacing=0"}, {"numerics.particle_spacing", "0", "must be positive"});
}

TEST_F(CaseReaderTest, NegativeEndTimeRejectedZeroAllowed) {
    EXPECT_EQ(read_ok(minimal_2d, {"time.end=0"}).end_time, 0.0);
    expect_error(replaced(minimal_2d, "end = 0.5", "end = -1.5"), {}, {"time.end", "-1.5", "must not be negative"});
    expect_error(minimal_2d, {"time.end=-1"}, {"time.end", "-1", "must not be negative"});
}

TEST_F(CaseReaderTest, OutOfRangeValues) {
    expect_error(minimal_2d, {"time.cfl=1.5"}, {"time.cfl", "1.5", "must lie in"});
    expect_error(minimal_2d, {"simulation.dimension=4"}, {"simulation.dimension", "4", "must lie in [2, 3]"});
    expect_error(minimal_2d, {"output.interval=0"}, {"output.interval", "0", "must be positive"});
    expect_error(minimal_2d, {"time.end=nan"}, {"time.end", "nan", "finite"});
}

TEST_F(CaseReaderTest, BoxMaxNotAboveMin) {
    expect_error(replaced(minimal_2d, "max = [0.25, 0.125]", "max = [0.25, 0.0]"), {},
                 {"fluid[0].max", "0.25", "must exceed min in y"});
    expect_error(minimal_2d, {"wall[0].max=[-0.5, 0.25]"}, {"wall[0].max", "-0.5", "must exceed min in x"});
    expect_error(minimal_2d, {"domain.max=[0.625, -0.25]"}, {"domain.max", "-0.25", "must exceed"});
}

TEST_F(CaseReaderTest, BoxSmallerThanSpacing) {
    // The spacing is larger than the fluid box.
    expect_error(minimal_2d, {"numerics.particle_spacing=0.5"},
                 {"fluid[0].max", "0.25", "less than numerics.particle_spacing", "0.5"});
    expect_error(replaced(minimal_2d, "max = [0.25, 0.125]", "max = [0.25, 0.0078125]"), {},
                 {"fluid[0].max", "0.0078125", "wide in y", "less than numerics.particle_spacing"});
}

TEST_F(CaseReaderTest, UnknownMaterial) {
    expect_error(replaced(minimal_2d, "material = \"my_water\"", "material = \"unobtainium\""), {},
                 {"fluid[0].material", "\"unobtainium\"", "unknown material", "water_tait", "my_water"});
    expect_error(minimal_2d, {"materials.my_water.base=lava"}, {"materials.my_water.base", "\"lava\"", "unknown"});
    // A new material with neither a base nor an EOS.
    expect_error(minimal_2d, {"materials.foo.sound_speed=30", "fluid[0].material=foo"}, {"materials.foo.eos", "required"});
}

TEST_F(CaseReaderTest, UnknownKernel) {
    expect_error(replaced(minimal_2d, "particle_spacing = 0.015625", "particle_spacing = 0.015625\nkernel = \"gauss\""),
                 {}, {"numerics.kernel", "\"gauss\"", "must be one of", "cubic_spline"});
}

TEST_F(CaseReaderTest, VectorOfWrongLength) {
    expect_error(replaced(minimal_2d, "gravity = [0.0, -9.75]", "gravity = [0.0, -9.75, 0.0]"), {},
                 {"physics.gravity", "-9.75", "must be an array of 2 numbers", "2D"});
    expect_error(minimal_2d, {"fluid[0].velocity=[1.0, 0.0, 0.0]"}, {"fluid[0].velocity", "must be an array of 2"});
    expect_error(minimal_2d, {"physics.gravity=-9.81"}, {"physics.gravity", "-9.81", "must be an array of 2"});
    expect_error(minimal_2d, {"physics.gravity=[0.0, \"down\"]"}, {"physics.gravity", "down", "numbers"});
}

TEST_F(CaseReaderTest, MalformedTomlNamesTheLine) {
    // Line 3 opens a table header that is never closed.
    const fs::path f = write("# a comment\n\n[time\nend = 1.0\n");
    expect_error_file(f, {}, {f.string(), "line 3", "malformed TOML"});
}

TEST_F(CaseReaderTest, MissingFile) {
    const fs::path f = dir_ / "does_not_exist.toml";
    expect_error_file(f, {}, {f.string(), "no such file"});
}

TEST_F(CaseReaderTest, MissingRequiredKey) {
    expect_error(replaced(minimal_2d, "end = 0.5", ""), {}, {"time.end", "is required"});
    expect_error(replaced(minimal_2d, "[domain]\nmin = [-0.125, -0.125]", "[domain]"), {}, {"domain.min", "required"});
}

TEST_F(CaseReaderTest, NoFluid) {
    std::string text = replaced(minimal_2d, "[[fluid]]", "[[wall]]");
    text = replaced(text, "material = \"my_water\"\n", "");
    // The block that was the fluid is now a wall, which needs a fluid's EOS: the walls' material is
    // required and the message says why.
    expect_error(text, {}, {"wall[0].material", "is required", "the case has none"});
}

// ---------------------------------------------------------------------------------------------------
// Grains

/// A grains-only 2D case: one garnet grain above a plane.
const std::string grains_2d = R"([simulation]
dimension = 2
[time]
end = 0.01
[output]
interval = 0.005
[physics]
gravity = [0.0, -9.81]
[dem]
contact_law = "linear"
[[grains]]
arrangement = "single"
position = [0.0, 0.01]
[[grain_wall]]
point = [0.0, 0.0]
normal = [0.0, 2.0]
[domain]
min = [-0.1, -0.1]
max = [0.1, 0.1]
)";

TEST_F(CaseReaderTest, GrainsOnlyCaseNeedsNoSpacingAndTakesGarnet) {
    const CaseSpec c = read_ok(grains_2d);
    EXPECT_FALSE(c.has_sph());
    ASSERT_EQ(c.grains.size(), 1u);
    ASSERT_EQ(c.grain_materials.size(), 1u);
    EXPECT_EQ(c.grain_materials[0].name, "garnet");
    // Table 4: d = 0.2 mm is the nominal diameter used when the block gives none.
    ASSERT_TRUE(std::holds_alternative<grit::dem::FixedSize>(c.grains[0].size));
    EXPECT_DOUBLE_EQ(std::get<grit::dem::FixedSize>(c.grains[0].size).diameter, 0.2e-3);
    ASSERT_EQ(c.grain_walls.size(), 1u);
    EXPECT_EQ(c.grain_walls[0].name, "plane0");
    EXPECT_DOUBLE_EQ(c.grain_walls[0].normal[1], 1.0);  // normalised
    EXPECT_EQ(c.dem.contact_law, "linear");
    EXPECT_TRUE(c.dem.grain_grain_contact);
    EXPECT_FALSE(read_ok(grains_2d, {"dem.grain_grain_contact=false"}).dem.grain_grain_contact);
}

TEST_F(CaseReaderTest, GrainSizeDistributionAndInlineMaterial) {
    const std::string random_block =
        replaced(grains_2d, "arrangement = \"single\"\nposition = [0.0, 0.01]\n",
                 "arrangement = \"random\"\nmin = [-0.05, 0.0]\nmax = [0.05, 0.05]\ncount = 10\n");
    const CaseSpec c = read_ok(random_block, {"grains[0].size.distribution=normal", "grains[0].size.mean=0.002",
                                           "grains[0].size.deviation=0.0005", "grains[0].size.min=0.001",
                                           "grains[0].size.max=0.003", "grains[0].material=sand",
                                           "grain_materials.sand.density=2650", "grain_materials.sand.youngs_modulus=7e10",
                                           "grain_materials.sand.poisson_ratio=0.25", "grain_materials.sand.friction=0.5",
                                           "grain_materials.sand.restitution=0.7"});
    ASSERT_EQ(c.grains.size(), 1u);
    EXPECT_EQ(c.grains[0].arrangement, "random");
    EXPECT_EQ(c.grains[0].count, 10);
    ASSERT_TRUE(std::holds_alternative<grit::dem::NormalSize>(c.grains[0].size));
    EXPECT_EQ(c.grain_materials[0].name, "sand");
    EXPECT_DOUBLE_EQ(c.grain_materials[0].density, 2650.0);
}

TEST_F(CaseReaderTest, FixedGrainsTakeNoVelocity) {
    const CaseSpec c = read_ok(grains_2d, {"grains[0].fixed=true"});
    ASSERT_EQ(c.grains.size(), 1u);
    EXPECT_TRUE(c.grains[0].fixed);
    EXPECT_FALSE(read_ok(grains_2d).grains[0].fixed);
    expect_error(grains_2d, {"grains[0].fixed=true", "grains[0].velocity=[0.0, -1.0]"},
                 {"grains[0].velocity", "0, -1", "fixed grains"});
}

TEST_F(CaseReaderTest, GrainErrorsNameKeyValueAndReason) {
    expect_error(grains_2d, {"grains[0].material=diamond"}, {"grains[0].material", "\"diamond\"", "garnet"});
    expect_error(grains_2d, {"dem.contact_law=jkr"}, {"dem.contact_law", "\"jkr\"", "\"linear\", \"hertz\""});
    expect_error(grains_2d, {"dem.grain_grain_contact=2"}, {"dem.grain_grain_contact", "2"});
    expect_error(grains_2d, {"grains[0].diameter=-0.001"}, {"grains[0].diameter", "-0.001", "must be positive"});
    expect_error(replaced(grains_2d, "arrangement = \"single\"\nposition = [0.0, 0.01]\n",
                          "arrangement = \"lattice\"\nmin = [0.0, 0.0]\nmax = [0.01, 0.01]\n"),
                 {}, {"grains[0].spacing", "is required"});
    expect_error(grains_2d, {"grains[0].size.distribution=uniform", "grains[0].size.min=0.002", "grains[0].size.max=0.001"},
                 {"grains[0].size.distribution", "min <= (mean <=) max"});
    expect_error(grains_2d, {"grain_wall[0].normal=[0.0, 0.0]"}, {"grain_wall[0].normal", "zero vector"});
    expect_error(grains_2d, {"dem.periodic=[\"q\"]"}, {"dem.periodic", "axes"});
    expect_error(grains_2d, {"grain_materials.sand.density=2650", "grains[0].material=sand"},
                 {"grain_materials.sand.youngs_modulus", "is required"});
    expect_error(grains_2d, {"grains[0].colour=red"}, {"grains[0].colour"});
}

// domain.periodic: the periodic axes of the SPH particles and the grains alike; dem.periodic is its older
// spelling, and both given must agree. Solids and outlets across a periodic face are refused.
TEST_F(CaseReaderTest, PeriodicAxes) {
    EXPECT_FALSE(read_ok(minimal_2d).any_periodic());
    const CaseSpec c = read_ok(minimal_2d, {"domain.periodic=[\"x\"]"});
    EXPECT_EQ(c.periodic, (std::vector<bool>{true, false}));
    EXPECT_EQ(c.periodic_key, "domain.periodic");
    const CaseSpec g = read_ok(grains_2d, {"dem.periodic=[\"x\"]"});
    EXPECT_EQ(g.periodic, (std::vector<bool>{true, false}));
    EXPECT_EQ(g.periodic_key, "dem.periodic");
    EXPECT_EQ(read_ok(grains_2d, {"dem.periodic=[\"y\"]", "domain.periodic=[\"y\"]"}).periodic,
              (std::vector<bool>{false, true}));
    expect_error(grains_2d, {"dem.periodic=[\"x\"]", "domain.periodic=[\"x\", \"y\"]"},
                 {"'domain.periodic' = [\"x\", \"y\"]", "'dem.periodic' = [\"x\"]", "differ"});
    expect_error(grains_2d, {"dem.periodic=[\"x\"]", "domain.periodic=[]"}, {"domain.periodic", "differ"});
    expect_error(minimal_2d, {"domain.periodic=[\"z\"]"}, {"domain.periodic", "\"z\"", "names axes \"x\", \"y\""});
    expect_error(minimal_2d, {"domain.periodic=\"x\""}, {"domain.periodic", "array of strings"});
    // An outlet inside the period, or spanning all of it, is fine; one across a face is refused.
    const std::string outlet = "\n[[outlet]]\nmin = [0.5, -0.1]\nmax = [0.6, 0.0]\n";
    EXPECT_TRUE(read_ok(minimal_2d + outlet, {"domain.periodic=[\"x\"]"}).any_periodic());
    EXPECT_TRUE(read_ok(minimal_2d + outlet, {"domain.periodic=[\"x\"]", "outlet[0].min=[-0.2, -0.1]",
                                              "outlet[0].max=[0.7, 0.0]"})
                    .any_periodic());
    expect_error(minimal_2d + outlet, {"domain.periodic=[\"x\"]", "outlet[0].max=[0.7, 0.0]"},
                 {"outlet[0].min", "crosses a periodic face", "along x"});
    // The period must hold whole particle spacings (0.75 m / 0.015625 m = 48).
    expect_error(minimal_2d, {"domain.periodic=[\"x\"]", "domain.max=[0.63, 0.5]"},
                 {"domain.max", "not a whole number", "periodic face"});
    // Solids may be periodic too.
    const std::string solid = "\n[[solid]]\nshape = \"box\"\nmin = [-0.125, 0.25]\nmax = [0.625, 0.3125]\nmaterial = \"OFHC_copper\"\n";
    const auto periodic_solid = read_ok(minimal_2d + solid, {"domain.periodic=[\"x\"]"});
    EXPECT_TRUE(periodic_solid.any_periodic());
    EXPECT_EQ(periodic_solid.solids.size(), 1u);
}

// The Johnson-Cook damage length (non-local damage): 0 by default (the paper's local law), read from a
// material's section, and refused when negative.
TEST_F(CaseReaderTest, DamageLengthOfAJohnsonCookSolid) {
    const fs::path file = fs::path(GRIT_SOURCE_DIR) / "cases" / "awj_copper_2d" / "case.toml";
    auto copper = [](const CaseSpec& c) {
        for (const auto& m : c.materials)
            if (m.name == "OFHC_copper") return std::get<grit::material::JohnsonCook>(m.solid_model);
        ADD_FAILURE() << "no OFHC_copper";
        return grit::material::JohnsonCook{};
    };
    EXPECT_EQ(copper(read_case(file)).damage_length, 0.0);
    EXPECT_FALSE(copper(read_case(file)).nonlocal_damage());
    const auto jc = copper(read_case(file, {"materials.OFHC_copper.damage_length=3e-4"}));
    EXPECT_DOUBLE_EQ(jc.damage_length, 3e-4);
    EXPECT_TRUE(jc.nonlocal_damage());
    expect_error_file(file, {"materials.OFHC_copper.damage_length=-1e-4"},
                      {"materials.OFHC_copper.damage_length", "-0.0001"});
}

// Brittle solids (JH-2): the shipped compression case, its defaults, and errors naming key and reason.
TEST_F(CaseReaderTest, BrittleSolidKeysAndErrors) {
    const fs::path file = fs::path(GRIT_SOURCE_DIR) / "cases" / "compression_sandstone_2d" / "case.toml";
    const CaseSpec c = read_case(file, {"materials.red_sandstone.failure_d1=0.04"});
    const auto cracks = grit::modules::crack_options(c);  // on by default for a JH-2 solid
    ASSERT_TRUE(cracks.has_value());
    EXPECT_DOUBLE_EQ(cracks->damage_threshold, 0.5);
    EXPECT_DOUBLE_EQ(cracks->link_distance, 1.5 * c.particle_spacing);
    EXPECT_EQ(cracks->min_particles, 3);
    bool found = false;
    for (const auto& m : c.materials)
        if (m.name == "red_sandstone") {
            found = true;
            const auto& jh2 = std::get<grit::material::JH2>(m.solid_model);
            EXPECT_DOUBLE_EQ(jh2.failure.D1, 0.04);
            EXPECT_DOUBLE_EQ(jh2.bulk_modulus, 10.45e9);
        }
    EXPECT_TRUE(found);
    expect_error_file(file, {"materials.sandstone_tab.eos=tait", "materials.sandstone_tab.model=jh2"},
                      {"materials.sandstone_tab.model", "polynomial"});
    expect_error_file(file, {"materials.sandstone_tab.sound_speed=2000"}, {"materials.sandstone_tab.sound_speed", "k1"});
    expect_error_file(file, {"materials.red_sandstone.bulking_fraction=1.5"},
                      {"materials.red_sandstone.bulking_fraction", "1.5", "[0, 1]"});
    expect_error_file(file, {"materials.rock.eos=polynomial", "materials.rock.reference_density=2000",
                             "materials.rock.shear_modulus=1e9", "materials.rock.model=jh2", "solid[0].material=rock"},
                      {"materials.rock.k1", "is required"});
    expect_error_file(file, {"materials.rock.eos=polynomial", "materials.rock.reference_density=2000",
                             "materials.rock.k1=1e10", "materials.rock.shear_modulus=1e9", "materials.rock.model=jh2",
                             "solid[0].material=rock"},
                      {"materials.rock.hel_pressure", "is required"});
    expect_error_file(file, {"cracks.link_distance=-0.001"}, {"cracks.link_distance", "must be positive"});
}

// ---------------------------------------------------------------------------------------------------
// The particle budget: numerics.max_particles against the count estimated from the shapes

TEST_F(CaseReaderTest, DamBreakEstimateIsItsRealCount) {
    const fs::path file = fs::path(GRIT_SOURCE_DIR) / "cases" / "dambreak_2d" / "case.toml";
    const CaseSpec c = read_case(file);
    EXPECT_EQ(c.max_particles, 20'000'000);
    // `grit run cases/dambreak_2d/case.toml --end-time 0` makes 23018 particles (summary.json): the
    // column 100 x 200 and the tank, 406 x 303 lattice points less the 400 x 300 inside it.
    const double real = 23018.0;
    const auto e = estimate_particles(c);
    EXPECT_GE(e.sph, real);
    EXPECT_LE(e.sph, 1.5 * real);
    EXPECT_EQ(e.grains, 0.0);
    EXPECT_EQ(e.inlets, 0.0);
    EXPECT_GT(e.bytes, 100.0 * real);
    EXPECT_LT(e.bytes, 1000.0 * real);
}

TEST_F(CaseReaderTest, MinimalCaseEstimateIsExact) {
    // Fluid 16 x 8; tank with two layers, top open: 36 x 18 less 32 x 16 (`grit run` makes 264).
    EXPECT_DOUBLE_EQ(estimate_particles(read_ok(minimal_2d)).total(), 128.0 + 136.0);
}

TEST_F(CaseReaderTest, ShapeBoundsLieAboveTheLatticeCounts) {
    const double dx = 0.01;
    grit::io::ShapeSpec box;
    box.kind = "box";
    box.min = {0.0, 0.0, 0.0};
    box.max = {0.1, 0.2, 0.3};
    EXPECT_DOUBLE_EQ(shape_particle_bound(box, 2, dx), 10.0 * 20.0);
    EXPECT_DOUBLE_EQ(shape_particle_bound(box, 3, dx), 10.0 * 20.0 * 30.0);
    // Discs and spheres: at least their area (volume) / dx^Dim, and not far above for a radius of 20 dx.
    grit::io::ShapeSpec disc;
    disc.kind = "disc";
    disc.center = {0.0, 0.0, 0.0};
    disc.radius = 0.2;
    const double area = std::numbers::pi * 400.0, volume = 4.0 / 3.0 * std::numbers::pi * 8000.0;
    EXPECT_GE(shape_particle_bound(disc, 2, dx), area);
    EXPECT_LE(shape_particle_bound(disc, 2, dx), 1.2 * area);
    EXPECT_GE(shape_particle_bound(disc, 3, dx), volume);
    EXPECT_LE(shape_particle_bound(disc, 3, dx), 1.3 * volume);
    grit::io::ShapeSpec cylinder = disc;
    cylinder.kind = "cylinder";
    cylinder.length = 0.5;
    cylinder.axis = 1;
    EXPECT_GE(shape_particle_bound(cylinder, 3, dx), area * 50.0);
    EXPECT_LE(shape_particle_bound(cylinder, 3, dx), 1.2 * area * 50.0);
    // A closed 3D tank, one layer: 12 x 22 x 32 lattice points less the 10 x 20 x 30 inside.
    grit::io::ShapeSpec tank = box;
    tank.kind = "tank";
    tank.layers = 1;
    EXPECT_DOUBLE_EQ(shape_particle_bound(tank, 3, dx), 12.0 * 22.0 * 32.0 - 6000.0);
    tank.open = {"top", "front"};  // z high and y low open: 12 x 21 x 31
    EXPECT_DOUBLE_EQ(shape_particle_bound(tank, 3, dx), 12.0 * 21.0 * 31.0 - 6000.0);
}

// A jet into the minimal case: 8 points across (diameter 0.125 m / 0.015625 m), 2 m/s from 0.1 s.
const std::string inlet =
    "[[inlet]]\nposition = [0.4, 0.2]\ndirection = [0.0, -1.0]\ndiameter = 0.125\n"
    "velocity = 2.0\nstart = 0.1\nmaterial = \"my_water\"\n\n[domain]";

TEST_F(CaseReaderTest, InletEstimateCountsEveryLayerUntilTheEnd) {
    // To 0.5 s: 1 + 51.2 -> 52 layers of 8.
    const CaseSpec c = read_ok(replaced(minimal_2d, "[domain]", inlet));
    EXPECT_DOUBLE_EQ(estimate_particles(c).inlets, 8.0 * 52.0);
    EXPECT_DOUBLE_EQ(estimate_particles(c).inlets_held, 8.0 * 52.0);
    EXPECT_DOUBLE_EQ(estimate_particles(read_ok(replaced(minimal_2d, "[domain]", inlet), {"inlet[0].stop=0.1"})).inlets, 0.0);
}

// An inlet run long emits far more particles than the domain holds; what is beyond its room has left
// through its faces or outlets, so neither the budget nor the run estimate counts it.
TEST_F(CaseReaderTest, InletEstimateHoldsNoMoreThanTheDomainsRoom) {
    const Overrides long_run = {"time.end=1e6", "output.interval=1e3"};
    const auto e = estimate_particles(read_ok(replaced(minimal_2d, "[domain]", inlet), long_run));
    EXPECT_GT(e.inlets, 1e9);
    // The domain, 0.75 x 0.625 m at 0.015625 m: 49 x 41 lattice points, +10 %; the blocks hold 264 of them.
    const double room = 1.1 * 49.0 * 41.0;
    EXPECT_DOUBLE_EQ(grit::io::domain_particle_room(read_ok(minimal_2d)), room);
    EXPECT_DOUBLE_EQ(e.inlets_held, room - 264.0);
    EXPECT_DOUBLE_EQ(e.total(), room);
    Overrides tight = long_run;
    tight.push_back("numerics.max_particles=2000");
    expect_error(replaced(minimal_2d, "[domain]", inlet), tight,
                 {"numerics.particle_spacing = 0.015625 m with inlets until time.end = 1000000 s", "about 2.2e+03",
                  "numerics.max_particles = 2000"});
}

// The paper's 30 ms of the abrasive jet on copper at the case's 0.1 mm emit 1.5 million water particles
// and 15,000 grains. Run (grit run cases/awj_copper_2d/case.toml --set time.end=0.03 --threads 1), it
// holds 5,603 particles and 12 grains at 0.1 ms (series.csv), and much the same through the run: the
// estimate stays above them and within three times.
TEST_F(CaseReaderTest, AbrasiveJetOverMillisecondsHoldsTheDomainNotWhatItEmits) {
    const fs::path file = fs::path(GRIT_SOURCE_DIR) / "cases" / "awj_copper_2d" / "case.toml";
    const auto e = estimate_particles(read_case(file, {"time.end=0.03", "output.interval=1e-4"}));
    EXPECT_GT(e.inlets, 1.4e6);
    EXPECT_GT(e.grains_fed, 1.4e4);
    EXPECT_GE(e.sph, 5603.0);
    EXPECT_LE(e.sph, 3.0 * 5603.0);
    // Garnet of 0.2 mm: 1.5 x (domain area / d^2) grains at most, a few thousand.
    EXPECT_GE(e.grains, 12.0);
    EXPECT_LE(e.grains, 1e4);
}

// What the run estimate counts (`grit check`'s wall time): the outlets drain the jet, so the domain holds
// what enters while a particle crosses it. The same run holds 5,600-6,000 particles and 12-24 grains at a
// time to 1.8 ms (docs/validation.md, "The AWJ on copper beyond 0.4 ms"): the particles in flight stay
// above that and within 1.5 times it; the grains, which leave slower than the water, within its range to
// three times its top.
TEST_F(CaseReaderTest, AbrasiveJetInFlightCountsAreWhatARunHolds) {
    const fs::path file = fs::path(GRIT_SOURCE_DIR) / "cases" / "awj_copper_2d" / "case.toml";
    const auto e = estimate_particles(read_case(file, {"time.end=0.03", "output.interval=1e-4"}));
    const double blocks = e.sph - e.inlets_held;
    std::printf("blocks %.0f + in flight %.0f (held %.0f); grains in flight %.0f (at most %.0f)\n", blocks,
                e.inlets_in_flight, e.inlets_held, e.grains_in_flight, e.grains);
    EXPECT_GE(blocks + e.inlets_in_flight, 6000.0);
    EXPECT_LE(blocks + e.inlets_in_flight, 1.5 * 6000.0);
    EXPECT_GE(e.grains_in_flight, 12.0);
    EXPECT_LE(e.grains_in_flight, 3.0 * 24.0);
    // Without outlets nothing drains: the in-flight counts are the held ones.
    const auto closed = estimate_particles(read_case(file, {"time.end=0.03", "output.interval=1e-4", "jet.side_outlets=false"}));
    EXPECT_DOUBLE_EQ(closed.inlets_in_flight, closed.inlets_held);
    EXPECT_DOUBLE_EQ(closed.grains_in_flight, closed.grains);
}

TEST_F(CaseReaderTest, TinySpacingIsRefusedNamingTheKeysAndTheCount) {
    // 0.25 x 0.125 m at 1e-12 m: 3.1e+22 fluid particles (the tank's two layers only ~2e+12).
    expect_error(minimal_2d, {"numerics.particle_spacing=1e-12"},
                 {"numerics.particle_spacing = 1e-12 m would make about 3.1e+22 particles (~1.6e+25 bytes)",
                  "numerics.max_particles = 20000000", "raise it"});
    expect_error(minimal_2d, {"numerics.particle_spacing=1e-320"},
                 {"numerics.particle_spacing = 1e-320 m", "more particles than a double can count", "numerics.max_particles"});
}

// Issue 16: a spacing in millimetres (0.05 for 0.05 mm) leaves a body a few particles across; the error
// names the key, the body and the unit. Three particles across still pass.
TEST_F(CaseReaderTest, BodyFewerThanThreeParticlesAcrossIsRefusedNamingTheUnit) {
    expect_error(minimal_2d, {"numerics.particle_spacing=0.05"},
                 {"key 'numerics.particle_spacing' = 0.05 m", "fluid[0] (box) is 0.125 m across at its thinnest",
                  "2.5 particles", "at least 3", "lengths are in metres"});
    EXPECT_NO_THROW(read_ok(minimal_2d, {"numerics.particle_spacing=0.041666"}));
}

TEST_F(CaseReaderTest, MaxParticlesBelowTheCountIsRefused) {
    expect_error(minimal_2d, {"numerics.max_particles=263"},
                 {"numerics.particle_spacing = 0.015625 m", "about 2.6e+02 particles", "numerics.max_particles = 263"});
    EXPECT_EQ(read_ok(minimal_2d, {"numerics.max_particles=264"}).max_particles, 264);
    // A finer spacing than the default limit allows, with the limit raised.
    const fs::path file = fs::path(GRIT_SOURCE_DIR) / "cases" / "dambreak_2d" / "case.toml";
    expect_error_file(file, {"numerics.particle_spacing=1e-5"}, {"numerics.particle_spacing = 1e-05 m", "numerics.max_particles"});
    EXPECT_NO_THROW((void)read_case(file, {"numerics.particle_spacing=1e-5", "numerics.max_particles=2000000000"}));
}

TEST_F(CaseReaderTest, BadMaxParticlesIsRefusedNamingTheKey) {
    expect_error(minimal_2d, {"numerics.max_particles=0"}, {"numerics.max_particles", "must lie in [1, 2147483647]"});
    expect_error(minimal_2d, {"numerics.max_particles=-1"}, {"numerics.max_particles", "-1", "must lie in"});
    expect_error(minimal_2d, {"numerics.max_particles=1.5"}, {"numerics.max_particles", "1.5", "must be an integer"});
    expect_error(minimal_2d, {"numerics.max_particles=x"}, {"numerics.max_particles", "\"x\"", "must be an integer"});
    expect_error(minimal_2d, {"numerics.max_particles=3000000000"}, {"numerics.max_particles", "must lie in"});
}

TEST_F(CaseReaderTest, GrainsCountTowardsTheBudget) {
    const std::string lattice = replaced(grains_2d, "arrangement = \"single\"\nposition = [0.0, 0.01]\n",
                                         "arrangement = \"lattice\"\nmin = [0.0, 0.0]\nmax = [0.01, 0.01]\nspacing = 0.001\n");
    const CaseSpec c = read_ok(lattice);
    EXPECT_DOUBLE_EQ(estimate_particles(c).grains, 100.0);
    expect_error(lattice, {"grains[0].spacing=1e-7"},
                 {"grains[0].spacing = 1e-07 m would make about 1.0e+10 grains", "numerics.max_particles = 20000000"});
    const std::string random = replaced(grains_2d, "arrangement = \"single\"\nposition = [0.0, 0.01]\n",
                                        "arrangement = \"random\"\nmin = [0.0, 0.0]\nmax = [0.05, 0.05]\ncount = 2\n");
    expect_error(random, {"numerics.max_particles=1"},
                 {"grains[0].count = 2 would make about 2.0e+00 grains", "numerics.max_particles = 1"});
}

// LIGGGHTS' chute: 0.1 kg/s of 3 and 5 mm glass every 0.01 s for 1 s. `grit run
// cases/chute_wear_3d/case.toml` feeds 1,329 grains (summary.json grains_fed); the estimate counts each
// insertion's mass in the smaller grains, plus one: above the real count, within three times.
TEST_F(CaseReaderTest, GrainFeedEstimateLiesAboveWhatItFeeds) {
    const fs::path file = fs::path(GRIT_SOURCE_DIR) / "cases" / "chute_wear_3d" / "case.toml";
    const auto e = estimate_particles(read_case(file));
    EXPECT_GE(e.grains_fed, 1329.0);
    EXPECT_LE(e.grains_fed, 3.0 * 1329.0);
    EXPECT_DOUBLE_EQ(e.grains, e.grains_fed);  // the LIGGGHTS box has room for many more
}

TEST_F(CaseReaderTest, DuplicateProbeName) {
    expect_error(replaced(minimal_2d, "name = \"front\"", "name = \"p_bottom\""), {},
                 {"probe[1].name", "\"p_bottom\"", "another probe"});
}

TEST_F(CaseReaderTest, MalformedOverride) {
    expect_error(minimal_2d, {"numerics.particle_spacing"}, {"--set 'numerics.particle_spacing'", "key.path=value"});
    expect_error(minimal_2d, {"=0.02"}, {"--set '=0.02'", "key.path=value"});
    expect_error(minimal_2d, {"fluid[3].velocity=[1.0, 0.0]"}, {"fluid[3]", "no table"});
    expect_error(minimal_2d, {"fluid[x].velocity=[1.0, 0.0]"}, {"fluid[x]", "bad index"});
    expect_error(minimal_2d, {"time.end.x=1"}, {"time.end.x=1", "'end' is not a table"});
    expect_error(minimal_2d, {"numerics..kernel=x"}, {"numerics..kernel", "empty key"});
}

}  // namespace

// A time.end in the wrong unit (seconds for microseconds) is caught by the number of outputs it implies.
TEST_F(CaseReaderTest, AbsurdNumberOfOutputsIsRefused) {
    expect_error(minimal_2d, {"time.end=2e4"}, {"key 'time.end' = 20000", "160001 outputs", "output.max_outputs = 100000"});
    (void)read_ok(minimal_2d, {"time.end=2e4", "output.max_outputs=1e6"});
}

// fluid.solver: the blocks carry it ([[fluid]] is an array of tables), --set reaches every block.
TEST_F(CaseReaderTest, FluidSolverDefaultsToWcsphAndSetReachesEveryBlock) {
    EXPECT_EQ(read_ok(minimal_2d).fluid_solver, "wcsph");
    const std::string two_blocks = minimal_2d + R"(
[[fluid]]
shape = "box"
min = [0.3, 0.0]
max = [0.35, 0.05]
material = "water"
)";
    const CaseSpec c = read_ok(two_blocks, {"fluid.solver=isph", "isph.tolerance=1e-7"});
    EXPECT_EQ(c.fluid_solver, "isph");
    EXPECT_DOUBLE_EQ(c.isph.tolerance, 1e-7);
    EXPECT_DOUBLE_EQ(c.isph.free_surface_divergence, 1.5);
    EXPECT_EQ(read_ok(two_blocks, {"fluid[1].solver=wcsph"}).fluid_solver, "wcsph");
}

TEST_F(CaseReaderTest, FluidSolverBadValuesAreRefused) {
    expect_error(minimal_2d, {"fluid.solver=implicit"}, {"'fluid[0].solver'", "\"implicit\"", "\"wcsph\", \"isph\""});
    const std::string two_blocks = minimal_2d + R"(
[[fluid]]
shape = "box"
min = [0.3, 0.0]
max = [0.35, 0.05]
material = "water"
)";
    expect_error(two_blocks, {"fluid.solver=isph", "fluid[1].solver=wcsph"},
                 {"'fluid[1].solver'", "\"wcsph\"", "differs from fluid[0].solver = \"isph\""});
    expect_error(minimal_2d, {"isph.tolerance=1e-7"}, {"'isph'", "fluid.solver = \"wcsph\""});
    expect_error(minimal_2d, {"fluid.solver=isph", "isph.tolerance=0.5"}, {"'isph.tolerance'", "0.5", "[1e-14, 0.01]"});
    expect_error(minimal_2d, {"fluid.solver=isph", "numerics.shepard_interval=10"},
                 {"'numerics.shepard_interval'", "10", "reference density"});
}

TEST_F(CaseReaderTest, IsphRefusesWhatItDoesNotIntegrate) {
    expect_error_file(fs::path(GRIT_SOURCE_DIR) / "cases/awj_copper_2d/case.toml", {"fluid.solver=isph"},
                      {"'fluid.solver'", "\"isph\"", "does not yet handle", "\"wcsph\""});
}

// Bitter's deformation factor: the built-in's is derived from Oka (20 m/s, 1 mm quartz); a material based on
// it with its own hardness re-derives it; "oka" derives it at the case's speed; a number is taken as given.
TEST(CaseReader, BitterDeformationFactorDerivedFromOkaOrGiven) {
    namespace wear = grit::wear;
    const fs::path sweep = fs::path(GRIT_SOURCE_DIR) / "cases/wear_angle_sweep_3d/case.toml";
    const Overrides hard = {"mesh[0].wear_model=bitter", "mesh[0].wear_material=\"hard\"",
                            "wear_materials.hard.based_on=\"steel\""};
    auto read = [&](Overrides more) {
        Overrides all = hard;
        all.insert(all.end(), more.begin(), more.end());
        return read_case(sweep, all).meshes.front().wear_material;
    };
    const auto steel = *wear::find_wear_material("steel");
    EXPECT_DOUBLE_EQ(read({}).bitter_deformation_factor, steel.bitter_deformation_factor);

    auto harder = steel;
    harder.vickers_hardness = 2.0;
    EXPECT_DOUBLE_EQ(read({"wear_materials.hard.vickers_hardness=2.0"}).bitter_deformation_factor,
                     wear::bitter_deformation_factor_from_oka(harder, 20.0, 1e-3));

    const auto at_jet = read({"wear_materials.hard.bitter_deformation_factor=\"oka\"",
                              "wear_materials.hard.bitter_calibration_speed=104.0"});
    EXPECT_DOUBLE_EQ(at_jet.bitter_deformation_factor, wear::bitter_deformation_factor_from_oka(steel, 104.0, 1e-3));
    EXPECT_EQ(at_jet.bitter_calibration_speed, 104.0);

    const auto given = read({"wear_materials.hard.bitter_deformation_factor=3e10"});
    EXPECT_EQ(given.bitter_deformation_factor, 3e10);
    EXPECT_TRUE(std::isnan(given.bitter_calibration_speed));
}

// An integer beyond 2^53 where a number is read (found by the case reader's fuzz target: it threw
// std::bad_optional_access, not an InputError): it is the nearest double, and checked like any number.
TEST_F(CaseReaderTest, IntegersBeyondTwoToThe53AreNumbers) {
    // Read as 8.9e17 s, then refused for what it asks: 7.1e18 outputs.
    expect_error(minimal_2d, {"time.end=888888888888888888"}, {"time.end", "888888888888888888", "outputs"});
    const auto spec = read_ok(minimal_2d, {"time.end=9007199254740993", "output.interval=9007199254740993"});
    EXPECT_EQ(spec.end_time, 9007199254740992.0);
    expect_error(minimal_2d, {"numerics.particle_spacing=-9007199254740993"}, {"numerics.particle_spacing", "must be"});
    expect_error(minimal_2d, {"domain.max=[9007199254740993, -9007199254740993]"}, {"domain.max"});
}

// What the symmetry plane refuses, each with its reason: a periodic x, a wall mesh across the plane that is
// not symmetric about it (jet_on_thin_plate_3d's plate: two triangles split by a diagonal). ISPH and mesh
// walls are taken (tests/validation/test_isph.cpp, tests/verification/test_symmetry_plane.cpp).
TEST_F(CaseReaderTest, SymmetryPlaneRefusalsNameTheirReason) {
    EXPECT_TRUE(read_ok(minimal_2d, {"domain.symmetry=[\"x\"]"}).symmetry_plane);
    expect_error(minimal_2d, {"domain.symmetry=[\"x\"]", "domain.periodic=[\"x\"]"},
                 {"'domain.symmetry'", "'domain.periodic'", "periodic and mirrored", "periodic copies"});
    EXPECT_TRUE(read_ok(minimal_2d, {"domain.symmetry=[\"x\"]", "fluid.solver=isph"}).symmetry_plane);
    EXPECT_TRUE(read_case(fs::path(GRIT_SOURCE_DIR) / "cases" / "wear_angle_sweep_3d" / "case.toml",
                          {"domain.symmetry=[\"x\"]"})
                    .symmetry_plane);
    expect_error_file(fs::path(GRIT_SOURCE_DIR) / "cases" / "jet_on_thin_plate_3d" / "case.toml",
                      {"domain.symmetry=[\"x\"]", "wall[0].thin=true"},
                      {"'wall[0].file'", "'domain.symmetry'", "must be symmetric about the plane x = 0",
                       "no mirror image"});
}
