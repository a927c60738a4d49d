// Ghosts against brute force: the sums a particle makes over its owned neighbours and the ghosts of a
// periodic box or a mirror plane are the sums over the nearest images (periodic) or over the set and its
// mirror image (plane), and what a stage spreads onto ghosts returns to their owners as it would have
// landed on the images.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "grit/core/sym_tensor.hpp"
#include "grit/domain/halo.hpp"

namespace grit::domain {
namespace {

constexpr double reach = 0.15;

double weight(double d) { return (reach - d) * (reach - d); }

template <int Dim>
std::vector<core::Vec<Dim>> random_points(int n, const core::Vec<Dim>& lo, const core::Vec<Dim>& hi, unsigned seed) {
    std::mt19937 rng(seed);
    std::vector<core::Vec<Dim>> x(static_cast<std::size_t>(n));
    for (auto& p : x)
        for (int k = 0; k < Dim; ++k) p[k] = std::uniform_real_distribution<double>(lo[k], hi[k])(rng);
    return x;
}

/// The owned points followed by their ghosts (positions by the transforms), and the halo that made them.
template <int Dim>
struct WithGhosts {
    std::vector<core::Vec<Dim>> x;
    Halo<Dim> halo;
    Index owned = 0;
};

template <int Dim>
WithGhosts<Dim> with_ghosts(const std::vector<core::Vec<Dim>>& owned,
                            const std::vector<std::pair<Index, GhostTransform<Dim>>>& ghosts) {
    WithGhosts<Dim> out;
    out.x = owned;
    out.owned = static_cast<Index>(owned.size());
    for (const auto& [owner, t] : ghosts) {
        out.halo.add(owner, static_cast<Index>(out.x.size()), t);
        out.x.push_back(t.position(owned[static_cast<std::size_t>(owner)]));
    }
    return out;
}

/// For each owned point i: the sum of value_j w(|x_i - x_j|) over every other point j of the extended set
/// within reach.
template <int Dim>
std::vector<double> gathered_sums(const WithGhosts<Dim>& s, const std::vector<double>& value) {
    std::vector<double> out(static_cast<std::size_t>(s.owned), 0.0);
    for (Index i = 0; i < s.owned; ++i)
        for (std::size_t j = 0; j < s.x.size(); ++j) {
            if (static_cast<Index>(j) == i) continue;
            const double d = core::norm(s.x[static_cast<std::size_t>(i)] - s.x[j]);
            if (d < reach) out[static_cast<std::size_t>(i)] += value[j] * weight(d);
        }
    return out;
}

template <int Dim>
void expect_periodic_sums_match_the_minimum_image(const std::array<bool, Dim>& axes, unsigned seed) {
    using Vec = core::Vec<Dim>;
    Vec lo = Vec::zero(), hi;
    for (int k = 0; k < Dim; ++k) hi[k] = 1.0;
    const auto box = neighbors::PeriodicBox<Dim>::make(axes, lo, hi);
    const auto x = random_points<Dim>(Dim == 2 ? 300 : 600, lo, hi, seed);
    auto s = with_ghosts<Dim>(x, periodic_ghosts<Dim>(x.data(), static_cast<Index>(x.size()), box, reach));
    EXPECT_GT(s.halo.size(), 0u);
    std::mt19937 rng(seed + 1);
    std::vector<double> value(s.x.size());
    for (Index i = 0; i < s.owned; ++i) value[static_cast<std::size_t>(i)] = std::uniform_real_distribution<double>(0.5, 2.0)(rng);
    s.halo.forward(value.data());
    const auto sums = gathered_sums(s, value);
    for (std::size_t i = 0; i < x.size(); ++i) {
        double brute = 0.0;
        for (std::size_t j = 0; j < x.size(); ++j) {
            if (j == i) continue;
            const double d = core::norm(box.nearest_image(x[i] - x[j]));
            if (d < reach) brute += value[j] * weight(d);
        }
        ASSERT_NEAR(sums[i], brute, 1e-12 * std::max(1.0, std::abs(brute))) << "point " << i;
    }
}

TEST(Halo, PeriodicGhostsGiveTheMinimumImageSums) {
    expect_periodic_sums_match_the_minimum_image<2>({true, true}, 11);
    expect_periodic_sums_match_the_minimum_image<2>({true, false}, 12);
    expect_periodic_sums_match_the_minimum_image<3>({true, true, true}, 13);
    expect_periodic_sums_match_the_minimum_image<3>({false, true, false}, 14);
}

TEST(Halo, PeriodicGhostsOfACornerPointCoverEveryFaceAndCorner) {
    const auto box = neighbors::PeriodicBox<3>::make({true, true, true}, core::Vec<3>::zero(), {1.0, 1.0, 1.0});
    const core::Vec<3> corner{0.01, 0.02, 0.99};
    EXPECT_EQ(periodic_ghosts<3>(&corner, 1, box, reach).size(), 7u);  // 3 faces, 3 edges, 1 corner
    const core::Vec<3> inside{0.5, 0.5, 0.5};
    EXPECT_TRUE(periodic_ghosts<3>(&inside, 1, box, reach).empty());
    EXPECT_THROW(periodic_ghosts<3>(&inside, 1, box, 0.6), std::invalid_argument);
}

TEST(Halo, MirrorGhostsGiveTheSumsOverTheSetAndItsMirrorImage) {
    using Vec = core::Vec<2>;
    const auto x = random_points<2>(400, Vec{0.0, 0.0}, Vec{1.0, 1.0}, 21);
    auto s = with_ghosts<2>(x, mirror_ghosts<2>(x.data(), static_cast<Index>(x.size()), 0, reach));
    std::mt19937 rng(22);
    std::vector<double> value(s.x.size());
    std::vector<Vec> velocity(s.x.size());
    for (Index i = 0; i < s.owned; ++i) {
        value[static_cast<std::size_t>(i)] = std::uniform_real_distribution<double>(0.5, 2.0)(rng);
        velocity[static_cast<std::size_t>(i)] = {std::uniform_real_distribution<double>(-1.0, 1.0)(rng), 0.3};
    }
    s.halo.forward(value.data());
    s.halo.forward(velocity.data());
    for (std::size_t k = 0; k < s.halo.size(); ++k) {
        const auto owner = static_cast<std::size_t>(s.halo.owners()[k]);
        const auto ghost = static_cast<std::size_t>(s.halo.ghosts()[k]);
        EXPECT_EQ(velocity[ghost][0], -velocity[owner][0]);  // a mirror image moves the other way across
        EXPECT_EQ(velocity[ghost][1], velocity[owner][1]);
    }
    const auto sums = gathered_sums(s, value);
    for (std::size_t i = 0; i < x.size(); ++i) {
        double brute = 0.0;
        for (std::size_t j = 0; j < x.size(); ++j) {
            const Vec image{-x[j][0], x[j][1]};
            if (const double d = core::norm(x[i] - image); d < reach) brute += value[j] * weight(d);
            if (j == i) continue;
            if (const double d = core::norm(x[i] - x[j]); d < reach) brute += value[j] * weight(d);
        }
        ASSERT_NEAR(sums[i], brute, 1e-12 * std::max(1.0, std::abs(brute))) << "point " << i;
    }
}

/// Each owned point spreads v_i w(d) onto every other point within reach, ghosts included; reverse_add then
/// brings the ghosts' share to their owners. Brute force: what each owner receives from the images of
/// the spreading points, in its own frame.
template <int Dim>
void expect_reverse_add_returns_what_landed_on_images(bool mirror, unsigned seed) {
    using Vec = core::Vec<Dim>;
    Vec lo = Vec::zero(), hi;
    for (int k = 0; k < Dim; ++k) hi[k] = 1.0;
    std::array<bool, Dim> axes{};
    axes[0] = true;
    const auto box = neighbors::PeriodicBox<Dim>::make(axes, lo, hi);
    const auto x = random_points<Dim>(300, lo, hi, seed);
    const auto n = static_cast<Index>(x.size());
    auto s = with_ghosts<Dim>(x, mirror ? mirror_ghosts<Dim>(x.data(), n, 0, reach)
                                        : periodic_ghosts<Dim>(x.data(), n, box, reach));
    std::mt19937 rng(seed + 1);
    std::vector<Vec> v(x.size());
    for (auto& vi : v)
        for (int k = 0; k < Dim; ++k) vi[k] = std::uniform_real_distribution<double>(-1.0, 1.0)(rng);

    std::vector<Vec> received(s.x.size(), Vec::zero());
    for (Index i = 0; i < s.owned; ++i)
        for (std::size_t j = 0; j < s.x.size(); ++j) {
            if (static_cast<Index>(j) == i) continue;
            const double d = core::norm(s.x[static_cast<std::size_t>(i)] - s.x[j]);
            if (d < reach) received[j] += weight(d) * v[static_cast<std::size_t>(i)];
        }
    s.halo.reverse_add(received.data());

    for (std::size_t j = 0; j < x.size(); ++j) {
        Vec brute = Vec::zero();
        for (std::size_t i = 0; i < x.size(); ++i) {
            if (mirror) {
                // Onto j itself, and onto j's mirror image (what lands there comes back mirrored).
                if (i != j)
                    if (const double d = core::norm(x[i] - x[j]); d < reach) brute += weight(d) * v[i];
                Vec image = x[j];
                image[0] = -image[0];
                if (const double d = core::norm(x[i] - image); image[0] > -reach && d < reach) {
                    Vec back = weight(d) * v[i];
                    back[0] = -back[0];
                    brute += back;
                }
            } else if (i != j) {
                if (const double d = core::norm(box.nearest_image(x[i] - x[j])); d < reach) brute += weight(d) * v[i];
            }
        }
        for (int k = 0; k < Dim; ++k)
            ASSERT_NEAR(received[j][k], brute[k], 1e-12 * std::max(1.0, std::abs(brute[k]))) << "point " << j;
    }
}

TEST(Halo, ReverseAddReturnsWhatLandedOnGhostsToTheirOwners) {
    expect_reverse_add_returns_what_landed_on_images<2>(false, 31);
    expect_reverse_add_returns_what_landed_on_images<3>(false, 32);
    expect_reverse_add_returns_what_landed_on_images<2>(true, 33);
    expect_reverse_add_returns_what_landed_on_images<3>(true, 34);
}

TEST(Halo, ForwardCarriesEveryFieldOfARegistry) {
    particles::FieldRegistry fields;
    auto& x = fields.add<core::Vec<2>>("position", core::Vec<2>::zero(), true);
    auto& u = fields.add<core::Vec<2>>("velocity", core::Vec<2>::zero(), true);
    auto& rho = fields.add<double>("density", 0.0, true);
    auto& tau = fields.add<core::SymTensor3>("stress", core::SymTensor3{}, true);
    auto& id = fields.add<std::int32_t>("id", 0, true);
    fields.resize(4);
    x[0] = {0.05, 0.5};
    u[0] = {1.0, 2.0};
    rho[0] = 1000.0;
    tau[0].xy = 3.0;
    tau[0].yz = 4.0;
    id[0] = 7;
    x[1] = {0.95, 0.25};
    u[1] = {-1.0, 0.5};
    rho[1] = 998.0;
    id[1] = 8;
    Halo<2> halo;
    halo.add(0, 2, GhostTransform<2>::mirror(0));
    halo.add(1, 3, GhostTransform<2>::periodic({-1.0, 0.0}));
    halo.forward(fields, x.data());
    EXPECT_EQ(x[2][0], -0.05);
    EXPECT_EQ(x[2][1], 0.5);
    EXPECT_EQ(u[2][0], -1.0);
    EXPECT_EQ(u[2][1], 2.0);
    EXPECT_EQ(rho[2], 1000.0);
    EXPECT_EQ(tau[2].xy, -3.0);  // the shear across the plane changes sign, the one along it does not
    EXPECT_EQ(tau[2].yz, 4.0);
    EXPECT_EQ(id[2], 7);
    EXPECT_NEAR(x[3][0], -0.05, 1e-15);
    EXPECT_EQ(x[3][1], 0.25);
    EXPECT_EQ(u[3][0], -1.0);  // a periodic image moves as its owner does
    EXPECT_EQ(rho[3], 998.0);
    EXPECT_EQ(id[3], 8);
}

}  // namespace
}  // namespace grit::domain
