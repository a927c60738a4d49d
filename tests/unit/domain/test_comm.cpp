// The communicator's reductions and the combine kinds of output values.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <mutex>
#include <utility>
#include <vector>

#include "grit/domain/comm.hpp"
#include "support/loopback_comm.hpp"

namespace grit::domain {
namespace {

/// Rank 0 of a run whose other ranks hold `others`: the reductions over all of them, as a real
/// communicator would return them.
class FixedPeers final : public Comm {
public:
    explicit FixedPeers(std::vector<double> others) : others_(std::move(others)) {}
    int rank() const override { return 0; }
    int size() const override { return 1 + static_cast<int>(others_.size()); }
    double min(double v) const override {
        for (double o : others_) v = std::fmin(v, o);  // NaN left out, as Comm says
        return v;
    }
    double max(double v) const override {
        for (double o : others_) v = std::fmax(v, o);
        return v;
    }
    double sum(double v) const override {
        for (double o : others_) v += o;
        return v;
    }
    bool any(bool v) const override { return v || std::any_of(others_.begin(), others_.end(), [](double o) { return o != 0.0; }); }
    /// Each other rank holds its value in every element.
    void max_each(std::vector<double>& values) const override {
        for (double& v : values) v = max(v);
    }
    void sum_each(std::vector<double>& values) const override {
        for (double& v : values) v = sum(v);
    }
    std::int64_t min_id(std::int64_t v) const override { return v; }  // the others hold no ids
    std::vector<Message> exchange(std::vector<Message>) const override {
        throw std::logic_error("FixedPeers holds values, not messages");
    }

private:
    std::vector<double> others_;
};

TEST(Comm, SerialIsRankZeroOfOneAndReturnsItsArgument) {
    const SerialComm comm;
    EXPECT_EQ(comm.rank(), 0);
    EXPECT_EQ(comm.size(), 1);
    EXPECT_EQ(comm.min(2.5), 2.5);
    EXPECT_EQ(comm.max(-1.0), -1.0);
    EXPECT_EQ(comm.sum(0.1), 0.1);
    EXPECT_TRUE(comm.any(true));
    EXPECT_FALSE(comm.any(false));
    for (const auto kind : {Combine::same, Combine::sum, Combine::min, Combine::max, Combine::whole_set})
        EXPECT_EQ(comm.combine(kind, 0.3), 0.3) << combine_name(kind);
    std::vector<double> bins = {1.0, std::nan(""), -2.0};
    comm.max_each(bins);
    comm.sum_each(bins);
    EXPECT_EQ(bins[0], 1.0);
    EXPECT_TRUE(std::isnan(bins[1]));
    EXPECT_EQ(bins[2], -2.0);
}

// Element-wise: a bin no rank has a value in stays NaN; one some rank has takes the largest.
TEST(Comm, ElementWiseMaximumLeavesNaNOutAndSumAdds) {
    const FixedPeers one_nan({std::nan("")});
    std::vector<double> bins = {std::nan(""), 3.0};
    one_nan.max_each(bins);
    EXPECT_TRUE(std::isnan(bins[0]));
    EXPECT_EQ(bins[1], 3.0);
    const FixedPeers two({4.0, -1.0});
    bins = {std::nan(""), 5.0, 1.0};
    two.max_each(bins);
    EXPECT_EQ(bins, (std::vector<double>{4.0, 5.0, 4.0}));
    std::vector<double> sums = {0.5, 2.0};
    two.sum_each(sums);
    EXPECT_EQ(sums, (std::vector<double>{3.5, 5.0}));
}

TEST(Comm, EachCombineKindReducesAsItsNameSays) {
    const FixedPeers comm({4.0, -2.0});
    EXPECT_EQ(comm.size(), 3);
    EXPECT_EQ(comm.combine(Combine::sum, 1.0), 3.0);
    EXPECT_EQ(comm.combine(Combine::min, 1.0), -2.0);
    EXPECT_EQ(comm.combine(Combine::max, 1.0), 4.0);
    // Held alike by every rank, or computed over the gathered set by its module: left as it is.
    EXPECT_EQ(comm.combine(Combine::same, 1.0), 1.0);
    EXPECT_EQ(comm.combine(Combine::whole_set, 1.0), 1.0);
    EXPECT_TRUE(comm.any(false));  // another rank's list is stale: every rank rebuilds
    EXPECT_STREQ(combine_name(Combine::whole_set), "whole_set");
    // A rank with no value yet (NaN: no removal yet) leaves the others' minimum as it is.
    EXPECT_EQ(comm.combine(Combine::min, std::nan("")), -2.0);
    EXPECT_TRUE(std::isnan(FixedPeers({std::nan("")}).combine(Combine::min, std::nan(""))));
}

TEST(Comm, OneProcessSendsItsMessageToItself) {
    const SerialComm comm;
    const Comm::Message m = {std::byte{1}, std::byte{2}};
    const auto in = comm.exchange({m});
    ASSERT_EQ(in.size(), 1u);
    EXPECT_EQ(in[0], m);
    EXPECT_THROW(comm.exchange({m, m}), std::logic_error);
    EXPECT_EQ(unite(comm, {5, 3, 5}), (std::vector<std::int64_t>{3, 5}));
}

// Over three sub-domains (the loopback the process tests run on): messages reach the rank they are
// addressed to, ids keep all 64 bits (two ids a double would round to one), the ids of every rank are
// united, and a sum adds the ranks' values in rank order (the same bits whichever thread comes first).
TEST(Comm, ThreeSubDomainsExchangeReduceAndUnite) {
    constexpr std::int64_t big = (std::int64_t{1} << 60) + 1;  // beyond 2^53: a double holds 2^60
    std::mutex lock;
    std::vector<std::vector<std::int64_t>> seen(3);
    grit::testing::run_loopback(3, [&](const Comm& comm) {
        const int r = comm.rank();
        std::vector<Comm::Message> out(3);
        for (int to = 0; to < 3; ++to) out[static_cast<std::size_t>(to)] = {std::byte(10 * r + to)};
        const auto in = comm.exchange(out);
        for (int from = 0; from < 3; ++from)
            EXPECT_EQ(in[static_cast<std::size_t>(from)], Comm::Message{std::byte(10 * from + r)});
        EXPECT_EQ(comm.min_id(r == 1 ? big : big + 1), big);
        EXPECT_EQ(comm.sum(r == 0 ? 1.0 : r == 1 ? 1e-16 : 1e-16), (1.0 + 1e-16) + 1e-16);
        EXPECT_TRUE(comm.any(r == 2));
        EXPECT_FALSE(comm.any(false));
        const auto all = unite(comm, r == 0 ? std::vector<std::int64_t>{} : std::vector<std::int64_t>{7, r});
        const std::lock_guard guard(lock);
        seen[static_cast<std::size_t>(r)] = all;
    });
    for (const auto& s : seen) EXPECT_EQ(s, (std::vector<std::int64_t>{1, 2, 7}));
}

}  // namespace
}  // namespace grit::domain
