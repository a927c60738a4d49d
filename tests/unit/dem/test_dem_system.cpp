// DemSystem: equal and opposite pair forces bit for bit, contact history through re-sorting, thread
// independence, momentum of a closed cloud, grain removal.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <numeric>
#include <random>
#include <utility>
#include <vector>

#include "grit/dem/dem_system.hpp"
#include "grit/dem/grain_fill.hpp"
#include "grit/parallel/parallel.hpp"

using namespace grit::dem;
using grit::Index;
using grit::domain::ParticleId;
using grit::core::Vec;

namespace {

GrainMaterial soft_glass() { return {"soft_glass", 2500.0, 5e6, 0.45, 0.5, 0.3, 0.0}; }

/// Spheres of 3 mm on a jittered lattice in a box periodic in x and y, falling onto a plane at z = 0:
/// a small version of the settling benchmark.
DemSystem<3> settling_box(const std::string& law, int n_side, double s = 0.0033) {
    DemParameters<3> p;
    p.contact_law = law;
    p.gravity = {{0.0, 0.0, -9.81}};
    p.skin = 0.001;
    const double length = n_side * s;
    p.domain.periodic = {true, true, false};
    p.domain.lower = {{0.0, 0.0, 0.0}};
    p.domain.upper = {{length, length, 1.0}};
    DemSystem<3> sys(p, {soft_glass()});
    const auto seeds = lattice_fill<3>(Vec<3>{{0.0, 0.0, 0.0}}, Vec<3>{{length, length, 4 * s}}, s,
                                       FixedSize{0.003}, 11, 0.0003);
    for (const auto& g : seeds) sys.add_grain(g.position, 0.5 * g.diameter, 0);
    sys.add_wall({Vec<3>{{0.0, 0.0, 0.0}}, Vec<3>{{0.0, 0.0, 1.0}}, 0});
    return sys;
}

/// Tangential history of every listed pair, keyed by (grain id, partner id).
std::map<std::pair<ParticleId, ParticleId>, std::array<double, 3>> history_by_ids(const DemSystem<3>& sys) {
    std::map<std::pair<ParticleId, ParticleId>, std::array<double, 3>> m;
    const auto& pairs = sys.pairs();
    const ParticleId* id = sys.grains().id();
    for (Index i = 0; i < pairs.particle_count(); ++i)
        for (Index k = pairs.upper_begin(i); k < pairs.upper_end(i); ++k) {
            const Vec<3>& v = sys.contact_history().values()[k];
            if (grit::core::norm2(v) == 0.0) continue;
            // As seen from the grain of lower id: the pair's own grain (lower index) may be either.
            const int a = id[i], b = id[pairs.upper()[k]];
            if (a < b)
                m[{a, b}] = {v[0], v[1], v[2]};
            else
                m[{b, a}] = {-v[0], -v[1], -v[2]};
        }
    return m;
}

/// Positions by grain id.
std::map<ParticleId, Vec<3>> positions_by_id(const DemSystem<3>& sys) {
    std::map<ParticleId, Vec<3>> m;
    for (Index i = 0; i < sys.grains().size(); ++i) m[sys.grains().id()[i]] = sys.grains().position()[i];
    return m;
}

}  // namespace

TEST(DemSystem, PairForcesAreEqualAndOppositeBitForBit) {
    for (const char* law : {"linear", "hertz"}) {
        DemParameters<3> p;
        p.contact_law = law;
        DemSystem<3> sys(p, {soft_glass()});
        sys.add_grain(Vec<3>{{0.0, 0.0, 0.0}}, 0.0015, 0, Vec<3>{{0.1, 0.02, -0.03}});
        sys.add_grain(Vec<3>{{0.0025, 0.0003, 0.0001}}, 0.0012, 0, Vec<3>{{-0.1, 0.05, 0.01}});
        sys.grains().angular_velocity()[0] = Vec<3>{{3.0, -1.0, 2.0}};
        for (int k = 0; k < 5; ++k) sys.step(1e-6, k * 1e-6);
        const Vec<3>* f = sys.grains().force();
        ASSERT_GT(grit::core::norm(f[0]), 0.0) << law;
        for (int c = 0; c < 3; ++c) EXPECT_EQ(f[0][c], -f[1][c]) << law;
        EXPECT_GT(sys.contact_history().active_pairs(), 0u);
    }
}

