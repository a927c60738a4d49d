// Ghosts: copies of owned particles that stand in the sums of particles near a periodic face or a mirror
// plane (and, under MPI, near another sub-domain). A particle set holds its owned particles, then its
// ghosts; a Halo records which owner each ghost copies and how (a periodic shift, a mirror reflection),
// and moves values along that record: forward (owner to ghost) and reverse_add (what a stage added to a
// ghost, back onto its owner). A pair with a ghost is computed on the owner's side, so reverse_add is only
// for a stage that spreads a contribution onto particles it does not own.
#pragma once

#include <array>
#include <cstddef>
#include <stdexcept>
#include <type_traits>
#include <utility>
#include <vector>

#include "grit/core/types.hpp"
#include "grit/core/vec.hpp"
#include "grit/neighbors/periodic_box.hpp"
#include "grit/particles/field_registry.hpp"

namespace grit::domain {

/// How a ghost is made from its owner: mirrored in the plane through the origin normal to `mirror_axis`
/// (if >= 0), then shifted by `shift` (a periodic image). Directions (velocities, forces) are mirrored,
/// never shifted.
template <int Dim>
struct GhostTransform {
    using Vec = core::Vec<Dim>;
    Vec shift = Vec::zero();
    int mirror_axis = -1;
    bool shifted = false;  ///< whether shift applies (a mirror alone leaves positions as mirror_copy made them)

    static GhostTransform periodic(const Vec& s) { return {s, -1, true}; }
    static GhostTransform mirror(int axis) { return {Vec::zero(), axis, false}; }

    /// A position of the owner as the ghost sees it.
    Vec position(Vec x) const {
        if (mirror_axis >= 0) x[mirror_axis] = -x[mirror_axis];
        if (shifted) x += shift;
        return x;
    }
    /// A direction (velocity, force) of the owner as the ghost sees it, and back: a mirror is its own inverse.
    Vec direction(Vec v) const {
        if (mirror_axis >= 0) v[mirror_axis] = -v[mirror_axis];
        return v;
    }
};

template <int Dim>
class Halo {
public:
    using Vec = core::Vec<Dim>;
    using Transform = GhostTransform<Dim>;

    void clear() {
        owners_.clear();
        ghosts_.clear();
        transforms_.clear();
        grouped_ = false;
    }
    /// Ghost `ghost` (an index past the owned range) copies owner `owner` under `t`.
    void add(Index owner, Index ghost, const Transform& t) {
        owners_.push_back(owner);
        ghosts_.push_back(ghost);
        transforms_.push_back(t);
        grouped_ = false;
    }
    std::size_t size() const { return owners_.size(); }
    const std::vector<Index>& owners() const { return owners_; }
    const std::vector<Index>& ghosts() const { return ghosts_; }
    const std::vector<Transform>& transforms() const { return transforms_; }

    /// Owner to ghost in every field of `fields`: each ghost entry becomes its owner's, mirrored where its
    /// transform mirrors (vectors and tensors as FieldBase::mirror_copy says), then `position` (the set's
    /// positions, one of those fields) shifted where it shifts.
    void forward(particles::FieldRegistry& fields, Vec* position) const {
        group();
        // One pass per kind of transform, in entry order within each: the same copies as one by one.
        for (int axis = -1; axis < Dim; ++axis) {
            const Group& g = groups_[static_cast<std::size_t>(axis + 1)];
            if (g.from.empty()) continue;
            if (axis < 0)
                fields.copy(g.from, g.to);
            else
                fields.mirror_copy(g.from, g.to, axis);
        }
        for (const std::size_t k : shifted_)
            position[ghosts_[k]] += transforms_[k].shift;
    }

    /// Owner to ghost for the set's positions alone (mirrored and shifted).
    void forward_positions(Vec* position) const {
        for (std::size_t k = 0; k < size(); ++k) position[ghosts_[k]] = transforms_[k].position(position[owners_[k]]);
    }

    /// Owner to ghost for one array: scalars copied, vectors as directions (mirrored, not shifted).
    template <class T>
    void forward(T* values) const {
        for (std::size_t k = 0; k < size(); ++k) values[ghosts_[k]] = carried(values[owners_[k]], transforms_[k]);
    }

