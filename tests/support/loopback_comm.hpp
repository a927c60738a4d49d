// Sub-domains in one process, each run by its own thread, whose reductions and messages meet in shared
// memory behind domain::Comm: the path a run over many processes takes (halo, migration, reductions over
// ranks) tested before MPI exists. Reductions fold the ranks' values in rank order, as the MPI communicator
// will, so that sums do not depend on which thread arrives first.
#pragma once

#include <algorithm>
#include <barrier>
#include <cmath>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>
#include <utility>
#include <vector>

#include "grit/domain/comm.hpp"
#include "grit/parallel/parallel.hpp"

namespace grit::testing {

class LoopbackComm final : public domain::Comm {
public:
    /// What the ranks share: one slot each per kind of value, and a mailbox per pair of ranks.
    struct Shared {
        explicit Shared(int n)
            : size(n), barrier(n), reals(static_cast<std::size_t>(n)), ids(static_cast<std::size_t>(n)),
              flags(static_cast<std::size_t>(n)), arrays(static_cast<std::size_t>(n)),
              mail(static_cast<std::size_t>(n)) {}
        int size;
        std::barrier<> barrier;
        std::vector<double> reals;
        std::vector<std::int64_t> ids;
        std::vector<char> flags;
        std::vector<std::vector<double>> arrays;
        std::vector<std::vector<Message>> mail;  ///< [from][to]
    };

    LoopbackComm(Shared& shared, int rank) : shared_(shared), rank_(rank) {}
    int rank() const override { return rank_; }
    int size() const override { return shared_.size; }
    double min(double v) const override { return fold(v, [](double a, double b) { return std::fmin(a, b); }); }
    double max(double v) const override { return fold(v, [](double a, double b) { return std::fmax(a, b); }); }
    double sum(double v) const override { return fold(v, [](double a, double b) { return a + b; }); }
    std::int64_t min_id(std::int64_t v) const override {
        shared_.ids[me()] = v;
        sync();
        const std::int64_t r = *std::min_element(shared_.ids.begin(), shared_.ids.end());
        sync();
        return r;
    }
    bool any(bool v) const override {
        shared_.flags[me()] = v;
        sync();
        const bool r = std::any_of(shared_.flags.begin(), shared_.flags.end(), [](char f) { return f != 0; });
        sync();
        return r;
    }
    void max_each(std::vector<double>& values) const override {
        each(values, [](double a, double b) { return std::fmax(a, b); });
    }
    void sum_each(std::vector<double>& values) const override {
        each(values, [](double a, double b) { return a + b; });
    }
    std::vector<Message> exchange(std::vector<Message> outgoing) const override {
        if (outgoing.size() != static_cast<std::size_t>(size())) throw std::logic_error("a message per rank");
        shared_.mail[me()] = std::move(outgoing);
        sync();
        std::vector<Message> incoming(static_cast<std::size_t>(size()));
        for (std::size_t r = 0; r < incoming.size(); ++r) incoming[r] = shared_.mail[r][me()];
        sync();
        return incoming;
    }

private:
    std::size_t me() const { return static_cast<std::size_t>(rank_); }
    void sync() const { shared_.barrier.arrive_and_wait(); }
    template <class Op>
    double fold(double v, Op op) const {
        shared_.reals[me()] = v;
        sync();
        double r = shared_.reals[0];
        for (std::size_t k = 1; k < shared_.reals.size(); ++k) r = op(r, shared_.reals[k]);
        sync();
        return r;
    }
    template <class Op>
    void each(std::vector<double>& values, Op op) const {
        shared_.arrays[me()] = values;
        sync();
        values = shared_.arrays[0];
        for (std::size_t k = 1; k < shared_.arrays.size(); ++k)
            for (std::size_t i = 0; i < values.size(); ++i) values[i] = op(values[i], shared_.arrays[k][i]);
        sync();
    }

    Shared& shared_;
    int rank_;
};

/// Runs body(comm) on `ranks` sub-domains at once, each in its own thread with one OpenMP thread (as an MPI
/// test runs each process), and rethrows the first exception any of them threw (a rank that throws leaves
/// the barrier, so the others do not wait for it).
inline void run_loopback(int ranks, const std::function<void(const domain::Comm&)>& body) {
    LoopbackComm::Shared shared(ranks);
    std::exception_ptr failure;
    std::mutex failure_mutex;
    std::vector<std::thread> threads;
    for (int r = 0; r < ranks; ++r)
        threads.emplace_back([&, r] {
            try {
                parallel::set_threads(1);
                const LoopbackComm comm(shared, r);
                body(comm);
            } catch (...) {
                {
                    const std::lock_guard lock(failure_mutex);
                    if (!failure) failure = std::current_exception();
                }
                shared.barrier.arrive_and_drop();
            }
        });
    for (auto& t : threads) t.join();
    if (failure) std::rethrow_exception(failure);
}

}  // namespace grit::testing