// Shuffling the grains (and so rebuilding the lists in another order) must carry every tangential
// history over by ids: one step later the histories are bit-identical to an unshuffled run (they
// depend only on positions and velocities, which the shuffle does not touch), and the motion stays the
// same to round-off (force sums are added in another order).
TEST(DemSystem, ContactHistorySurvivesReSorting) {
    DemSystem<3> a = settling_box("hertz", 6), b = settling_box("hertz", 6);
    for (int k = 0; k < 3000; ++k) a.step(1e-5, k * 1e-5), b.step(1e-5, k * 1e-5);
    ASSERT_GT(a.contact_history().active_pairs(), 50u);
    std::vector<Index> shuffle(static_cast<std::size_t>(b.grains().size()));
    std::iota(shuffle.begin(), shuffle.end(), 0);
    std::shuffle(shuffle.begin(), shuffle.end(), std::mt19937_64(5));
    b.gather(shuffle);
    a.step(1e-5, 3000 * 1e-5);
    b.step(1e-5, 3000 * 1e-5);
    const auto ha = history_by_ids(a), hb = history_by_ids(b);
    EXPECT_EQ(ha.size(), hb.size());
    for (const auto& [key, v] : ha) {
        const auto it = hb.find(key);
        ASSERT_NE(it, hb.end()) << "pair " << key.first << "-" << key.second << " lost its history";
        for (int c = 0; c < 3; ++c)
            EXPECT_EQ(v[c], it->second[c]) << "pair " << key.first << "-" << key.second << " component " << c;
    }
    for (int k = 3001; k < 3501; ++k) a.step(1e-5, k * 1e-5), b.step(1e-5, k * 1e-5);
    const auto pa = positions_by_id(a), pb = positions_by_id(b);
    double worst = 0.0;
    for (const auto& [id, x] : pa) worst = std::max(worst, grit::core::norm(x - pb.at(id)));
    EXPECT_LT(worst, 1e-12);  // round-off, against a grain diameter of 3e-3 m
}

TEST(DemSystem, OneAndTwoThreadsGiveIdenticalGrains) {
    std::vector<std::map<ParticleId, Vec<3>>> results;
    for (int threads : {1, 2}) {
        grit::parallel::set_threads(threads);
        // 2,304 grains, above parallel::serial_below, over 17 slabs of cells: the pair pass runs its
        // coloured blocks (SlabBlocks) in parallel. A lattice of 2.9 mm for 3 mm grains: every grain
        // touches its neighbours from the first step.
        DemSystem<3> sys = settling_box("hertz", 24, 0.0029);
        for (int k = 0; k < 200; ++k) sys.step(1e-5, k * 1e-5);
        ASSERT_GE(sys.grains().size(), grit::parallel::serial_below);
        ASSERT_GE(sys.neighbors().slab_starts().size(), 7u);
        ASSERT_GT(sys.contact_history().active_pairs(), 2000u);
        results.push_back(positions_by_id(sys));
    }
    grit::parallel::set_threads(2);
    for (const auto& [id, x] : results[0])
        for (int c = 0; c < 3; ++c) ASSERT_EQ(x[c], results[1].at(id)[c]) << "grain " << id;
}

// A closed cloud (periodic on all axes, no gravity, no walls): pair forces cancel exactly, so the total
// momentum changes only by the round-off of the per-grain sums.
TEST(DemSystem, MomentumOfAClosedCloudIsConserved) {
    for (const char* law : {"linear", "hertz"}) {
        DemParameters<3> p;
        p.contact_law = law;
        p.skin = 0.0005;
        p.domain.periodic = {true, true, true};
        p.domain.upper = {{0.03, 0.03, 0.03}};
        DemSystem<3> sys(p, {soft_glass()});
        std::mt19937_64 rng(9);
        std::uniform_real_distribution<double> u(-1.0, 1.0);
        const auto seeds =
            lattice_fill<3>(Vec<3>::zero(), Vec<3>::filled(0.03), 0.0032, UniformSize{0.0025, 0.0031}, 4, 0.0001);
        for (const auto& g : seeds) sys.add_grain(g.position, 0.5 * g.diameter, 0, Vec<3>{{u(rng), u(rng), u(rng)}});
        auto momentum = [&]() {
            Vec<3> m = Vec<3>::zero();
            double scale = 0.0;
            for (Index i = 0; i < sys.grains().size(); ++i) {
                m += sys.grains().velocity()[i] * sys.grains().mass()[i];
                scale += grit::core::norm(sys.grains().velocity()[i]) * sys.grains().mass()[i];
            }
            return std::pair{m, scale};
        };
        const auto [p0, scale] = momentum();
        for (int k = 0; k < 2000; ++k) sys.step(2e-6, k * 2e-6);
        EXPECT_GT(sys.counters().rebuilds, 1);
        const auto [p1, scale1] = momentum();
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(p1[c], p0[c], 1e-13 * scale) << law;
        EXPECT_LT(scale1, scale);  // collisions with e = 0.3 dissipate
    }
}

