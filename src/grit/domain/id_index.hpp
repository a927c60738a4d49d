// The local index of each particle id in a set. A particle's place in the arrays changes with every sort,
// removal and (over many processes) migration; its id does not, so whatever must find a particle again
// (a mirror image's source, a contact's partner) looks it up here by id.
#pragma once

#include <stdexcept>
#include <string>
#include <unordered_map>

#include "grit/core/types.hpp"
#include "grit/domain/particle_id.hpp"

namespace grit::domain {

class IdIndex {
public:
    /// Indexes ids[0, n) (rebuild after the set is sorted or changed). Ids must be unique: a repeated
    /// id is a std::logic_error (two particles were given one id).
    void build(const ParticleId* ids, Index n) {
        index_.clear();
        index_.reserve(static_cast<std::size_t>(n));
        for (Index i = 0; i < n; ++i)
            if (!index_.emplace(ids[i], i).second)
                throw std::logic_error("particle id " + std::to_string(ids[i]) + " (" + describe_id(ids[i]) +
                                       ") is held by two particles");
    }
    /// Adds one id at index i (a set that grew without being re-sorted).
    void add(ParticleId id, Index i) {
        if (!index_.emplace(id, i).second)
            throw std::logic_error("particle id " + std::to_string(id) + " is held by two particles");
    }
    /// The local index of `id`, or -1 when no particle here has it.
    Index find(ParticleId id) const {
        const auto it = index_.find(id);
        return it == index_.end() ? Index{-1} : it->second;
    }
    std::size_t size() const noexcept { return index_.size(); }

private:
    std::unordered_map<ParticleId, Index> index_;
};

}  // namespace grit::domain
