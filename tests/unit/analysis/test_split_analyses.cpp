// Analyses as a local pass and a combine: the crater's bins and the probes' samples of a set split into two
// sub-domains, combined as domain::Comm combines them (bins and fronts by their maximum, NaN left out;
// point probes' sums by adding), give the whole set's crater and probe values; the crack labels, joined
// through ghosts whose labels are exchanged until none changes, give the whole set's cracks, and the
// fragment labels with the anchored labels of each sub-domain united remove what the whole set removes.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <map>
#include <random>
#include <vector>

#include "grit/analysis/cracks.hpp"
#include "grit/analysis/crater.hpp"
#include "grit/analysis/fragments.hpp"
#include "grit/analysis/probes.hpp"

namespace {

using grit::Index;
using grit::Phase;
namespace analysis = grit::analysis;

constexpr double dx = 1e-4;

/// The two parts of `ps`: the particles `first` accepts, and the others.
template <int Dim>
std::array<grit::particles::SphParticles<Dim>, 2> split(const grit::particles::SphParticles<Dim>& ps,
                                                        const std::function<bool(Index)>& first) {
    std::array<std::vector<Index>, 2> keep;
    for (Index i = 0; i < ps.size(); ++i) keep[first(i) ? 0 : 1].push_back(i);
    std::array<grit::particles::SphParticles<Dim>, 2> parts{ps, ps};
    parts[0].gather(keep[0]);
    parts[1].gather(keep[1]);
    return parts;
}

/// Element-wise maximum of two ranks' arrays, NaN left out (domain::Comm::max_each over two ranks).
std::vector<double> max_each(std::vector<double> a, const std::vector<double>& b) {
    for (std::size_t k = 0; k < a.size(); ++k)
        if (std::isnan(a[k]) || b[k] > a[k]) a[k] = b[k];
    return a;
}

/// A solid block 40 columns wide and 10 deep below y = 0 with a pit 6 columns wide and 3 deep, two
/// columns piled beside it (lips), and one top particle slipped a third of a spacing sideways.
grit::particles::SphParticles<2> pitted_block() {
    grit::particles::SphParticles<2> ps;
    auto add = [&](double x, double y) {
        const Index a = ps.append(1);
        ps.position()[a] = {{x, y}};
        ps.phase()[a] = static_cast<std::int32_t>(Phase::solid);
    };
    for (int i = 0; i < 40; ++i)
        for (int j = -10; j < 0; ++j) {
            if (i >= 17 && i < 23 && j >= -3) continue;
            add((i + 0.5 + (i == 12 && j == -1 ? 0.33 : 0.0)) * dx, (j + 0.5) * dx);
        }
    for (int j = 0; j < 2; ++j) {
        add(15.5 * dx, (j + 0.5) * dx);
        add(24.5 * dx, (j + 0.5) * dx);
    }
    return ps;
}

void expect_same_profile(const analysis::CraterProfile& a, const analysis::CraterProfile& b) {
    ASSERT_EQ(a.surface.size(), b.surface.size());
    for (std::size_t k = 0; k < a.surface.size(); ++k)
        EXPECT_TRUE(a.surface[k] == b.surface[k] || (std::isnan(a.surface[k]) && std::isnan(b.surface[k]))) << "bin " << k;
    EXPECT_EQ(a.depth, b.depth);
    EXPECT_EQ(a.width, b.width);
    EXPECT_EQ(a.rim_width, b.rim_width);
    EXPECT_EQ(a.lip_height, b.lip_height);
    EXPECT_EQ(a.area, b.area);
    EXPECT_EQ(a.shape_factor, b.shape_factor);
}

TEST(SplitAnalyses, CraterBinsOfTwoSubDomainsCombinedByTheirMaximumAreTheWholeCrater) {
    const auto ps = pitted_block();
    const analysis::CraterRegion region{0.0, 0.0, 40 * dx};
    const auto whole = analysis::analyse_crater(ps, region, dx);
    ASSERT_NEAR(whole.depth, 3.0 * dx, 1e-12);
    ASSERT_GT(whole.lip_height, 0.0);
    // Cut through the pit (a bin's particles on both sides of the cut, some within the bins' margin of it),
    // and interleaved by index (every bin shared).
    const double cut = 20.3 * dx;
    for (const auto& first : std::vector<std::function<bool(Index)>>{
             [&](Index i) { return ps.position()[i][0] < cut; }, [](Index i) { return i % 2 == 0; }}) {
        const auto parts = split(ps, first);
        ASSERT_GT(parts[0].size(), 0);
        ASSERT_GT(parts[1].size(), 0);
        auto combined = analysis::crater_bins(parts[0], region, dx);
        combined.surface = max_each(combined.surface, analysis::crater_bins(parts[1], region, dx).surface);
        analysis::measure_profile(combined, region.surface, dx);
        expect_same_profile(combined, whole);
    }
}

TEST(SplitAnalyses, ThreeDCraterCellsOfTwoSubDomainsAreTheWholeMap) {
    grit::particles::SphParticles<3> ps;
    for (int i = 0; i < 40; ++i)
        for (int j = 0; j < 20; ++j)
            for (int k = -6; k < 0; ++k) {
                if (i >= 10 && i < 22 && j >= 7 && j < 13 && k >= -3) continue;  // a kerf along x
                const Index a = ps.append(1);
                ps.position()[a] = {{(i + 0.5) * dx, (j + 0.5) * dx, (k + 0.5) * dx}};
                ps.phase()[a] = static_cast<std::int32_t>(Phase::solid);
            }
    const analysis::CraterRegion region{0.0, 0.0, 40 * dx, false, 0.0, 20 * dx};
    const auto whole = analysis::analyse_crater(ps, region, dx);
    ASSERT_NEAR(whole.depth, 3.0 * dx, 1e-12);
    const auto parts = split(ps, [&](Index i) { return ps.position()[i][1] < 9.9 * dx; });  // across the kerf
    auto combined = analysis::crater_bins(parts[0], region, dx);
    combined.surface = max_each(combined.surface, analysis::crater_bins(parts[1], region, dx).surface);
    analysis::measure_map(combined, region.surface, dx);
    ASSERT_EQ(combined.surface.size(), whole.surface.size());
    for (std::size_t k = 0; k < whole.surface.size(); ++k) EXPECT_EQ(combined.surface[k], whole.surface[k]) << "cell " << k;
    EXPECT_EQ(combined.depth, whole.depth);
    EXPECT_EQ(combined.width, whole.width);
    EXPECT_EQ(combined.length, whole.length);
    EXPECT_EQ(combined.area, whole.area);
}

TEST(SplitAnalyses, ProbeSamplesOfTwoSubDomainsGiveTheWholeSetsValues) {
    // Water on a 30 x 20 lattice with a hydrostatic pressure and a shear flow.
    grit::particles::SphParticles<2> ps;
    for (int i = 0; i < 30; ++i)
        for (int j = 0; j < 20; ++j) {
            const Index a = ps.append(1);
            const double y = (j + 0.5) * dx;
            ps.position()[a] = {{(i + 0.5) * dx, y}};
            ps.velocity()[a] = {{3.0 * y / (20 * dx), 0.0}};
            ps.pressure()[a] = 1000.0 * 9.81 * (20 * dx - y);
            ps.density()[a] = 1000.0 + 1e-3 * j;
            ps.mass()[a] = 1000.0 * dx * dx;
            ps.phase()[a] = static_cast<std::int32_t>(Phase::fluid);
        }
    const grit::sph::Kernel<2> kernel = grit::sph::WendlandC2<2>(1.3 * dx);
    std::vector<analysis::ProbeSpec> probes(4);
    probes[0] = {"p", "pressure_mid", "point", 0, "pressure", {15.0 * dx, 10.0 * dx}, 0, false, {}, {}};
    probes[1] = {"v", "speed_top", "point", 0, "velocity", {15.2 * dx, 19.0 * dx}, 0, false, {}, {}};
    probes[2] = {"f", "front", "front", 0, "", {}, 0, false, {}, {}};
    probes[3] = {"g", "front_low", "front", 0, "", {}, 0, true, {0.0, 0.0}, {1.0, 5.0 * dx}};
    const auto parts = split(ps, [&](Index i) { return ps.position()[i][0] < 15.1 * dx; });  // through the points
    for (const auto& probe : probes) {
        const double whole = analysis::evaluate_probe(probe, ps, kernel, dx);
        const auto a = analysis::sample_probe(probe, parts[0], kernel), b = analysis::sample_probe(probe, parts[1], kernel);
        const analysis::ProbeSample combined =
            probe.kind == "front" ? analysis::ProbeSample{max_each({a.value}, {b.value})[0], 0.0}
                                  : analysis::ProbeSample{a.value + b.value, a.weight + b.weight};
        if (probe.kind == "front")
            EXPECT_EQ(analysis::probe_value(probe, combined, dx), whole) << probe.name;  // a maximum is exact
        else
            EXPECT_NEAR(analysis::probe_value(probe, combined, dx), whole, 1e-12 * std::abs(whole)) << probe.name;
    }
    // A front seen by one part only: the other's NaN is left out.
    const auto front_a = analysis::sample_probe(probes[3], parts[0], kernel);
    auto right = parts[1];
    for (Index i = 0; i < right.size(); ++i) right.phase()[i] = static_cast<std::int32_t>(Phase::wall);
    const auto none = analysis::sample_probe(probes[3], right, kernel);
    EXPECT_TRUE(std::isnan(none.value));
    EXPECT_EQ(max_each({none.value}, {front_a.value})[0], front_a.value);
}

/// One sub-domain of a crack test: its own particles, then ghosts (copies of the other's within the link
/// distance of the cut) with the index of each ghost's owner there.
struct SubDomain {
    grit::particles::SphParticles<2> ps;
    std::vector<double> damage;
    Index owned = 0;
    std::vector<Index> owner;  // per ghost: its index in the other sub-domain
};

/// `whole` cut at x = cut into two sub-domains, each with the other's particles within `width` of the cut
/// as ghosts; from[side] is the whole-set index of each of its particles.
std::array<SubDomain, 2> split_at(const grit::particles::SphParticles<2>& whole, const std::vector<double>& damage,
                                  double cut, double width, std::array<std::vector<Index>, 2>& from) {
    std::array<SubDomain, 2> sub;
    for (int side = 0; side < 2; ++side) {
        auto mine = [&](Index i) { return (whole.position()[i][0] < cut) == (side == 0); };
        for (Index i = 0; i < whole.size(); ++i)
            if (mine(i)) from[side].push_back(i);
        sub[side].owned = static_cast<Index>(from[side].size());
        for (Index i = 0; i < whole.size(); ++i)
            if (!mine(i) && std::abs(whole.position()[i][0] - cut) <= width) from[side].push_back(i);
        sub[side].ps = whole;
        sub[side].ps.gather(from[side]);
        for (const Index i : from[side]) sub[side].damage.push_back(damage[static_cast<std::size_t>(i)]);
    }
    for (int side = 0; side < 2; ++side) {
        std::map<Index, Index> there;  // whole-set index -> index in the other sub-domain
        for (std::size_t k = 0; k < from[1 - side].size(); ++k) there[from[1 - side][k]] = static_cast<Index>(k);
        for (std::size_t k = static_cast<std::size_t>(sub[side].owned); k < from[side].size(); ++k)
            sub[side].owner.push_back(there.at(from[side][k]));
    }
    return sub;
}

/// Labels each sub-domain with `label(side, ghost_labels)`, exchanges the ghosts' labels, and again until
/// no label changes (at most 20 rounds); returns the rounds it took.
using Labels = std::vector<grit::domain::ParticleId>;
int exchange_until_settled(const std::array<SubDomain, 2>& sub, std::array<Labels, 2>& labels,
                           const std::function<Labels(int, const grit::domain::ParticleId*)>& label) {
    std::array<Labels, 2> ghost_labels;
    int rounds = 0;
    for (bool changed = true; changed && rounds < 20; ++rounds) {
        for (int side = 0; side < 2; ++side) labels[side] = label(side, rounds == 0 ? nullptr : ghost_labels[side].data());
        changed = false;
        for (int side = 0; side < 2; ++side) {
            Labels fresh;
            for (const Index o : sub[side].owner) fresh.push_back(labels[1 - side][static_cast<std::size_t>(o)]);
            changed |= fresh != ghost_labels[side];
            ghost_labels[side] = fresh;
        }
    }
    return rounds;
}

TEST(SplitAnalyses, CrackLabelsExchangedThroughGhostsGiveTheWholeSetsCracks) {
    // A 40 x 30 solid lattice with random damage (20 %) and a snake of damage that crosses the cut at
    // x = 20 dx four times: its label must travel through several exchanges.
    constexpr double h = 1e-3;
    grit::particles::SphParticles<2> whole;
    std::vector<double> damage;
    std::mt19937 rng(7);
    for (int j = 0; j < 30; ++j)
        for (int i = 0; i < 40; ++i) {
            const Index a = whole.append(1);
            whole.position()[a] = {{i * h, j * h}};
            whole.phase()[a] = static_cast<std::int32_t>(Phase::solid);
            whole.density()[a] = 2500.0;
            whole.mass()[a] = 2500.0 * h * h;
            const bool snake = (j == 25 && i >= 12 && i <= 28) || ((i == 12 || i == 28) && j >= 20 && j <= 25) ||
                               (j == 20 && i >= 12 && i <= 28 && (i < 16 || i > 24));
            damage.push_back(snake || std::uniform_real_distribution<double>(0.0, 1.0)(rng) < 0.2 ? 0.9 : 0.1);
        }
    grit::analysis::CrackOptions options;
    options.link_distance = 1.5 * h;
    const auto reference = grit::analysis::analyse_cracks<2>(whole, damage.data(), options);
    const auto reference_labels = grit::analysis::crack_labels<2>(whole, damage.data(), options, whole.size());
    ASSERT_GT(reference.crack_count, 3);

    const double cut = 19.5 * h;
    std::array<std::vector<Index>, 2> from;  // whole-set index of each particle of each sub-domain
    const auto sub = split_at(whole, damage, cut, options.link_distance, from);
    std::array<Labels, 2> labels;
    const int rounds = exchange_until_settled(sub, labels, [&](int side, const grit::domain::ParticleId* ghosts) {
        return grit::analysis::crack_labels<2>(sub[side].ps, sub[side].damage.data(), options, sub[side].owned, ghosts);
    });
    ASSERT_LT(rounds, 20);
    EXPECT_GT(rounds, 2);  // the snake needed more than one exchange
    // Every owned particle holds the whole set's label; the shares added label by label count the same cracks.
    std::map<grit::domain::ParticleId, Index> sizes;
    for (int side = 0; side < 2; ++side) {
        for (Index k = 0; k < sub[side].owned; ++k)
            EXPECT_EQ(labels[side][static_cast<std::size_t>(k)], reference_labels[static_cast<std::size_t>(from[side][static_cast<std::size_t>(k)])]);
        for (const auto& [label, count] : grit::analysis::crack_sizes(labels[side], sub[side].owned)) sizes[label] += count;
    }
    grit::analysis::CrackMeasures combined;
    grit::analysis::count_cracks(sizes, options, combined);
    EXPECT_EQ(combined.crack_count, reference.crack_count);
    EXPECT_EQ(combined.largest_crack, reference.largest_crack);
}

// Neighbour lists of every pair closer than `radius`, by brute force (the sets here are small).
grit::neighbors::NeighborList<2> all_pairs(const grit::particles::SphParticles<2>& ps, double radius) {
    std::vector<Index> offsets{0}, indices;
    for (Index i = 0; i < ps.size(); ++i) {
        for (Index j = 0; j < ps.size(); ++j)
            if (j != i && grit::core::norm2(ps.position()[i] - ps.position()[j]) < radius * radius) indices.push_back(j);
        offsets.push_back(static_cast<Index>(indices.size()));
    }
    grit::neighbors::NeighborList<2> list;
    list.assign(offsets, indices, std::vector<grit::core::Vec<2>>(ps.position(), ps.position() + ps.size()));
    return list;
}

TEST(SplitAnalyses, FragmentLabelsOfTwoSubDomainsRemoveWhatTheWholeSetRemoves) {
    // Intact rock in the bottom 5 rows of a 40 x 30 lattice, water above it, and in the water fractured
    // rock: a snake anchored on the rock at its right end that crosses the cut at x = 19.5 dx four
    // times (the anchor must travel through several exchanges), an island across the cut that touches
    // nothing, and scattered fractured particles (10 %), some on the rock.
    constexpr double h = 1e-3;
    grit::particles::SphParticles<2> whole;
    std::vector<double> damage;
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
            damage.push_back(!solid ? 0.0 : rock && !scattered ? 0.1 : 1.0);
        }
    const double link = 1.5 * h;
    const auto labels = grit::analysis::fragment_labels<2>(whole, damage.data(), link, whole.size());
    const auto anchored =
        grit::analysis::anchored_fragments<2>(whole, damage.data(), labels, all_pairs(whole, 2.5 * h), link, whole.size());
    auto removed = [&](const std::vector<grit::domain::ParticleId>& label, const std::vector<grit::domain::ParticleId>& a,
                       Index i) { return label[static_cast<std::size_t>(i)] >= 0 &&
                                         !std::binary_search(a.begin(), a.end(), label[static_cast<std::size_t>(i)]); };
    Index gone = 0, kept = 0;
    for (Index i = 0; i < whole.size(); ++i)
        if (labels[static_cast<std::size_t>(i)] >= 0) ++(removed(labels, anchored, i) ? gone : kept);
    ASSERT_GT(gone, 17);  // the island at least
    ASSERT_GT(kept, 50);  // the snake at least

