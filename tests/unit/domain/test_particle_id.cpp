// Ids by origin: which id a particle or grain gets depends on the source that made it and its place in
// that source (lattice point, inlet layer and slot, feed column), never on how the work is split or in
// which order the sources run. Checked against the whole set built at once.
#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <set>
#include <stdexcept>
#include <tuple>
#include <vector>

#include "grit/boundary/abrasive_inlet.hpp"
#include "grit/boundary/jet_inlet.hpp"
#include "grit/domain/id_index.hpp"
#include "grit/domain/particle_id.hpp"
#include "grit/io/case_reader.hpp"
#include "grit/sim/particle_blocks.hpp"

namespace grit::domain {
namespace {

TEST(ParticleId, KeepsItsSourceAndSerial) {
    const IdSource solid{IdKind::solid_block, 3};
    const ParticleId id = make_particle_id(solid, 123456789);
    EXPECT_EQ(id_source(id).kind, IdKind::solid_block);
    EXPECT_EQ(id_source(id).index, 3);
    EXPECT_EQ(id_serial(id), 123456789);
    EXPECT_EQ(describe_id(id), "solid block 3, serial 123456789");
    // Within a source the ids follow the serials; sources of one kind follow their index, kinds their order.
    EXPECT_LT(make_particle_id(solid, 7), make_particle_id(solid, 8));
    EXPECT_LT(make_particle_id(solid, id_serial_limit - 1), make_particle_id({IdKind::solid_block, 4}, 0));
    EXPECT_LT(make_particle_id({IdKind::fluid_block, id_index_limit - 1}, id_serial_limit - 1),
              make_particle_id({IdKind::solid_block, 0}, 0));
    // The largest id is positive: mirror images (negative ids) never meet one.
    EXPECT_GT(make_particle_id({IdKind::abrasive_feed, id_index_limit - 1}, id_serial_limit - 1), 0);
    // A hand-built set's ids are its serials, as before ids had an origin.
    EXPECT_EQ(make_particle_id({IdKind::hand_built, 0}, 41), 41);
}

TEST(ParticleId, ASerialOrSourceBeyondItsBitsIsRefused) {
    EXPECT_THROW(make_particle_id({IdKind::inlet, 0}, id_serial_limit), std::overflow_error);
    EXPECT_THROW(make_particle_id({IdKind::inlet, 0}, -1), std::overflow_error);
    EXPECT_THROW(make_particle_id({IdKind::inlet, id_index_limit}, 0), std::overflow_error);
}

TEST(IdIndex, FindsEveryIdAndRefusesOneHeldTwice) {
    const std::vector<ParticleId> ids = {make_particle_id({IdKind::wall_block, 0}, 5), 17, -19,
                                         make_particle_id({IdKind::inlet, 2}, 0)};
    IdIndex index;
    index.build(ids.data(), static_cast<Index>(ids.size()));
    for (std::size_t i = 0; i < ids.size(); ++i) EXPECT_EQ(index.find(ids[i]), static_cast<Index>(i));
    EXPECT_EQ(index.find(18), -1);
    const std::vector<ParticleId> twice = {4, 9, 4};
    EXPECT_THROW(index.build(twice.data(), 3), std::logic_error);
}

/// Each particle's state by id (position, mass, pressure, phase, material), checking that no id repeats.
template <int Dim>
std::map<ParticleId, std::tuple<double, double, double, double, int, int>> by_id(const particles::SphParticles<Dim>& ps) {
    std::map<ParticleId, std::tuple<double, double, double, double, int, int>> out;
    for (Index i = 0; i < ps.size(); ++i) {
        const auto [it, fresh] = out.emplace(ps.id()[i], std::tuple{ps.position()[i][0], ps.position()[i][1], ps.mass()[i],
                                                                    ps.pressure()[i], ps.phase()[i], ps.material()[i]});
        EXPECT_TRUE(fresh) << "id " << ps.id()[i] << " twice";
    }
    return out;
}

TEST(ParticleIds, ABlockSplitInTwoAndBuiltInEitherOrderGivesTheWholeBlocksIds) {
    // The 2D tank: a fluid block inside a wall block, cut at x = 0.13 m across both.
    const io::CaseSpec spec =
        io::read_case(std::filesystem::path(GRIT_SOURCE_DIR) / "cases" / "hydrostatic_2d" / "case.toml");
    const double dx = spec.particle_spacing;
    particles::SphParticles<2> whole;
    sim::add_particle_blocks<2>(spec, dx, whole);
    particles::SphParticles<2> right_then_left;
    sim::add_particle_blocks<2>(spec, dx, right_then_left, [](const core::Vec<2>& x) { return x[0] >= 0.13; });
    const Index right = right_then_left.size();
    sim::add_particle_blocks<2>(spec, dx, right_then_left, [](const core::Vec<2>& x) { return x[0] < 0.13; });
    ASSERT_GT(right, 0);
    ASSERT_LT(right, whole.size());
    EXPECT_EQ(by_id(right_then_left), by_id(whole));
    // The sources are the case's blocks: fluid block 0 and wall block 0, serials from 0 up.
    std::set<std::pair<IdKind, std::int32_t>> sources;
    std::int64_t largest_fluid_serial = -1;
    for (Index i = 0; i < whole.size(); ++i) {
        const IdSource s = id_source(whole.id()[i]);
        sources.insert({s.kind, s.index});
        if (s.kind == IdKind::fluid_block) largest_fluid_serial = std::max(largest_fluid_serial, id_serial(whole.id()[i]));
    }
    EXPECT_EQ(sources, (std::set<std::pair<IdKind, std::int32_t>>{{IdKind::fluid_block, 0}, {IdKind::wall_block, 0}}));
    EXPECT_EQ(largest_fluid_serial, 40 * 30 - 1);
}

TEST(ParticleIds, InletsGiveLayerAndSlotWhicheverRunsFirst) {
    io::InletSpec a;
    a.position = {0.0, 0.0};
    a.direction = {0.0, -1.0};
    a.diameter = 4e-3;
    a.velocity = 10.0;
    io::InletSpec b = a;
    b.position = {0.01, 0.0};
    const double dx = 1e-3, dt = 3e-5;
    auto emit = [&](bool a_first) {
        boundary::JetInlet<2> first(a_first ? a : b, a_first ? 0 : 1, dx, 1000.0, 1e-3);
        boundary::JetInlet<2> second(a_first ? b : a, a_first ? 1 : 0, dx, 1000.0, 1e-3);
        particles::SphParticles<2> ps;
        for (int step = 0; step < 20; ++step) {
            first.emit(ps, step * dt, dt);
            second.emit(ps, step * dt, dt);
        }
        return ps;
    };
    const auto ab = emit(true), ba = emit(false);
    ASSERT_GT(ab.size(), 0);
    ASSERT_EQ(ab.size() % 8, 0);  // whole layers of 4 slots from each of the two inlets
    EXPECT_EQ(by_id(ab), by_id(ba));
    // Slot k of layer L of an inlet has serial 4 L + k: a slot lies at one place across the section,
    // whichever layer and inlet it belongs to, and each inlet's layers are 0 .. L - 1.
    const std::int64_t layers = ab.size() / 8;
    std::map<std::int64_t, double> slot_offset;
    std::map<std::int32_t, std::set<std::int64_t>> serials;
    for (Index i = 0; i < ab.size(); ++i) {
        const IdSource s = id_source(ab.id()[i]);
        EXPECT_EQ(s.kind, IdKind::inlet);
        const auto serial = id_serial(ab.id()[i]);
        serials[s.index].insert(serial);
        const double offset = ab.position()[i][0] - (s.index == 0 ? 0.0 : 0.01);
        const auto [it, fresh] = slot_offset.emplace(serial % 4, offset);
        if (!fresh) {
            EXPECT_NEAR(offset, it->second, 1e-12) << "slot " << serial % 4;
        }
    }
    EXPECT_EQ(slot_offset.size(), 4u);
    for (const auto& [inlet, set] : serials) {
        EXPECT_EQ(static_cast<std::int64_t>(set.size()), 4 * layers) << "inlet " << inlet;
        EXPECT_EQ(*set.rbegin(), 4 * layers - 1) << "inlet " << inlet;
    }
}

TEST(ParticleIds, AnAbrasiveGrainsSerialIsItsColumnWhateverTheStep) {
    io::AbrasiveSpec spec;
    spec.enabled = true;
    spec.size = dem::FixedSize{2e-4};
    spec.spacing = 5e-4;
    spec.seed = 3;
    io::InletSpec jet;
    jet.position = {0.0, 2e-3};
    jet.direction = {0.0, -1.0};
    jet.diameter = 1e-3;
    jet.velocity = 500.0;
    // The same feed stepped by 3.3 ns and by 10 ns: each column's grain enters once, with its offset.
    auto columns = [&](double dt) {
        boundary::AbrasiveInlet<2> inlet(spec, jet);
        std::map<std::int64_t, double> offset;
        for (double t = 0.0; t < 100 * spec.spacing / jet.velocity; t += dt)
            for (const auto& g : inlet.emit(t, dt)) EXPECT_TRUE(offset.emplace(g.column, g.position[0]).second);
        return offset;
    };
    const auto fine = columns(3.3e-9), coarse = columns(1e-8);
    ASSERT_GE(fine.size(), 99u);
    for (const auto& [column, x] : fine)
        if (coarse.count(column)) {
            EXPECT_EQ(coarse.at(column), x) << "column " << column;
        }
    EXPECT_GE(coarse.size() + 1, fine.size());
}

}  // namespace
}  // namespace grit::domain
