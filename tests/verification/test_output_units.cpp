// Every output value of every shipped case has a unit (summary.json's "units" map: sim/output_units.cpp
// and the modules that name their own), so that no series.csv column is left without one.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>

#include "grit/sim/output_units.hpp"
#include "support/case_fixture.hpp"

namespace {

template <int Dim>
void expect_units(const grit::io::CaseSpec& spec) {
    grit::sim::Simulation<Dim> sim(spec, grit::testing::in_memory());
    sim.prime();
    for (const auto& v : sim.output_values()) EXPECT_FALSE(v.unit.empty()) << "'" << v.name << "' has no unit";
}

}  // namespace

TEST(OutputUnits, EveryValueOfEveryCaseHasAUnit) {
    const auto cases = grit::testing::all_cases();
    ASSERT_GE(cases.size(), 10u);
    for (const auto& path : cases) {
        SCOPED_TRACE(path.string());
        const auto spec = grit::io::read_case(path);
        if (spec.dimension == 2)
            expect_units<2>(spec);
        else
            expect_units<3>(spec);
    }
    EXPECT_EQ(grit::sim::output_unit("eroded_mass", 2), "kg/m");
    EXPECT_EQ(grit::sim::output_unit("eroded_mass", 3), "kg");
    EXPECT_EQ(grit::sim::output_unit("wear_mass_floor", 3), "kg");
    EXPECT_EQ(grit::sim::output_unit("no_such_value", 3), "");
}
