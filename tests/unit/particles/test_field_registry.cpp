// The field registry moves every field together: growth, reordering, removal, copies, output.
#include <gtest/gtest.h>

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
