// The field registry moves every field together: growth, reordering, removal, copies, output.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "grit/particles/sph_particles.hpp"

using grit::Index;
using grit::particles::SphParticles;

TEST(FieldRegistry, GatherReordersAndRemovesEveryField) {
    SphParticles<2> ps;
    auto& temperature = ps.fields().add<double>("temperature", 293.0, true);
    ps.append(4);
    for (Index i = 0; i < 4; ++i) {
        ps.position()[i] = {{1.0 * i, 0.0}};
        ps.mass()[i] = 10.0 + i;
        temperature[i] = 300.0 + i;
    }
    ps.gather({3, 1, 0});  // particle 2 removed, the rest reordered
    ASSERT_EQ(ps.size(), 3);
    EXPECT_EQ(ps.position()[0][0], 3.0);
    EXPECT_EQ(ps.mass()[1], 11.0);
    EXPECT_EQ(ps.fields().get<double>("temperature")[2], 300.0);
    ps.append(1);
    EXPECT_EQ(ps.fields().get<double>("temperature")[3], 293.0);  // new particles take the fill value
}

TEST(FieldRegistry, CopiesAreDeepAndOutputListsFlaggedFields) {
    SphParticles<3> ps;
    ps.append(2);
    ps.density()[0] = 1000.0;
    SphParticles<3> copy = ps;
    ps.density()[0] = 5.0;
    EXPECT_EQ(copy.density()[0], 1000.0);
    const auto cloud = copy.snapshot();
    EXPECT_EQ(cloud.size(), 2u);
    bool has_velocity = false, has_acceleration = false;
    for (const auto& a : cloud.arrays) {
        has_velocity |= a.name == "velocity" && a.components == 3;
        has_acceleration |= a.name == "acceleration";
    }
    EXPECT_TRUE(has_velocity);
    EXPECT_FALSE(has_acceleration);
}

TEST(FieldRegistry, SameNameWithAnotherTypeIsALogicError) {
    SphParticles<2> ps;
    EXPECT_THROW(ps.fields().add<std::int32_t>("density", 0, false), std::logic_error);
    EXPECT_NO_THROW(ps.fields().add<double>("density", 0.0, true));
}

// A solid-only field is NaN on the water in snapshots (ParaView then leaves the water out of its colour
// range); integer fields and fields without a scope are written everywhere. The scope survives copies.
TEST(FieldRegistry, OutputScopeWritesNaNWhereAFieldMeansNothing) {
    SphParticles<2> ps;
    auto& temperature = ps.fields().add<double>("temperature", 293.0, true);
    auto& stress = ps.fields().add<grit::core::SymTensor3>("deviatoric_stress", grit::core::SymTensor3::zero(), true);
    const auto solid = static_cast<std::int32_t>(grit::Phase::solid);
    for (const char* name : {"temperature", "deviatoric_stress"})
        ps.fields().base(name).set_output_scope([solid](std::int32_t phase, std::int32_t) { return phase == solid; });
    ps.append(3);
    ps.phase()[1] = solid;
    temperature[1] = 400.0;
    stress[1].xx = 5.0;
    const SphParticles<2> copy = ps;
    const auto cloud = copy.snapshot();
    auto array = [&cloud](const std::string& name) {
        for (const auto& a : cloud.arrays)
            if (a.name == name) return a;
        ADD_FAILURE() << "no array " << name;
        return grit::io::PointArray{};
    };
    const auto t = array("temperature");
    EXPECT_TRUE(std::isnan(t.real[0]));
    EXPECT_EQ(t.real[1], 400.0);
    EXPECT_TRUE(std::isnan(t.real[2]));
    const auto s = array("deviatoric_stress");
    ASSERT_EQ(s.real.size(), 18u);
    for (int k = 0; k < 6; ++k) {
        EXPECT_TRUE(std::isnan(s.real[static_cast<std::size_t>(k)]));
        EXPECT_FALSE(std::isnan(s.real[6 + static_cast<std::size_t>(k)]));
    }
    EXPECT_EQ(s.real[6], 5.0);
    EXPECT_EQ(array("density").real[0], 0.0);         // no scope: written on every particle
    EXPECT_EQ(array("phase").integer[1], solid);       // integer fields have no NaN
    EXPECT_EQ(ps.fields().get<double>("temperature")[0], 293.0);  // the state itself keeps its values
}
