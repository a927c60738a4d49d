// Every case in cases/ gives bit-identical particles at 1 and 2 threads (gather loops, fixed-order
// reductions): a race or an order-dependent sum would show here.
#include <gtest/gtest.h>

#include <filesystem>

#include "grit/parallel/parallel.hpp"
#include "support/case_fixture.hpp"

namespace {

std::vector<std::filesystem::path> all_cases() {
    std::vector<std::filesystem::path> out;
    const std::filesystem::path root = std::filesystem::path(GRIT_SOURCE_DIR) / "cases";
    for (const auto& e : std::filesystem::recursive_directory_iterator(root))
        if (e.path().extension() == ".toml") out.push_back(e.path());
    std::sort(out.begin(), out.end());
    return out;
}

template <int Dim>
grit::particles::SphParticles<Dim> run(const grit::io::CaseSpec& spec, int threads, int steps) {
    grit::parallel::set_threads(threads);
    grit::sim::Simulation<Dim> sim(spec, grit::testing::in_memory());
    sim.advance_to(0.0);
    for (int k = 0; k < steps; ++k) sim.step();
    return sim.particles();
}

template <int Dim>
void compare(const grit::io::CaseSpec& spec) {
    const auto one = run<Dim>(spec, 1, 40);
    const auto two = run<Dim>(spec, 2, 40);
    grit::parallel::set_threads(2);
    ASSERT_EQ(one.size(), two.size());
    ASSERT_GT(one.size(), 0);
    for (grit::Index i = 0; i < one.size(); ++i) {
        for (int k = 0; k < Dim; ++k) {
            ASSERT_EQ(one.position()[i][k], two.position()[i][k]) << "particle " << i;
            ASSERT_EQ(one.velocity()[i][k], two.velocity()[i][k]) << "particle " << i;
        }
        ASSERT_EQ(one.density()[i], two.density()[i]) << "particle " << i;
        ASSERT_EQ(one.pressure()[i], two.pressure()[i]) << "particle " << i;
    }
}

}  // namespace

TEST(Determinism, EveryCaseIsIdenticalAtOneAndTwoThreads) {
    const auto cases = all_cases();
    ASSERT_GE(cases.size(), 6u);
    for (const auto& path : cases) {
        SCOPED_TRACE(path.string());
        const auto spec = grit::io::read_case(path);
        if (spec.dimension == 2)
            compare<2>(spec);
        else
            compare<3>(spec);
    }
}
