// The grain-particle penalty contact (first seed paper eqs. 12-14) integrated with grit's leap-frog,
// grain and SPH particle alone: reference, a head-on collision of two free bodies through a spring with
// omega^2 dt^2 = 2 (a quarter turn per step) leaves them with their relative speed reversed exactly
// (elastic) and their momentum unchanged, whatever their mass ratio. Eq. (13) as printed has
// omega^2 dt^2 = 2 (1 + m_a / M) and diverges once the particle outweighs the grain.
#include <gtest/gtest.h>

#include <cmath>

#include "grit/coupling/grain_boundary_contact.hpp"
#include "grit/dem/grain_material.hpp"

namespace {

using grit::Index;
using grit::Phase;
using grit::core::Vec;

struct Collision {
    double energy_ratio = 0.0;    // kinetic energy after / before
    double momentum_error = 0.0;  // |p_after - p_before| / |p_before|
    int contact_steps = 0;
};

// A garnet disc (d = 0.2 mm, 2D: kg/m) at 500 m/s straight down onto one free solid particle of
// `mass_ratio` times its mass, d_ini = 0.1 mm below its surface less one step's travel; leap-frog with
// the same dt for both (as the SPH and grain modules step them), until they separate.
Collision head_on(double mass_ratio, int touching_particles = 1) {
    const double dt = 1.0e-9, d_ini = 1.0e-4, speed = 500.0;
    grit::dem::GrainSet<2> grains;
    const auto garnet = grit::dem::garnet();
    grains.add({{0.0, 0.0}}, 1.0e-4, garnet, 0, {{0.0, -speed}});
    const double M = grains.mass()[0];
    grit::particles::SphParticles<2> particles;
    particles.append(touching_particles);
    for (Index a = 0; a < touching_particles; ++a) {
        // Particles side by side on the circle the grain's surface + d_ini will reach first.
        const double angle = (a - 0.5 * (touching_particles - 1)) * 0.3;
        const double r = 1.0e-4 + d_ini + 0.6 * speed * dt;
        particles.position()[a] = {{r * std::sin(angle), -r * std::cos(angle)}};
        particles.velocity()[a] = Vec<2>::zero();
        particles.mass()[a] = mass_ratio * M / touching_particles;
        particles.phase()[a] = static_cast<std::int32_t>(Phase::solid);
    }
    auto momentum = [&] {
        Vec<2> p = grains.velocity()[0] * M;
        for (Index a = 0; a < touching_particles; ++a) p += particles.velocity()[a] * particles.mass()[a];
        return p;
    };
    auto energy = [&] {
        double e = 0.5 * M * grit::core::norm2(grains.velocity()[0]);
        for (Index a = 0; a < touching_particles; ++a)
            e += 0.5 * particles.mass()[a] * grit::core::norm2(particles.velocity()[a]);
        return e;
    };
    const Vec<2> p0 = momentum();
    const double e0 = energy();

    grit::coupling::PenaltyContactParameters parameters;
    parameters.spacing = d_ini;
    parameters.friction = 0.0;
    grit::coupling::GrainBoundaryContact<2> contact(parameters);
    Collision result;
    bool touched = false;
    for (int step = 0; step < 200; ++step) {
        grains.force()[0] = Vec<2>::zero();
        for (Index a = 0; a < touching_particles; ++a) particles.acceleration()[a] = Vec<2>::zero();
        contact.compute(grains, particles, dt);
        bool touching = false;
        for (const auto& c : contact.contacts()) touching = touching || c.touching;
        if (touching) ++result.contact_steps;
        if (touched && !touching) break;
        touched = touched || touching;
        contact.apply(grains, particles, nullptr);
        grains.velocity()[0] += grains.force()[0] * (dt / M);
        grains.position()[0] += grains.velocity()[0] * dt;
        for (Index a = 0; a < touching_particles; ++a) {
            particles.velocity()[a] += particles.acceleration()[a] * dt;
            particles.position()[a] += particles.velocity()[a] * dt;
        }
    }
    result.energy_ratio = energy() / e0;
    result.momentum_error = std::sqrt(grit::core::norm2(momentum() - p0) / grit::core::norm2(p0));
    return result;
}

TEST(GrainParticleContact, HeadOnCollisionIsElasticAtAnyMassRatio) {
    // 0.1: eq. (13)'s own regime (a heavy grain); 0.7: a copper particle at 0.1 mm spacing against a
    // 0.2 mm garnet grain in 2D; 2 and 10: coarser still. Eq. (13) as printed ends these four collisions
    // with 1.004, 0.69, 1.64 and 55 times the energy.
    for (const double ratio : {0.1, 0.7, 2.0, 10.0}) {
        const Collision c = head_on(ratio);
        EXPECT_NEAR(c.energy_ratio, 1.0, 1e-9) << "m_a / M = " << ratio;
        EXPECT_LT(c.momentum_error, 1e-12) << "m_a / M = " << ratio;
        EXPECT_GT(c.contact_steps, 0) << "m_a / M = " << ratio;
        EXPECT_LE(c.contact_steps, 3) << "the overlap is removed within a step or two; m_a / M = " << ratio;
    }
}

TEST(GrainParticleContact, SeveralParticlesAsHeavyAsTheGrainDoNotGainEnergy) {
    // Three particles on the grain's path together outweighing it 3 to 1, touched at once: the grain's
    // share keeps the stiff mode stable; with eq. (13) as printed the three push it out with 3.0 times
    // the energy it brought.
    for (const double ratio : {1.0, 3.0}) {
        const Collision c = head_on(ratio, 3);
        EXPECT_LT(c.energy_ratio, 1.0 + 1e-9) << "m_a / M = " << ratio;
        EXPECT_GT(c.energy_ratio, 0.5) << "m_a / M = " << ratio;
        EXPECT_LT(c.momentum_error, 1e-12) << "m_a / M = " << ratio;
    }
}

}  // namespace