TEST(DemSystem, RemovingGrainsKeepsTheOthersHistory) {
    DemSystem<3> sys = settling_box("linear", 5);
    for (int k = 0; k < 3000; ++k) sys.step(1e-5, k * 1e-5);
    const auto before = history_by_ids(sys);
    std::vector<Index> keep;
    for (Index i = 0; i < sys.grains().size(); ++i)
        if (sys.grains().id()[i] % 7 != 0) keep.push_back(i);
    sys.gather(keep);
    sys.compute_forces(0.0, 3000 * 1e-5);  // rebuilds the lists; dt = 0 leaves the histories as they were
    const auto after = history_by_ids(sys);
    ASSERT_FALSE(after.empty());
    for (const auto& [ids, v] : after) {
        ASSERT_NE(ids.first % 7, 0);
        ASSERT_NE(ids.second % 7, 0);
        ASSERT_TRUE(before.count(ids));
    }
    EXPECT_EQ(sys.grains().size(), static_cast<Index>(keep.size()));
}

// Two discs closing head-on touch for many steps: each counts one collision, as the contact begins,
// not one a step, and not again when the forces are evaluated twice at the same state (dt = 0). Sent
// back at each other once apart, each counts a second.
TEST(DemSystem, CountsACollisionOnceAsItsContactBegins) {
    DemParameters<2> p;
    DemSystem<2> sys(p, {soft_glass()});
    const double r = 0.0015;
    sys.add_grain(Vec<2>{{-r - 1e-5, 0.0}}, r, 0, Vec<2>{{0.05, 0.0}});
    sys.add_grain(Vec<2>{{r + 1e-5, 0.0}}, r, 0, Vec<2>{{-0.05, 0.0}});
    const auto& g = sys.grains();
    auto gap = [&] { return std::abs(g.position()[1][0] - g.position()[0][0]) - 2.0 * r; };
    const double dt = 1e-6;
    double t = 0.0;
    auto step = [&] {
        sys.step(dt, t);
        t += dt;
    };
    for (int round = 1; round <= 2; ++round) {
        int steps_in_contact = 0;
        while (gap() > 0.0) step();  // closing
        while (gap() <= 0.0) {       // touching
            ++steps_in_contact;
            sys.compute_forces(0.0, t);
            for (Index i = 0; i < 2; ++i) {
                ASSERT_EQ(g.collisions()[i], round) << "grain " << i << ", step " << steps_in_contact;
                ASSERT_EQ(g.grain_contact()[i], 1);
            }
            step();
        }
        step();  // apart: the next pass sees it
        EXPECT_GT(steps_in_contact, 10);
        for (Index i = 0; i < 2; ++i) {
            EXPECT_EQ(g.collisions()[i], round);
            EXPECT_EQ(g.grain_contact()[i], 0);
        }
        // Back towards each other.
        for (Index i = 0; i < 2; ++i) sys.grains().velocity()[i] = sys.grains().velocity()[i] * -1.0;
    }
}

// With grain_pairs = false (dem.grain_grain_contact) the two discs pass through each other unchanged
// and count no collision.
TEST(DemSystem, GrainsWithoutPairContactPassThroughEachOther) {
    DemParameters<2> p;
    p.grain_pairs = false;
    DemSystem<2> sys(p, {soft_glass()});
    const double r = 0.0015;
    sys.add_grain(Vec<2>{{-r - 1e-5, 0.0}}, r, 0, Vec<2>{{1.0, 0.0}});
    sys.add_grain(Vec<2>{{r + 1e-5, 0.0}}, r, 0, Vec<2>{{-1.0, 0.0}});
    for (int k = 0; k < 2000; ++k) sys.step(1e-6, k * 1e-6);  // 2 mm of travel each: through and past each other
    const auto& g = sys.grains();
    for (Index i = 0; i < 2; ++i) {
        const double v0 = g.id()[i] == 0 ? 1.0 : -1.0;
        EXPECT_EQ(g.velocity()[i][0], v0);
        EXPECT_EQ(g.collisions()[i], 0);
        EXPECT_EQ(g.grain_contact()[i], 0);
    }
    const Index first = g.id()[0] == 0 ? 0 : 1;
    EXPECT_GT(g.position()[first][0], g.position()[1 - first][0]);  // crossed
}

