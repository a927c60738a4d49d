// Grain neighbour search: a cell grid sized by the largest grain (largest diameter + skin), optional
// periodic axes, grains sorted by cell, and Verlet lists in compressed rows holding each pair once, in
// the row of its grain of lower index (the contact pass evaluates each pair once, by that grain). The
// lists stay valid until a grain has moved more than skin/2.
#pragma once

#include <array>
#include <cstdint>
#include <cmath>
#include <vector>

#include "grit/core/types.hpp"
#include "grit/core/vec.hpp"
#include "grit/neighbors/cell_grid.hpp"
#include "grit/neighbors/periodic_box.hpp"

namespace grit::dem {

/// The box of a grain system: periodic axes wrap between lower and upper; other axes are open (their
/// bounds are ignored by the neighbour search, walls confine the grains). The run's periodic box, the
/// same type as the SPH particles' (case key domain.periodic).
template <int Dim>
using GrainDomain = neighbors::PeriodicBox<Dim>;

/// Verlet lists of grains within R_i + R_j + skin, each pair once (in its lower index's row), built over
/// grains sorted by cell.
template <int Dim>
class GrainNeighborList {
public:
    using Vec = core::Vec<Dim>;
    /// Grains are numbered by cell with x slowest (see CellOrder::x_slowest).
    using Grid = neighbors::CellGrid<Dim, neighbors::CellOrder::x_slowest>;

    /// The grid for x[0..n) (wrapped into the domain): cells of at least `cell_size` on every axis,
    /// periodic axes divided into a whole number of cells. Throws InputError when a periodic length is
    /// shorter than three cells, BlowUpError when grains have spread so far that the grid would be huge.
    /// Sort the grains with neighbors::sort_by_cell.
    static Grid make_grid(const GrainDomain<Dim>& domain, const Vec* x, Index n, double cell_size);

    /// Builds the lists of x[0..n), which must be wrapped and sorted by the cells of `grid`, with
    /// `cell_start` from neighbors::sort_by_cell. Row i holds i's partners of higher index, ascending.
    void build(const Grid& grid, const std::vector<Index>& cell_start, const GrainDomain<Dim>& domain,
               const Vec* x, const double* radius, Index n, double skin);

    Index begin(Index i) const noexcept { return offsets_[static_cast<std::size_t>(i)]; }
    Index end(Index i) const noexcept { return offsets_[static_cast<std::size_t>(i) + 1]; }
    /// Row starts, n + 1 of them (for neighbors::HalfLists).
    const Index* offsets() const noexcept { return offsets_.data(); }
    const Index* indices() const noexcept { return indices_.data(); }
    Index grain_count() const noexcept { return static_cast<Index>(offsets_.size()) - 1; }
    std::size_t entry_count() const noexcept { return indices_.size(); }
    /// Changes with every build, and is never the same for two lists (for neighbors::HalfLists::update).
    std::uint64_t version() const noexcept { return version_; }
    /// The first grain of each slab of cells along x (the grid's slowest axis), one more for the end:
    /// slab s holds grains [slab_starts()[s], slab_starts()[s + 1]). A grain's partners lie in its own
    /// slab or the next ones on either side (the cells are at least a list cutoff wide).
    const std::vector<Index>& slab_starts() const noexcept { return slab_starts_; }

    /// True when a grain has moved more than skin/2 since the build, or the count has changed.
    bool stale(const Vec* x, Index n) const;
    /// The positions at the build (one per grain), from which stale() measures the displacements.
    const Vec* reference_positions() const noexcept { return reference_positions_.data(); }
    /// stale() for n grains whose largest squared displacement from reference_positions() is max_d2.
    bool stale(double max_d2, Index n) const noexcept {
        return static_cast<std::size_t>(n) != reference_positions_.size() || 4.0 * max_d2 > skin_ * skin_;
    }

private:
    std::vector<Index> offsets_{0};
    std::vector<Index> indices_;
    std::vector<Vec> reference_positions_;
    std::vector<Index> slab_starts_{0};
    std::uint64_t version_ = 0;
    double skin_ = 0.0;
};

extern template class GrainNeighborList<2>;
extern template class GrainNeighborList<3>;

}  // namespace grit::dem
