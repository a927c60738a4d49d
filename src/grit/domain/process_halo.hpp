// The process side of the domain layer: ghosts of particles that another sub-domain owns, and the particles
// that move to the sub-domain that owns them now, over domain::Comm's messages (one process, a loopback of
// sub-domains in tests, or MPI ranks: the same calls).
//
// At a reneighbour point every rank, together: drop_ghosts, migrate (each owned particle that left the slab
// goes to its new owner with every field, its id included), make_ghosts (a copy of every particle another
// rank owns within the ghost width of this rank's slab). The set is then sorted and its lists built, and
// resolve() finds the ghosts and their owners again by id. Between reneighbour points, forward() refreshes
// the ghosts from their owners wherever a stage derived a value that sums read of a ghost (the predicted
// velocity and density, a wall's pressure), and reverse_add() hands back what a stage spread onto ghosts.
// A ghost keeps its owner's id: a cluster's label (the smallest id in it) and a contact's history are keyed
// by ids, and must read the same on both sides of a cut. The registry field `ghost` (1 on ghosts, 0 on the
// particles a rank owns; neither written nor saved) tells them apart.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

#include "grit/core/types.hpp"
#include "grit/domain/comm.hpp"
#include "grit/domain/id_index.hpp"
#include "grit/domain/slab_partition.hpp"
#include "grit/particles/sph_particles.hpp"

namespace grit::domain {

template <int Dim>
class ProcessHalo {
public:
    using Particles = particles::SphParticles<Dim>;

    static constexpr const char* ghost_field = "ghost";

    /// Each particle's ghost mark (non-zero: a copy of another rank's particle), or null while the set has
    /// never held ghosts. Read it once, outside a loop over particles (the field is found by name).
    static const std::int32_t* ghost_marks(const Particles& ps) {
        return ps.fields().has(ghost_field) ? ps.fields().template get<std::int32_t>(ghost_field).data() : nullptr;
    }

    /// Removes this rank's ghosts.
    void drop_ghosts(Particles& ps) {
        const std::int32_t* ghost = marks(ps);
        std::vector<Index> keep;
        keep.reserve(static_cast<std::size_t>(ps.size()));
        for (Index i = 0; i < ps.size(); ++i)
            if (!ghost[i]) keep.push_back(i);
        if (static_cast<Index>(keep.size()) != ps.size()) ps.remove(keep);
        send_ids_.clear();
        ghost_ids_.clear();
        send_rows_.clear();
        ghost_rows_.clear();
    }

    /// Sends each owned particle outside this rank's slab to the rank whose slab holds it, every field
    /// included, and takes in those sent here (in rank order, each rank's in its order). Ghosts must have
    /// been dropped. Returns how many particles left this rank.
    Index migrate(Particles& ps, const SlabPartition<Dim>& partition, const Comm& comm) {
        partition.check(comm.size());
        const int rank = comm.rank();
        std::vector<std::vector<Index>> leaving(static_cast<std::size_t>(comm.size()));
        std::vector<Index> keep;
        keep.reserve(static_cast<std::size_t>(ps.size()));
        const auto* x = ps.position();
        const std::int32_t* ghost = marks(ps);
        for (Index i = 0; i < ps.size(); ++i) {
            if (ghost[i]) throw std::logic_error("migrate: drop the ghosts first");
            const int owner = partition.owner(x[i]);
            if (owner == rank)
                keep.push_back(i);
            else
                leaving[static_cast<std::size_t>(owner)].push_back(i);
        }
        std::vector<Comm::Message> outgoing(static_cast<std::size_t>(comm.size()));
        for (std::size_t r = 0; r < outgoing.size(); ++r) outgoing[r] = ps.fields().pack(leaving[r]);
        const Index left = ps.size() - static_cast<Index>(keep.size());
        if (left > 0) ps.remove(keep);
        append(ps, comm.exchange(std::move(outgoing)), false);
        return left;
    }

    /// Makes this rank's ghosts afresh: every particle another rank owns within `width` of this rank's
    /// slab along the cut axis (the largest reach of any sum, with the lists' skin), with its owner's
    /// values. The set must hold no ghosts (drop_ghosts).
    void make_ghosts(Particles& ps, const SlabPartition<Dim>& partition, double width, const Comm& comm) {
        partition.check(comm.size());
        const auto ranks = static_cast<std::size_t>(comm.size());
        std::vector<std::vector<Index>> sending(ranks);
        const auto* x = ps.position();
        const std::int32_t* ghost = marks(ps);
        for (Index i = 0; i < ps.size(); ++i) {
            if (ghost[i]) throw std::logic_error("make_ghosts: drop the old ghosts first");
            for (int r = 0; r < comm.size(); ++r)
                if (r != comm.rank() && partition.distance(x[i], r) < width)
                    sending[static_cast<std::size_t>(r)].push_back(i);
        }
        std::vector<Comm::Message> outgoing(ranks);
        send_ids_.assign(ranks, {});
        for (std::size_t r = 0; r < ranks; ++r) {
            outgoing[r] = ps.fields().pack(sending[r]);
            for (const Index i : sending[r]) send_ids_[r].push_back(ps.id()[i]);
        }
        ghost_ids_ = append(ps, comm.exchange(std::move(outgoing)), true);
        resolve(ps);
    }

