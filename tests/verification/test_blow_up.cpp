// A blow-up that a stage meets before the health check (a neighbour grid over a position that is not
// finite) is reported as the health check reports one: the step, the culprit and what is wrong with it.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "grit/core/error.hpp"
#include "grit/sim/simulation.hpp"
#include "support/case_fixture.hpp"

using grit::testing::in_memory;
using grit::testing::load_case;

TEST(BlowUp, MetInsideAStageNamesTheStepAndTheGrain) {
    grit::sim::Simulation<3> sim(load_case("sedimentation_3d/case.toml", {"time.end=0.01"}), in_memory());
    sim.advance_to(1e-5);
    sim.state().grains->grains().position()[0][2] = std::nan("");
    std::string message;
    try {
        sim.advance_to(2e-5);
    } catch (const grit::core::BlowUpError& e) {
        message = e.what();
    }
    EXPECT_NE(message.find("numerical blow-up at step"), std::string::npos) << message;
    EXPECT_NE(message.find("position is not finite"), std::string::npos) << message;
    EXPECT_NE(message.find("grain "), std::string::npos) << message;
    // The grid's own words follow, so the test checks the stage's path, not the health check's.
    EXPECT_NE(message.find("(particles spread over a region"), std::string::npos) << message;
}