// Through the settling box's list rebuilds and re-sorts each grain's contact flag is what the geometry
// says (it touches another grain), and it has counted at least as many collisions as it has contacts.
TEST(DemSystem, ContactFlagsFollowTheGrainsThroughReSorting) {
    DemSystem<3> sys = settling_box("hertz", 6);
    for (int k = 0; k < 3000; ++k) sys.step(1e-5, k * 1e-5);
    ASSERT_GT(sys.counters().rebuilds, 3);
    const auto& g = sys.grains();
    const Index n = g.size();
    std::int64_t touching = 0, collisions = 0;
    for (Index i = 0; i < n; ++i) {
        int contacts = 0;
        for (Index j = 0; j < n; ++j) {
            if (j == i) continue;
            const double reach = g.radius()[i] + g.radius()[j];
            contacts += grit::core::norm2(sys.parameters().domain.nearest_image(g.position()[j] - g.position()[i])) <
                        reach * reach;
        }
        ASSERT_EQ(g.grain_contact()[i], contacts > 0 ? 1 : 0) << "grain " << g.id()[i];
        ASSERT_GE(g.collisions()[i], g.grain_contact()[i]);
        touching += contacts > 0;
        collisions += g.collisions()[i];
    }
    EXPECT_GT(touching, n / 2);  // a settled bed
    EXPECT_GE(collisions, touching);
}

TEST(DemSystem, RejectsBadInput) {
    DemParameters<2> p;
    EXPECT_THROW(DemSystem<2>(p, {}), grit::core::InputError);
    p.contact_law = "hooke";
    EXPECT_THROW(DemSystem<2>(p, {garnet()}), grit::core::InputError);
    p.contact_law = "linear";
    DemSystem<2> sys(p, {garnet()});
    EXPECT_THROW(sys.add_grain(Vec<2>::zero(), 0.0, 0), grit::core::InputError);
    EXPECT_THROW(sys.add_grain(Vec<2>::zero(), 1e-4, 3), grit::core::InputError);
    EXPECT_THROW(sys.add_wall({Vec<2>::zero(), Vec<2>::zero(), 0}), grit::core::InputError);
}

// A symmetry plane for grains (modules/symmetry_plane): a grain meets its mirror twin there, the two
// surfaces moving together along the plane, so the plane holds the grain without friction: an oblique
// impact keeps the tangential velocity and starts no spin, where a plane of the same material with
// friction slows the sliding and spins the grain.
TEST(DemSystem, FrictionlessPlaneKeepsTheTangentialVelocity) {
    for (const bool frictionless : {true, false}) {
        SCOPED_TRACE(frictionless ? "frictionless" : "with friction");
        DemParameters<2> p;
        DemSystem<2> sys(p, {soft_glass()});
        const double r = 0.0015;
        sys.add_wall({Vec<2>::zero(), Vec<2>{{1.0, 0.0}}, 0, frictionless});
        sys.add_grain(Vec<2>{{r + 1e-5, 0.0}}, r, 0, Vec<2>{{-0.5, 0.5}});
        const auto& g = sys.grains();
        bool touched = false;
        for (int k = 0; k < 20000 && !(touched && g.position()[0][0] > r + 1e-5); ++k) {
            sys.step(1e-7, k * 1e-7);
            touched |= g.position()[0][0] < r;
        }
        ASSERT_TRUE(touched);
        EXPECT_GT(g.velocity()[0][0], 0.0);  // bounced off
        if (frictionless) {
            EXPECT_EQ(g.velocity()[0][1], 0.5);
            EXPECT_EQ(g.angular_velocity()[0], 0.0);
        } else {
            EXPECT_LT(g.velocity()[0][1], 0.5 - 1e-3);
            EXPECT_NE(g.angular_velocity()[0], 0.0);
        }
    }
}

