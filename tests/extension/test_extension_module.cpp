// A module from outside grit's sources (tracer_module.cpp) is read, validated and run through the module
// catalog and the case-table registry: nothing in src/grit/sim or src/grit/io names it.
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "grit/core/error.hpp"
#include "grit/io/case_reader.hpp"
#include "grit/io/case_tables.hpp"
#include "grit/sim/module_catalog.hpp"
#include "grit/sim/simulation.hpp"
#include "support/case_text.hpp"
#include "tracer_module.hpp"

namespace grit::testing {
namespace {

namespace fs = std::filesystem;

const fs::path hydrostatic = fs::path(GRIT_SOURCE_DIR) / "cases" / "hydrostatic_2d" / "case.toml";

/// The hydrostatic tank with `table` appended, written to a temporary case file (removed at exit).
fs::path tank_with(const std::string& table) {
    static const struct Scratch {
        fs::path file = fs::temp_directory_path() / fmt::format("grit_tracer_{}.toml", ::getpid());
        ~Scratch() {
            std::error_code ignored;
            fs::remove(file, ignored);
        }
    } scratch;
    std::ifstream in(hydrostatic);
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    std::ofstream(scratch.file) << text << "\n" << table << "\n";
    return scratch.file;
}

const std::string tracer = "[tracer]\ncentre = [0.2, 0.15]\nradius = 0.05\n";

/// The message read_case throws for `file` (with `overrides`), or "" when it reads.
std::string refusal(const fs::path& file, const std::vector<std::string>& overrides = {}) {
    try {
        io::read_case(file, overrides);
    } catch (const core::InputError& e) {
        return e.what();
    }
    return "";
}

TEST(ExtensionModule, ItsTableIsReadIntoItsOwnSpec) {
    const auto spec = io::read_case(tank_with(tracer));
    const auto* t = spec.module_spec<TracerSpec>("tracer");
    ASSERT_NE(t, nullptr);
    EXPECT_EQ(t->centre, (std::vector<double>{0.2, 0.15}));
    EXPECT_EQ(t->radius, 0.05);
    EXPECT_EQ(t->phase, static_cast<int>(Phase::fluid));
    EXPECT_EQ(io::read_case(hydrostatic).module_spec<TracerSpec>("tracer"), nullptr);
    // --set reaches it as it reaches every table.
    EXPECT_EQ(io::read_case(tank_with(tracer), {"tracer.radius=0.08"}).module_spec<TracerSpec>("tracer")->radius, 0.08);
}

TEST(ExtensionModule, ItsKeysAreValidatedByTheSharedMachinery) {
    EXPECT_EQ(refusal(tank_with("[tracer]\ncentre = [0.2, 0.15]\nradius = -1.0\n")),
              "key 'tracer.radius' = -1: must be positive [m]");
    EXPECT_EQ(refusal(tank_with("[tracer]\ncentre = [0.2, 0.15]\nradius = 0.001\n")),
              "key 'tracer.radius' = 0.001: is less than numerics.particle_spacing = 0.01 m");
    EXPECT_EQ(refusal(tank_with(tracer + "radious = 0.1\n")),
              "key 'tracer.radious' = 0.1: unknown key (did you mean 'radius'?)");
    EXPECT_EQ(refusal(tank_with("[tracer]\ncentre = [0.2, 0.15]\n")), "key 'tracer.radius': is required");
    EXPECT_EQ(refusal(tank_with("[tracer]\ncentre = [0.2, 0.15, 0.0]\nradius = 0.05\n")),
              "key 'tracer.centre' = [0.2, 0.15, 0]: must be an array of 2 numbers [m] (the case is 2D)");
    EXPECT_EQ(refusal(tank_with("[tracr]\nradius = 0.05\n")), "key 'tracr': unknown key (a table; did you mean 'tracer'?)");
}

TEST(ExtensionModule, ItOwnsItsRulesAcrossTheCase) {
    EXPECT_EQ(refusal(tank_with("[tracer]\ncentre = [2.0, 0.15]\nradius = 0.05\n")),
              "key 'tracer.centre': the point lies outside domain.min/domain.max");
    EXPECT_EQ(refusal(tank_with(tracer + "phase = \"solid\"\n")), "key 'tracer.phase' = \"solid\": the case has no [[solid]]");
}

TEST(ExtensionModule, ItRunsAsAStageOfTheOnePipeline) {
    auto spec = io::read_case(tank_with(tracer), {"time.end=0.01"});
    sim::RunOptions options;
    options.write_files = false;
    sim::Simulation<2> s(spec, options);
    bool found = false;
    for (const auto& stage : s.pipeline().stages())
        if (stage.name == "tracer_count") {
            found = true;
            EXPECT_EQ(stage.module, "tracer");
            EXPECT_EQ(stage.hook, sim::Hook::end_step);
        }
    EXPECT_TRUE(found);
    s.advance_to(0.01);
    EXPECT_GT(s.steps(), 0);
    // The count it reports is the particles' own, counted here by brute force.
    const auto& ps = s.particles();
    Index expected = 0;
    for (Index i = 0; i < ps.size(); ++i)
        if (ps.phase()[i] == static_cast<std::int32_t>(Phase::fluid) &&
            std::hypot(ps.position()[i][0] - 0.2, ps.position()[i][1] - 0.15) <= 0.05)
            ++expected;
    EXPECT_GT(expected, 60);  // pi 0.05^2 / 0.01^2 = 78 lattice sites
    double reported = -1.0;
    for (const auto& v : s.output_values())
        if (v.name == "tracer_particles") {
            reported = v.value;
            EXPECT_EQ(v.unit, "1");
        }
    EXPECT_EQ(reported, static_cast<double>(expected));
}

TEST(ExtensionModule, TheCatalogRefusesASecondModuleOfTheSameName) {
    register_tracer();  // idempotent
    io::CaseTable again{"tracer",
                        [](const io::Section&, const io::CaseSpec&) { return std::shared_ptr<const io::ModuleSpec>(); },
                        {}};
    EXPECT_THROW(io::register_case_table(again), std::logic_error);
    sim::ModuleDescriptor<2> twin{"tracer", sim::BuildTime::after_particles, {}, {}, {}};
    EXPECT_THROW(sim::register_module<2>(twin), std::logic_error);
}

}  // namespace
}  // namespace grit::testing
