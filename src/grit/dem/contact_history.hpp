// Tangential spring history of grain-grain contacts (first seed paper eq. 9), keyed by persistent grain
// ids. Values sit beside the pair lists' entries (no look-up in the contact loop); when the lists are
// rebuilt, possibly after the grains were re-sorted or some removed, save() / restore() carry each
// contact's value over by the pair of ids.
//
// Each pair's value is held once, in the entry of its body a: the grain of lower index, which evaluates
// the pair (neighbors::HalfLists, each pair once). A re-sort can turn a pair round; its value is then
// negated (v_a - v_b and the normal both flip, so the history's increments v_t dt do).
#pragma once

#include <algorithm>
#include <cstdint>
#include <utility>
#include <vector>

#include "grit/core/types.hpp"
#include "grit/core/vec.hpp"
#include "grit/dem/grain_loop.hpp"
#include "grit/domain/particle_id.hpp"
#include "grit/io/hdf5_file.hpp"
#include "grit/neighbors/half_lists.hpp"

namespace grit::dem {

template <int Dim>
class ContactHistory {
public:
    using Vec = core::Vec<Dim>;

    /// delta_t of each same-phase entry of the pair lists (HalfLists::upper) [m]; zero when the pair is
    /// not in contact.
    Vec* values() noexcept { return values_.data(); }
    const Vec* values() const noexcept { return values_.data(); }
    std::size_t size() const noexcept { return values_.size(); }

    /// Keeps the non-zero values of the current lists with their grain ids (before a rebuild or a
    /// reordering). `ids` are those of the n grains the lists were cut for (grains appended since have no
    /// history yet).
    void save(const domain::ParticleId* ids, Index n, const neighbors::HalfLists& pairs) {
        saved_rows_.clear();
        saved_partner_.clear();
        saved_value_.clear();
        if (values_.size() != pairs.upper_size() || pairs.particle_count() > n) return;  // no history yet
        for (Index i = 0; i < pairs.particle_count(); ++i) {
            const auto first = static_cast<Index>(saved_partner_.size());
            for (Index k = pairs.upper_begin(i); k < pairs.upper_end(i); ++k) {
                const Vec& v = values_[static_cast<std::size_t>(k)];
                if (core::norm2(v) == 0.0) continue;
                saved_partner_.push_back(ids[pairs.upper()[k]]);
                saved_value_.push_back(v);
            }
            if (static_cast<Index>(saved_partner_.size()) > first)
                saved_rows_.push_back({ids[i], first, static_cast<Index>(saved_partner_.size())});
        }
        std::sort(saved_rows_.begin(), saved_rows_.end(),
                  [](const SavedRow& a, const SavedRow& b) { return a.owner < b.owner; });
    }

    /// Sizes the values to the new lists and fills each entry with the saved value of its pair of ids,
    /// negated where the pair's order turned round.
    void restore(const domain::ParticleId* ids, const neighbors::HalfLists& pairs) {
        values_.assign(pairs.upper_size(), Vec::zero());
        if (saved_rows_.empty()) return;
        // The saved row of grain `owner` (null if it holds none), and the value of its pair with `partner`.
        auto row_of = [&](domain::ParticleId owner) -> const SavedRow* {
            const auto row = std::lower_bound(saved_rows_.begin(), saved_rows_.end(), owner,
                                              [](const SavedRow& r, domain::ParticleId id) { return r.owner < id; });
            return row == saved_rows_.end() || row->owner != owner ? nullptr : &*row;
        };
        auto find = [&](const SavedRow* row, domain::ParticleId partner) -> const Vec* {
            if (!row) return nullptr;
            for (Index s = row->first; s < row->last; ++s)
                if (saved_partner_[static_cast<std::size_t>(s)] == partner)
                    return &saved_value_[static_cast<std::size_t>(s)];
            return nullptr;
        };
        for_each_grain(pairs.particle_count(), [&](Index i) {
            const SavedRow* own = row_of(ids[i]);
            for (Index k = pairs.upper_begin(i); k < pairs.upper_end(i); ++k) {
                const domain::ParticleId partner = ids[pairs.upper()[k]];
                if (const Vec* v = find(own, partner))
                    values_[static_cast<std::size_t>(k)] = *v;
                else if (const Vec* w = find(row_of(partner), ids[i]))
                    values_[static_cast<std::size_t>(k)] = -*w;
            }
        });
    }

    /// Writes everything (the values beside the current lists and the values saved by id) into
    /// `group`, bit for bit, for a checkpoint.
    void write(io::Hdf5Group& group) const {
        group.write("values", reinterpret_cast<const double*>(values_.data()), values_.size(), Dim);
        std::vector<std::int64_t> rows;
        for (const auto& r : saved_rows_) rows.insert(rows.end(), {r.owner, r.first, r.last});
        group.write("saved_rows", rows.data(), saved_rows_.size(), 3);
        group.write("saved_partner", saved_partner_.data(), saved_partner_.size(), 1);
        group.write("saved_value", reinterpret_cast<const double*>(saved_value_.data()), saved_value_.size(), Dim);
    }
    /// Reads back what write() wrote.
    void read(const io::Hdf5Group& group) {
        std::size_t n = 0;
        auto to_vecs = [](const std::vector<double>& raw) {
            std::vector<Vec> out(raw.size() / Dim);
            for (std::size_t i = 0; i < out.size(); ++i)
                for (int k = 0; k < Dim; ++k) out[i][k] = raw[i * Dim + static_cast<std::size_t>(k)];
            return out;
        };
        values_ = to_vecs(group.read_doubles("values", Dim, n));
        const auto rows = group.read_int64("saved_rows", 3, n);
        saved_rows_.clear();
        for (std::size_t r = 0; r < n; ++r)
            saved_rows_.push_back({rows[3 * r], static_cast<Index>(rows[3 * r + 1]),
                                   static_cast<Index>(rows[3 * r + 2])});
        saved_partner_ = group.read_int64("saved_partner", 1, n);
        saved_value_ = to_vecs(group.read_doubles("saved_value", Dim, n));
    }

    /// Number of pairs with a non-zero history.
    std::size_t active_pairs() const {
        std::size_t n = 0;
        for (const Vec& v : values_) n += core::norm2(v) != 0.0;
        return n;
    }

private:
    struct SavedRow {
        domain::ParticleId owner;
        Index first, last;
    };
    std::vector<Vec> values_;
    std::vector<SavedRow> saved_rows_;
    std::vector<domain::ParticleId> saved_partner_;
    std::vector<Vec> saved_value_;
};

}  // namespace grit::dem
