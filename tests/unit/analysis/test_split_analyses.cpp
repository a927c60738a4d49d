// Analyses as a local pass and a combine: the crater's bins and the probes' samples of a set split into two
// sub-domains, combined as domain::Comm combines them (bins and fronts by their maximum, NaN left out;
// point probes' sums by adding), give the whole set's crater and probe values. The crack and fragment
// labels, exchanged through a halo over sub-domains, are tested in tests/unit/domain/test_process_halo.cpp.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <vector>

#include "grit/analysis/crater.hpp"
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

}  // namespace
