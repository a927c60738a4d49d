// Verlet neighbour lists in compressed rows, built from a cell grid over particles sorted by cell.
// Each particle lists every other particle within cutoff + skin (full lists, for gather loops); the
// lists stay valid until some particle has moved more than skin / 2. With periodic axes, pairs across
// a periodic face are listed too (their distance is that of the nearest image).
#pragma once

#include <cstdint>
#include <vector>

#include "grit/core/types.hpp"
#include "grit/core/vec.hpp"
#include "grit/neighbors/cell_grid.hpp"
#include "grit/neighbors/periodic_box.hpp"

namespace grit::neighbors {

/// The two sides of walls thinner than the kernel (second seed paper, sec. 3.2): per particle a unit
/// normal (zero where it does not matter) and a flag for the wall particles laid for a wall's far side
/// (a sheet folded back: they stand in the other side's water). A pair is left out when its normals
/// point away from each other (dot < 0) or, with a far-side particle in it, when they differ by more
/// than acos(far_cos): fluid by the fold's edge, whose normal is the edge's, belongs to neither side.
template <int Dim>
struct SideSeparation {
    const core::Vec<Dim>* normal = nullptr;
    const std::int32_t* far_side = nullptr;
    double far_cos = 0.5;
    bool apart(Index i, Index j) const {
        const double c = core::dot(normal[i], normal[j]);
        return c < 0.0 || ((far_side[i] | far_side[j]) != 0 && c < far_cos && core::norm2(normal[i]) > 0.0 &&
                           core::norm2(normal[j]) > 0.0);
    }
};

/// A new list version, never handed out before (process-wide): for every kind of list whose cuts
/// (HalfLists) are redone only when the version changes.
std::uint64_t next_list_version();

template <int Dim>
class NeighborList {
public:
    using Vec = core::Vec<Dim>;

    /// Builds the lists for x[0..n), which must be sorted by the cells of `grid` (cell_start from
    /// sort_by_cell after applying its order). `radius` is the list radius (cutoff + skin). Without
    /// periodic axes `grid` is a covering() grid; with them (`box`), an over_box() grid of the same
    /// periodic axes, cells of at least `radius`, and x[0..n) inside the box along them: cells wrap, and
    /// distances are those of the nearest image. With `phase`, pairs of two fixed wall particles are left
    /// out: nothing between them is computed. With `sides`, the pairs it sets apart are left out.
    void build(const CellGrid<Dim>& grid, const std::vector<Index>& cell_start, const Vec* x, Index n,
               double radius, const std::int32_t* phase = nullptr, const PeriodicBox<Dim>& box = {},
               const SideSeparation<Dim>* sides = nullptr);

    /// The lists of the set that kept old[keep[i]] as new[i] (keep ascending): the rows of removed
    /// particles and the entries naming them are dropped, the rest keep their order and stay valid for
    /// the same skin (removing particles moves none). Far cheaper than a build: no distances, no sort.
    void compact(const std::vector<Index>& keep);
    /// Lists as saved (offsets: n + 1 row starts; indices; the positions they were built at).
    void assign(std::vector<Index> offsets, std::vector<Index> indices, std::vector<Vec> reference_positions);

    /// Neighbours of i: indices [begin(i), end(i)) into indices().
    Index begin(Index i) const noexcept { return offsets_[static_cast<std::size_t>(i)]; }
    Index end(Index i) const noexcept { return offsets_[static_cast<std::size_t>(i) + 1]; }
    const Index* indices() const noexcept { return indices_.data(); }
    Index particle_count() const noexcept { return static_cast<Index>(offsets_.size()) - 1; }
    const Index* offsets() const noexcept { return offsets_.data(); }
    std::size_t pair_count() const noexcept { return indices_.size(); }

    /// Changes whenever the lists do (build, compact, assign), and is never the same for two lists:
    /// what is cut from the lists (HalfLists) is cut again only when it changed.
    std::uint64_t version() const noexcept { return version_; }

    /// The positions the lists were built at (one per particle).
    const Vec* reference_positions() const noexcept { return reference_positions_.data(); }

    /// Largest squared displacement of any particle since the last build (along periodic axes of `box`,
    /// that of the nearest image: a particle wrapped across a face has moved by its step, not the period).
    double max_displacement2(const Vec* x, Index n, const PeriodicBox<Dim>& box = {}) const;

private:
    template <class Image, class F>
    void scan(const CellGrid<Dim>& grid, const std::vector<Index>& cell_start, const Vec* x, Index i,
              double r2max, const std::int32_t* phase, const Image& image, F&& visit) const;

    std::vector<Index> offsets_{0};
    std::vector<Index> indices_;
    std::vector<Vec> reference_positions_;
    std::uint64_t version_ = 0;
    std::vector<std::vector<Index>> chunk_entries_;  // build scratch: the entries each thread found
};

extern template class NeighborList<2>;
extern template class NeighborList<3>;

}  // namespace grit::neighbors