    const double cut = 19.5 * h;
    std::array<std::vector<Index>, 2> from;
    const auto sub = split_at(whole, damage, cut, link, from);
    std::array<Labels, 2> local;
    const int rounds = exchange_until_settled(sub, local, [&](int side, const grit::domain::ParticleId* ghosts) {
        return grit::analysis::fragment_labels<2>(sub[side].ps, sub[side].damage.data(), link, sub[side].owned, ghosts);
    });
    ASSERT_LT(rounds, 20);
    EXPECT_GT(rounds, 2);
    // Each sub-domain's anchored labels, united.
    std::vector<grit::domain::ParticleId> united;
    for (int side = 0; side < 2; ++side) {
        const auto mine = grit::analysis::anchored_fragments<2>(sub[side].ps, sub[side].damage.data(), local[side],
                                                                all_pairs(sub[side].ps, 2.5 * h), link, sub[side].owned);
        united.insert(united.end(), mine.begin(), mine.end());
    }
    std::sort(united.begin(), united.end());
    united.erase(std::unique(united.begin(), united.end()), united.end());
    EXPECT_EQ(united, anchored);
    for (int side = 0; side < 2; ++side)
        for (Index k = 0; k < sub[side].owned; ++k) {
            const Index i = from[side][static_cast<std::size_t>(k)];
            EXPECT_EQ(local[side][static_cast<std::size_t>(k)], labels[static_cast<std::size_t>(i)]) << "particle " << i;
            EXPECT_EQ(removed(local[side], united, k), removed(labels, anchored, i)) << "particle " << i;
        }
}

}  // namespace