// A grain flagged as straddling the frictionless plane (a grain on the jet's axis) passes it untouched;
// the plane still holds the others.
TEST(DemSystem, FrictionlessPlaneLetsStraddlingGrainsPass) {
    DemParameters<2> p;
    DemSystem<2> sys(p, {soft_glass()});
    const double r = 0.0015;
    sys.add_wall({Vec<2>::zero(), Vec<2>{{1.0, 0.0}}, 0, true});
    sys.grains().fields().add<std::int32_t>(straddling_field, 0, false);
    sys.add_grain(Vec<2>{{0.5 * r, 0.0}}, r, 0, Vec<2>{{-0.5, 0.0}});
    sys.add_grain(Vec<2>{{0.5 * r, 0.01}}, r, 0, Vec<2>{{-0.5, 0.0}});
    const auto& g = sys.grains();
    const Index flagged = g.id()[0] == 0 ? 0 : 1;
    sys.grains().fields().get<std::int32_t>(straddling_field)[flagged] = 1;
    const ParticleId flagged_id = g.id()[flagged];
    for (int k = 0; k < 100; ++k) sys.step(1e-6, k * 1e-6);
    const Index a = g.id()[0] == flagged_id ? 0 : 1;
    EXPECT_EQ(g.velocity()[a][0], -0.5);
    EXPECT_GT(g.velocity()[1 - a][0], 0.0);  // pushed out
}

// The step's phases, called as a run's stages call them (kick, drift, lists, forces), give step()'s grains
// bit for bit: step() is the same phases with the second half kick inside the force pass.
TEST(DemSystem, PhasesAsStagesAreTheFusedStep) {
    DemSystem<3> fused = settling_box("hertz", 5), staged = settling_box("hertz", 5);
    const double dt = 1e-5;
    staged.compute_forces(0.0, 0.0);
    for (int k = 0; k < 2000; ++k) {
        fused.step(dt, k * dt);
        if (k > 0) staged.kick(dt);
        staged.drift(dt, k * dt);
        staged.update_neighbors();
        staged.compute_contact_forces(dt, (k + 1) * dt);
    }
    staged.kick(dt);
    ASSERT_GT(fused.contact_pairs(), 20u);
    EXPECT_EQ(fused.counters().rebuilds, staged.counters().rebuilds);
    const auto a = positions_by_id(fused), b = positions_by_id(staged);
    for (const auto& [id, x] : a)
        for (int c = 0; c < 3; ++c) ASSERT_EQ(x[c], b.at(id)[c]) << "grain " << id << " component " << c;
}

// A stage between the phases is felt as the grains' own forces are: weight added after the contact forces
// (as the coupling adds drag) settles the bed as gravity inside the force pass does, to round-off (the
// same terms added in another order).
TEST(DemSystem, AForceAddedBetweenThePhasesActsAsTheGrainsOwn) {
    DemSystem<3> inside = settling_box("hertz", 5);
    DemParameters<3> p = inside.parameters();
    const grit::core::Vec<3> g = p.gravity;
    p.gravity = Vec<3>::zero();
    DemSystem<3> outside(p, {soft_glass()});
    for (Index i = 0; i < inside.grains().size(); ++i)
        outside.add_grain(inside.grains().position()[i], inside.grains().radius()[i], 0);
    outside.add_wall(inside.walls().front());
    auto add_weight = [&] {
        auto& grains = outside.grains();
        for (Index i = 0; i < grains.size(); ++i) grains.force()[i] += g * grains.mass()[i];
    };
    const double dt = 1e-5;
    inside.compute_forces(0.0, 0.0);
    outside.compute_forces(0.0, 0.0);
    add_weight();
    for (int k = 0; k < 400; ++k) {
        for (auto* s : {&inside, &outside}) {
            if (k > 0) s->kick(dt);
            s->drift(dt, k * dt);
            s->update_neighbors();
            s->compute_contact_forces(dt, (k + 1) * dt);
        }
        add_weight();
    }
    // 400 steps of 10 us: 7.8 mm of fall from rest, and the lowest layer on the plane.
    const auto a = positions_by_id(inside), b = positions_by_id(outside);
    double worst = 0.0, lowest = 1.0;
    for (const auto& [id, x] : a) {
        worst = std::max(worst, grit::core::norm(x - b.at(id)));
        lowest = std::min(lowest, x[2]);
    }
    EXPECT_LT(lowest, 0.0016);  // the first layer touches the plane (radius 1.5 mm)
    EXPECT_LT(worst, 1e-12);
}
