// The process halo against brute force, over sub-domains in threads of one process (a loopback
// communicator): the ghosts a sub-domain receives are exactly the other sub-domains' particles within the
// ghost width of its slab; forward gives them their owners' values; a value spread from owned particles
// onto every neighbour, ghosts included, comes back to the owners by reverse_add as the whole set would
// have spread it; migration leaves each particle owned once, in its slab, with every field; crack labels
// exchanged through the halo until no sub-domain's ghost label changes (Comm::any) are the whole set's, and
// so are the fragments a solid removes (fragment labels settled alike, anchored labels united over ranks).
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <mutex>
#include <random>
#include <set>
#include <vector>

#include "grit/analysis/cracks.hpp"
#include "grit/analysis/fragments.hpp"
#include "grit/domain/process_halo.hpp"
#include "support/all_pairs.hpp"
#include "support/loopback_comm.hpp"

namespace grit::domain {
namespace {

using Particles = particles::SphParticles<2>;
constexpr double reach = 0.08;
constexpr double weight_of(double d) { return (reach - d) * (reach - d); }

bool same(const core::Vec<2>& a, const core::Vec<2>& b) { return a[0] == b[0] && a[1] == b[1]; }

/// 600 particles strewn over [0, 1]^2 with a value each (the hand-built ids number them).
Particles cloud(unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    Particles ps;
    ps.append(600);
    for (Index i = 0; i < ps.size(); ++i) {
        ps.position()[i] = {{u(rng), u(rng)}};
        ps.velocity()[i] = {{u(rng) - 0.5, u(rng) - 0.5}};
        ps.density()[i] = 1000.0 + u(rng);
    }
    return ps;
}

/// Sub-domain `rank`'s part of `whole`.
Particles part(const Particles& whole, const SlabPartition<2>& partition, int rank) {
    std::vector<Index> mine;
    for (Index i = 0; i < whole.size(); ++i)
        if (partition.owner(whole.position()[i]) == rank) mine.push_back(i);
    Particles ps = whole;
    ps.gather(mine);
    return ps;
}

/// For each particle i of `ps` (owned or ghost) and each owned particle a within reach, adds
/// rho_a w(|x_a - x_i|) to spread[i]: a contribution an owned particle spreads onto its neighbours.
std::vector<double> spread_from_owned(const Particles& ps) {
    std::vector<double> spread(static_cast<std::size_t>(ps.size()), 0.0);
    const std::int32_t* ghost = ProcessHalo<2>::ghost_marks(ps);
    for (Index a = 0; a < ps.size(); ++a) {
        if (ghost && ghost[a]) continue;
        for (Index i = 0; i < ps.size(); ++i) {
            const double d = core::norm(ps.position()[a] - ps.position()[i]);
            if (i != a && d < reach) spread[static_cast<std::size_t>(i)] += ps.density()[a] * weight_of(d);
        }
    }
    return spread;
}

/// Labels a sub-domain whose ghosts are [owned, size) with `label(ghost_labels)`, gives each ghost its
/// owner's label (forward) and labels again until no rank's ghost labels change (Comm::any); returns the
/// labelling rounds (at most 20).
template <class Label>
int settle(const ProcessHalo<2>& halo, const Particles& ps, Index owned, const Comm& comm,
           std::vector<ParticleId>& labels, const Label& label) {
    labels = label(nullptr);
    std::vector<ParticleId> ghost_labels;
    int rounds = 1;
    for (; rounds < 20; ++rounds) {
        halo.forward(ps, labels.data(), comm);
        std::vector<ParticleId> fresh(labels.begin() + owned, labels.end());
        if (!comm.any(fresh != ghost_labels)) break;
        ghost_labels = std::move(fresh);
        labels = label(ghost_labels.data());
    }
    return rounds;
}

class ProcessHaloTest : public ::testing::TestWithParam<int> {};

TEST_P(ProcessHaloTest, GhostsAreTheOtherSubDomainsParticlesWithinTheWidth) {
    const int ranks = GetParam();
    const Particles whole = cloud(7);
    SlabPartition<2> partition{0, {}};
    for (int r = 1; r < ranks; ++r) partition.cuts.push_back(static_cast<double>(r) / ranks);
    grit::testing::run_loopback(ranks, [&](const Comm& comm) {
        Particles ps = part(whole, partition, comm.rank());
        const Index owned = ps.size();
        ProcessHalo<2> halo;
        halo.make_ghosts(ps, partition, reach, comm);
        // Brute force: every particle of the whole set owned elsewhere, within the width of this slab.
        std::set<ParticleId> expected;
        for (Index i = 0; i < whole.size(); ++i)
            if (partition.owner(whole.position()[i]) != comm.rank() &&
                partition.distance(whole.position()[i], comm.rank()) < reach)
                expected.insert(whole.id()[i]);
        std::set<ParticleId> got;
        const std::int32_t* ghost = ProcessHalo<2>::ghost_marks(ps);
        ASSERT_NE(ghost, nullptr);
        for (Index i = owned; i < ps.size(); ++i) {
            ASSERT_TRUE(ghost[i]);
            got.insert(ps.id()[i]);  // a ghost keeps its owner's id
        }
        EXPECT_EQ(got, expected) << "rank " << comm.rank();
        EXPECT_EQ(halo.ghost_count(), expected.size());
        // A ghost is its owner, field by field, and stays so after the owners change and forward.
        auto check = [&](const Particles& reference) {
            std::map<ParticleId, Index> where;
            for (Index i = 0; i < reference.size(); ++i) where[reference.id()[i]] = i;
            for (Index g = owned; g < ps.size(); ++g) {
                const Index o = where.at(ps.id()[g]);
                EXPECT_TRUE(same(ps.position()[g], reference.position()[o]));
                EXPECT_TRUE(same(ps.velocity()[g], reference.velocity()[o]));
                EXPECT_EQ(ps.density()[g], reference.density()[o]);
            }
        };
        check(whole);
        Particles moved = whole;  // every rank changes its owned particles alike
        for (Index i = 0; i < moved.size(); ++i) moved.density()[i] += static_cast<double>(moved.id()[i] % 7);
        for (Index i = 0; i < owned; ++i) ps.density()[i] += static_cast<double>(ps.id()[i] % 7);
        halo.forward(ps, comm);
        check(moved);
    });
}

TEST_P(ProcessHaloTest, ReverseAddReturnsWhatLandedOnGhostsAsTheWholeSetSpreadsIt) {
    const int ranks = GetParam();
    const Particles whole = cloud(11);
    const std::vector<double> spread_whole = spread_from_owned(whole);
    std::map<ParticleId, double> expected;
    for (Index i = 0; i < whole.size(); ++i) expected[whole.id()[i]] = spread_whole[static_cast<std::size_t>(i)];
    SlabPartition<2> partition{0, {}};
    for (int r = 1; r < ranks; ++r) partition.cuts.push_back(0.2 + 0.6 * r / ranks);
    std::mutex lock;
    std::size_t seen = 0;
    grit::testing::run_loopback(ranks, [&](const Comm& comm) {
        Particles ps = part(whole, partition, comm.rank());
        ProcessHalo<2> halo;
        halo.make_ghosts(ps, partition, reach, comm);
        std::vector<double> spread = spread_from_owned(ps);
        halo.reverse_add(ps, spread.data(), comm);
        const std::lock_guard guard(lock);
        const std::int32_t* ghost = ProcessHalo<2>::ghost_marks(ps);
        for (Index i = 0; i < ps.size(); ++i) {
            if (ghost[i]) continue;
            ++seen;
            const double e = expected.at(ps.id()[i]);
            EXPECT_NEAR(spread[static_cast<std::size_t>(i)], e, 1e-12 * std::abs(e) + 1e-300)
                << "particle " << ps.id()[i] << " on rank " << comm.rank();
        }
    });
    EXPECT_EQ(seen, static_cast<std::size_t>(whole.size()));
}

TEST_P(ProcessHaloTest, MigrationLeavesEachParticleOwnedOnceInItsSlabWithItsFields) {
    const int ranks = GetParam();
    const Particles whole = cloud(13);
    SlabPartition<2> partition{0, {}};
    for (int r = 1; r < ranks; ++r) partition.cuts.push_back(static_cast<double>(r) / ranks);
    // Every particle moves a fifth of the box along x (those beyond 1 wrap to the start): many change slab.
    Particles after = whole;
    for (Index i = 0; i < after.size(); ++i) after.position()[i][0] = std::fmod(after.position()[i][0] + 0.2, 1.0);
    std::map<ParticleId, Index> index;
    for (Index i = 0; i < after.size(); ++i) index[after.id()[i]] = i;
    std::mutex lock;
    std::set<ParticleId> owned;
    long left = 0;
    grit::testing::run_loopback(ranks, [&](const Comm& comm) {
        Particles ps = part(whole, partition, comm.rank());
        for (Index i = 0; i < ps.size(); ++i) ps.position()[i] = after.position()[index.at(ps.id()[i])];
        ProcessHalo<2> halo;
        const Index gone = halo.migrate(ps, partition, comm);
        const std::lock_guard guard(lock);
        left += gone;
        for (Index i = 0; i < ps.size(); ++i) {
            EXPECT_EQ(partition.owner(ps.position()[i]), comm.rank());
            EXPECT_TRUE(owned.insert(ps.id()[i]).second) << "particle " << ps.id()[i] << " owned twice";
            const Index w = index.at(ps.id()[i]);
            EXPECT_TRUE(same(ps.velocity()[i], after.velocity()[w]));
            EXPECT_EQ(ps.density()[i], after.density()[w]);
        }
    });
    EXPECT_EQ(owned.size(), static_cast<std::size_t>(whole.size()));
    if (ranks > 1) {
        EXPECT_GT(left, 50);
    }
}

TEST_P(ProcessHaloTest, CrackLabelsSettledThroughTheHaloAreTheWholeSetsCracks) {
    // A 40 x 30 solid lattice with random damage (20 %) and a snake of damage that winds across the middle
    // of the block: its label must travel through several exchanges.
    const int ranks = GetParam();
    constexpr double h = 1e-3;
    Particles whole;
    auto& damage = whole.fields().add<double>("damage", 0.0, false);
    std::mt19937 rng(7);
    for (int j = 0; j < 30; ++j)
        for (int i = 0; i < 40; ++i) {
            const Index a = whole.append(1);
            whole.position()[a] = {{i * h, j * h}};
            whole.phase()[a] = static_cast<std::int32_t>(Phase::solid);
            const bool snake = (j == 25 && i >= 12 && i <= 28) || ((i == 12 || i == 28) && j >= 20 && j <= 25) ||
                               (j == 20 && i >= 12 && i <= 28 && (i < 16 || i > 24));
            damage[a] = snake || std::uniform_real_distribution<double>(0.0, 1.0)(rng) < 0.2 ? 0.9 : 0.1;
        }
    analysis::CrackOptions options;
    options.link_distance = 1.5 * h;
    const auto reference = analysis::analyse_cracks<2>(whole, damage.data(), options);
    const auto reference_labels = analysis::crack_labels<2>(whole, damage.data(), options, whole.size());
    ASSERT_GT(reference.crack_count, 3);
    std::map<ParticleId, ParticleId> expected;
    for (Index i = 0; i < whole.size(); ++i) expected[whole.id()[i]] = reference_labels[static_cast<std::size_t>(i)];

    SlabPartition<2> partition{0, {}};
    for (int r = 1; r < ranks; ++r) partition.cuts.push_back((19.5 + 6.0 * (r - 1)) * h);
    std::mutex lock;
    std::map<ParticleId, Index> sizes;
    std::vector<int> rounds_taken;
    grit::testing::run_loopback(ranks, [&](const Comm& comm) {
        Particles ps = part(whole, partition, comm.rank());
        const Index owned = ps.size();
        ProcessHalo<2> halo;
        halo.make_ghosts(ps, partition, 2.0 * options.link_distance, comm);  // ghosts at [owned, size)
        const double* d = ps.fields().get<double>("damage").data();
        std::vector<ParticleId> labels;
        const int rounds = settle(halo, ps, owned, comm, labels, [&](const ParticleId* ghost_labels) {
            return analysis::crack_labels<2>(ps, d, options, owned, ghost_labels);
        });
        const std::lock_guard guard(lock);
        rounds_taken.push_back(rounds);
        for (Index i = 0; i < owned; ++i)
            EXPECT_EQ(labels[static_cast<std::size_t>(i)], expected.at(ps.id()[i])) << "rank " << comm.rank();
        for (const auto& [label, count] : analysis::crack_sizes(labels, owned)) sizes[label] += count;
    });
    for (const int rounds : rounds_taken) {
        EXPECT_LT(rounds, 20);
        if (ranks > 1) {
            EXPECT_GT(rounds, 2) << "the snake needed more than one exchange";
        }
    }
    analysis::CrackMeasures combined;
    analysis::count_cracks(sizes, options, combined);
    EXPECT_EQ(combined.crack_count, reference.crack_count);
    EXPECT_EQ(combined.largest_crack, reference.largest_crack);
}

TEST_P(ProcessHaloTest, FragmentsAnchoredInAnySubDomainAreTheWholeSetsFragments) {
    // Intact rock in the bottom 5 rows of a 40 x 30 lattice, water above it, and in the water fractured
    // rock: a snake anchored on the rock at its right end that winds across the cuts (the anchor must
    // travel through several exchanges), an island that touches nothing, and scattered fractured particles
    // (10 %), some on the rock. A fractured particle goes when no sub-domain anchors its fragment.
    const int ranks = GetParam();
    constexpr double h = 1e-3;
    Particles whole;
    auto& damage = whole.fields().add<double>("damage", 0.0, false);
    std::mt19937 rng(11);
    for (int j = 0; j < 30; ++j)
        for (int i = 0; i < 40; ++i) {
            const Index a = whole.append(1);
            whole.position()[a] = {{i * h, j * h}};
            const bool rock = j < 5;
            const bool snake = (i == 35 && j >= 5 && j <= 25) || (j == 25 && i >= 8 && i <= 35) ||
                               (i == 8 && j >= 20 && j <= 25) || (j == 20 && i >= 8 && i <= 30);
            const bool island = j == 12 && i >= 12 && i <= 28;
            const bool scattered = std::uniform_real_distribution<double>(0.0, 1.0)(rng) < 0.1;
            const bool solid = rock || snake || island || scattered;
            whole.phase()[a] = static_cast<std::int32_t>(solid ? Phase::solid : Phase::fluid);
            damage[a] = !solid ? 0.0 : rock && !scattered ? 0.1 : 1.0;
        }
    const double link = 1.5 * h;
    const auto reference = analysis::fragment_labels<2>(whole, damage.data(), link, whole.size());
    const auto anchored = analysis::anchored_fragments<2>(whole, damage.data(), reference,
                                                          grit::testing::all_pairs<2>(whole, 2.5 * h), link, whole.size());
    auto removed = [](ParticleId label, const std::vector<ParticleId>& a) {
        return label >= 0 && !std::binary_search(a.begin(), a.end(), label);
    };
    std::map<ParticleId, bool> expected;
    Index gone = 0, kept = 0;
    for (Index i = 0; i < whole.size(); ++i) {
        const ParticleId label = reference[static_cast<std::size_t>(i)];
        expected[whole.id()[i]] = removed(label, anchored);
        if (label >= 0) ++(expected[whole.id()[i]] ? gone : kept);
    }
    ASSERT_GT(gone, 17);  // the island at least
    ASSERT_GT(kept, 50);  // the snake at least

    SlabPartition<2> partition{0, {}};
    for (int r = 1; r < ranks; ++r) partition.cuts.push_back((19.5 + 6.0 * (r - 1)) * h);
    std::mutex lock;
    Index seen = 0;
    grit::testing::run_loopback(ranks, [&](const Comm& comm) {
        Particles ps = part(whole, partition, comm.rank());
        const Index owned = ps.size();
        ProcessHalo<2> halo;
        halo.make_ghosts(ps, partition, 2.5 * h, comm);  // the list's reach: the anchor test reads intact ghosts
        const double* d = ps.fields().get<double>("damage").data();
        std::vector<ParticleId> labels;
        settle(halo, ps, owned, comm, labels, [&](const ParticleId* ghost_labels) {
            return analysis::fragment_labels<2>(ps, d, link, owned, ghost_labels);
        });
        const auto mine = analysis::anchored_fragments<2>(ps, d, labels, grit::testing::all_pairs<2>(ps, 2.5 * h), link, owned);
        const auto united = unite(comm, mine);
        const std::lock_guard guard(lock);
        EXPECT_EQ(united, anchored) << "rank " << comm.rank();
        for (Index i = 0; i < owned; ++i, ++seen)
            EXPECT_EQ(removed(labels[static_cast<std::size_t>(i)], united), expected.at(ps.id()[i]))
                << "particle " << ps.id()[i] << " on rank " << comm.rank();
    });
    EXPECT_EQ(seen, whole.size());
}

INSTANTIATE_TEST_SUITE_P(Ranks, ProcessHaloTest, ::testing::Values(1, 2, 3),
                         [](const ::testing::TestParamInfo<int>& p) { return std::to_string(p.param) + "Ranks"; });

}  // namespace
}  // namespace grit::domain