    /// What a stage added to the ghosts, back onto their owners: owner_values[owner(k)] += ghost_values[k]
    /// (entry k), directions mirrored back. Entries are added in order, so the sums do not depend on
    /// threads.
    template <class T>
    void reverse_add(const T* ghost_values, T* owner_values) const {
        for (std::size_t k = 0; k < size(); ++k) owner_values[owners_[k]] += carried(ghost_values[k], transforms_[k]);
    }
    /// The same with the ghosts' own entries of `values` (values[ghost(k)]).
    template <class T>
    void reverse_add(T* values) const {
        for (std::size_t k = 0; k < size(); ++k) values[owners_[k]] += carried(values[ghosts_[k]], transforms_[k]);
    }

private:
    template <class T>
    static T carried(const T& v, const Transform& t) {
        // Tensors would need mirroring too: whole registries go through forward(fields, position).
        static_assert(std::is_arithmetic_v<T> || std::is_same_v<T, Vec>, "one array of numbers or vectors");
        if constexpr (std::is_same_v<T, Vec>)
            return t.direction(v);
        else
            return v;
    }

    /// The entries by kind of transform (no mirror, then each mirror axis), and those that shift: made
    /// once per set of entries, as a halo is forwarded several times a step between its rebuilds.
    struct Group {
        std::vector<Index> from, to;
    };
    void group() const {
        if (grouped_) return;
        for (auto& g : groups_) {
            g.from.clear();
            g.to.clear();
        }
        shifted_.clear();
        for (std::size_t k = 0; k < size(); ++k) {
            Group& g = groups_[static_cast<std::size_t>(transforms_[k].mirror_axis + 1)];
            g.from.push_back(owners_[k]);
            g.to.push_back(ghosts_[k]);
            if (transforms_[k].shifted) shifted_.push_back(k);
        }
        grouped_ = true;
    }

    std::vector<Index> owners_, ghosts_;
    std::vector<Transform> transforms_;
    mutable std::array<Group, Dim + 1> groups_;
    mutable std::vector<std::size_t> shifted_;
    mutable bool grouped_ = false;
};

/// The periodic ghosts of `n` points `x` inside `box`: one per owner within `width` of a periodic face and
/// per combination of such faces (an edge or a corner of the box gives the images across each face and
/// across both), as (owner, transform) in owner order. `width` must be less than half of each period.
template <int Dim>
std::vector<std::pair<Index, GhostTransform<Dim>>> periodic_ghosts(const core::Vec<Dim>* x, Index n,
                                                                   const neighbors::PeriodicBox<Dim>& box,
                                                                   double width) {
    for (int k = 0; k < Dim; ++k)
        if (box.periodic[k] && !(2.0 * width < box.length(k)))
            throw std::invalid_argument("periodic_ghosts: the ghost width must be less than half the period");
    std::vector<std::pair<Index, GhostTransform<Dim>>> out;
    for (Index i = 0; i < n; ++i) {
        // Per axis: the shift of the image across the near face (0: none).
        std::array<double, Dim> s{};
        for (int k = 0; k < Dim; ++k) {
            if (!box.periodic[k]) continue;
            if (x[i][k] < box.lower[k] + width)
                s[k] = box.length(k);
            else if (x[i][k] >= box.upper[k] - width)
                s[k] = -box.length(k);
        }
        // Every non-empty subset of the axes with a shift.
        for (int mask = 1; mask < (1 << Dim); ++mask) {
            core::Vec<Dim> shift = core::Vec<Dim>::zero();
            bool valid = true;
            for (int k = 0; k < Dim && valid; ++k)
                if (mask & (1 << k)) {
                    if (s[k] == 0.0) valid = false;
                    shift[k] = s[k];
                }
            if (valid) out.emplace_back(i, GhostTransform<Dim>::periodic(shift));
        }
    }
    return out;
}

/// The mirror ghosts of `n` points `x` in the plane through the origin normal to `axis`: one per point
/// closer than `width` to it, as (owner, transform) in owner order.
template <int Dim>
std::vector<std::pair<Index, GhostTransform<Dim>>> mirror_ghosts(const core::Vec<Dim>* x, Index n, int axis,
                                                                 double width) {
    std::vector<std::pair<Index, GhostTransform<Dim>>> out;
    for (Index i = 0; i < n; ++i)
        if (x[i][axis] < width) out.emplace_back(i, GhostTransform<Dim>::mirror(axis));
    return out;
}

}  // namespace grit::domain
