// The communicator a run's reductions go through: the one time step (min), the rebuild decision (any), and
// every output value by its combine kind. A run in one process has the serial communicator, rank 0 of 1,
// whose reductions return their argument; a run over many processes puts its own behind the same calls,
// so that no module or analysis changes when it does.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

namespace grit::domain {

/// How an output value of one sub-domain combines with the others' into the run's value.
enum class Combine {
    same,       ///< every sub-domain holds the same value (time, step, dt, a set-up constant, or a value its
                ///< module combined itself: a crater from its combined bins, a mean from its combined sums)
    sum,        ///< a sum over particles or events (mass, energy, counts)
    min,        ///< a minimum over particles (the smallest porosity)
    max,        ///< a maximum over particles (the fastest speed, the largest plastic strain)
    whole_set,  ///< needs the whole set, not a combination of local values (the crack count's labels):
                ///< computed by its module from labels the sub-domains exchange
};

/// The name of a combine kind, as documentation and messages write it.
inline const char* combine_name(Combine c) {
    switch (c) {
        case Combine::same: return "same";
        case Combine::sum: return "sum";
        case Combine::min: return "min";
        case Combine::max: return "max";
        case Combine::whole_set: return "whole_set";
    }
    return "unknown";
}

class Comm {
public:
    virtual ~Comm() = default;
    /// This sub-domain's rank and the number of sub-domains.
    virtual int rank() const = 0;
    virtual int size() const = 0;
    /// Collective reductions over every rank. min and max leave NaN out (a sub-domain that has no value
    /// yet, such as no removal yet, reports NaN): NaN only when every rank has NaN.
    virtual double min(double value) const = 0;
    virtual double max(double value) const = 0;
    virtual double sum(double value) const = 0;
    /// The smallest of the ranks' integers (a particle id: ids need all 64 bits, which a double does not hold).
    virtual std::int64_t min_id(std::int64_t value) const = 0;
    /// True on every rank when `value` is true on any: the shared neighbour-list rebuild decision (the
    /// sub-domain tests take it; a run's lists are still rebuilt by their owners).
    virtual bool any(bool value) const = 0;
    /// Element-wise reductions, in place, of arrays every rank holds with the same length: the local pass
    /// of an analysis (a crater's bins, the probes' partial sums) becomes the run's. max_each leaves NaN
    /// out as max does (a bin no rank has a particle in stays NaN).
    virtual void max_each(std::vector<double>& values) const = 0;
    virtual void sum_each(std::vector<double>& values) const = 0;
    /// Point to point, every rank at once: outgoing[r] goes to rank r (empty: nothing for it), and the
    /// result's [r] is what rank r sent this one (a halo's values, migrating particles).
    using Message = std::vector<std::byte>;
    virtual std::vector<Message> exchange(std::vector<Message> outgoing) const = 0;

    /// `value` of this rank combined with the others' by `kind`. `same` returns it as it is (every rank
    /// holds it); `whole_set` values are computed by their module (from exchanged labels), not here.
    double combine(Combine kind, double value) const {
        switch (kind) {
            case Combine::sum: return sum(value);
            case Combine::min: return min(value);
            case Combine::max: return max(value);
            case Combine::same:
            case Combine::whole_set: return value;
        }
        return value;
    }
};

/// The union of the ids every rank holds, sorted, each once, on every rank (the fragments that some
/// sub-domain's particles anchor to intact rock).
inline std::vector<std::int64_t> unite(const Comm& comm, std::vector<std::int64_t> ids) {
    Comm::Message mine(ids.size() * sizeof(std::int64_t));
    if (!ids.empty()) std::memcpy(mine.data(), ids.data(), mine.size());
    const auto all = comm.exchange(std::vector<Comm::Message>(static_cast<std::size_t>(comm.size()), mine));
    ids.clear();
    for (const auto& m : all) {
        const std::size_t first = ids.size();
        ids.resize(first + m.size() / sizeof(std::int64_t));
        if (!m.empty()) std::memcpy(ids.data() + first, m.data(), m.size());
    }
    std::sort(ids.begin(), ids.end());
    ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
    return ids;
}

/// One process, one sub-domain: every reduction is the value itself.
class SerialComm final : public Comm {
public:
    int rank() const override { return 0; }
    int size() const override { return 1; }
    double min(double value) const override { return value; }
    double max(double value) const override { return value; }
    double sum(double value) const override { return value; }
    std::int64_t min_id(std::int64_t value) const override { return value; }
    bool any(bool value) const override { return value; }
    void max_each(std::vector<double>&) const override {}
    void sum_each(std::vector<double>&) const override {}
    std::vector<Message> exchange(std::vector<Message> outgoing) const override {
        if (outgoing.size() != 1) throw std::logic_error("one process: a message for a rank other than 0");
        return outgoing;
    }
};

}  // namespace grit::domain