    /// Finds, by id, the particles this rank sends to each rank and its own ghosts again (after a sort).
    void resolve(const Particles& ps) {
        IdIndex index;
        index.build(ps.id(), ps.size());
        const std::int32_t* ghost = ghost_marks(ps);
        auto rows_of = [&](const std::vector<std::vector<ParticleId>>& ids, bool ghosts) {
            std::vector<std::vector<Index>> rows(ids.size());
            for (std::size_t r = 0; r < ids.size(); ++r)
                for (const ParticleId id : ids[r]) {
                    const Index i = index.find(id);
                    if (i < 0 || !ghost || (ghost[i] != 0) != ghosts)
                        throw std::logic_error("halo: " + std::string(ghosts ? "the ghost of particle " : "particle ") +
                                               std::to_string(id) + " (" + describe_id(id) +
                                               ") is gone since the ghosts were made");
                    rows[r].push_back(i);
                }
            return rows;
        };
        send_rows_ = rows_of(send_ids_, false);
        ghost_rows_ = rows_of(ghost_ids_, true);
        resolved_ = ps.generation();
    }

    /// Every field of each owner onto its ghosts.
    void forward(Particles& ps, const Comm& comm) const {
        require_resolved(ps);
        std::vector<Comm::Message> outgoing(send_rows_.size());
        for (std::size_t r = 0; r < outgoing.size(); ++r) outgoing[r] = ps.fields().pack(send_rows_[r]);
        const auto incoming = comm.exchange(std::move(outgoing));
        std::int32_t* ghost = marks(ps);
        for (std::size_t r = 0; r < incoming.size(); ++r) {
            ps.fields().unpack(incoming[r], ghost_rows_[r]);
            for (const Index g : ghost_rows_[r]) ghost[g] = 1;
        }
    }

    /// One array (a value per particle of the set): each owner's value onto its ghosts.
    template <class T>
    void forward(const Particles& ps, T* values, const Comm& comm) const {
        require_resolved(ps);
        std::vector<Comm::Message> outgoing(send_rows_.size());
        for (std::size_t r = 0; r < outgoing.size(); ++r) outgoing[r] = pack(values, send_rows_[r]);
        const auto incoming = comm.exchange(std::move(outgoing));
        for (std::size_t r = 0; r < incoming.size(); ++r) unpack(incoming[r], values, ghost_rows_[r], false);
    }

    /// What a stage added to ghosts (values[g] for each ghost g) added onto their owners, rank after rank
    /// in the order the owners were sent: the same sums whatever the threads.
    template <class T>
    void reverse_add(const Particles& ps, T* values, const Comm& comm) const {
        require_resolved(ps);
        std::vector<Comm::Message> outgoing(ghost_rows_.size());
        for (std::size_t r = 0; r < outgoing.size(); ++r) outgoing[r] = pack(values, ghost_rows_[r]);
        const auto incoming = comm.exchange(std::move(outgoing));
        for (std::size_t r = 0; r < incoming.size(); ++r) unpack(incoming[r], values, send_rows_[r], true);
    }

    /// The ghosts this rank holds, and the copies of its particles it sends, over every rank.
    std::size_t ghost_count() const { return total(ghost_ids_); }
    std::size_t sent_count() const { return total(send_ids_); }

private:
    /// The ghost marks, registered on first use (every rank at the same call, so that the registries
    /// pack alike).
    static std::int32_t* marks(Particles& ps) {
        return ps.fields().template add<std::int32_t>(ghost_field, 0, false, false).data();
    }
    /// Appends what each rank sent (every field), rank after rank; as ghosts (marked), or as particles
    /// this rank now owns. Returns their ids, per sending rank.
    static std::vector<std::vector<ParticleId>> append(Particles& ps, const std::vector<Comm::Message>& incoming,
                                                       bool ghosts) {
        const std::size_t entry = ps.fields().entry_bytes();
        std::vector<std::vector<ParticleId>> ids(incoming.size());
        for (std::size_t r = 0; r < incoming.size(); ++r) {
            const auto n = static_cast<Index>(incoming[r].size() / entry);
            if (n == 0) continue;
            const Index first = ps.append_received(n);
            std::vector<Index> rows(static_cast<std::size_t>(n));
            for (Index k = 0; k < n; ++k) rows[static_cast<std::size_t>(k)] = first + k;
            ps.fields().unpack(incoming[r], rows);
            std::int32_t* ghost = marks(ps);
            for (const Index i : rows) {
                ids[r].push_back(ps.id()[i]);
                ghost[i] = ghosts ? 1 : 0;
            }
        }
        return ids;
    }
    template <class T>
    static Comm::Message pack(const T* values, const std::vector<Index>& rows) {
        Comm::Message out(rows.size() * sizeof(T));
        for (std::size_t k = 0; k < rows.size(); ++k) std::memcpy(out.data() + k * sizeof(T), &values[rows[k]], sizeof(T));
        return out;
    }
    template <class T>
    static void unpack(const Comm::Message& in, T* values, const std::vector<Index>& rows, bool add) {
        if (in.size() != rows.size() * sizeof(T)) throw std::logic_error("halo: a message of the wrong size");
        for (std::size_t k = 0; k < rows.size(); ++k) {
            T v;
            std::memcpy(&v, in.data() + k * sizeof(T), sizeof(T));
            if (add)
                values[rows[k]] += v;
            else
                values[rows[k]] = v;
        }
    }
    void require_resolved(const Particles& ps) const {
        if (resolved_ != ps.generation())
            throw std::logic_error("halo used after the set changed: call resolve() after a sort");
    }
    static std::size_t total(const std::vector<std::vector<ParticleId>>& ids) {
        std::size_t n = 0;
        for (const auto& r : ids) n += r.size();
        return n;
    }

    std::vector<std::vector<ParticleId>> send_ids_;   ///< per rank: the ids of this rank's particles it copies
    std::vector<std::vector<ParticleId>> ghost_ids_;  ///< per rank: the owners' ids of the ghosts it sent here
    std::vector<std::vector<Index>> send_rows_, ghost_rows_;  ///< the same, as local indices (resolve)
    std::uint64_t resolved_ = ~std::uint64_t{0};
};

}  // namespace grit::domain
