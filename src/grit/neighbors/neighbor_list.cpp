// Verlet neighbour lists: two passes over the cells (count, then fill), parallel over particles.
#include "grit/neighbors/neighbor_list.hpp"

#include <algorithm>

#include "grit/parallel/parallel.hpp"

namespace grit::neighbors {

template <int Dim>
template <class F>
void NeighborList<Dim>::scan(const CellGrid<Dim>& grid, const std::vector<Index>& cell_start, const Vec* x,
                             Index i, double r2max, const std::int32_t* phase, F&& visit) const {
    const auto c = grid.coords(x[i]);
    const auto wall = static_cast<std::int32_t>(Phase::wall);
    const bool skip_walls = phase && phase[i] == wall;
    // Cells are row-major with x fastest, so the three cells x-1..x+1 of one row are one contiguous
    // range of particles: Dim == 2 scans 3 ranges, Dim == 3 scans 9.
    const Index xlo = std::max<Index>(c[0] - 1, 0), xhi = std::min<Index>(c[0] + 1, grid.dims[0] - 1);
    auto row = [&](std::array<Index, Dim> rc) {
        rc[0] = xlo;
        const Index first = cell_start[static_cast<std::size_t>(grid.linear(rc))];
        rc[0] = xhi;
        const Index last = cell_start[static_cast<std::size_t>(grid.linear(rc)) + 1];
        for (Index j = first; j < last; ++j) {
            if (j == i || (skip_walls && phase[j] == wall)) continue;
            if (core::norm2(x[i] - x[j]) < r2max) visit(j);
        }
    };
    if constexpr (Dim == 2) {
        for (Index y = std::max<Index>(c[1] - 1, 0); y <= std::min<Index>(c[1] + 1, grid.dims[1] - 1); ++y)
            row({0, y});
    } else {
        for (Index z = std::max<Index>(c[2] - 1, 0); z <= std::min<Index>(c[2] + 1, grid.dims[2] - 1); ++z)
            for (Index y = std::max<Index>(c[1] - 1, 0); y <= std::min<Index>(c[1] + 1, grid.dims[1] - 1); ++y)
                row({0, y, z});
    }
}

template <int Dim>
void NeighborList<Dim>::build(const CellGrid<Dim>& grid, const std::vector<Index>& cell_start, const Vec* x,
                              Index n, double radius, const std::int32_t* phase) {
    const double r2 = radius * radius;
    offsets_.assign(static_cast<std::size_t>(n) + 1, 0);
    parallel::for_each(n, [&](Index i) {
        Index count = 0;
        scan(grid, cell_start, x, i, r2, phase, [&](Index) { ++count; });
        offsets_[static_cast<std::size_t>(i) + 1] = count;
    });
    for (Index i = 0; i < n; ++i) offsets_[static_cast<std::size_t>(i) + 1] += offsets_[static_cast<std::size_t>(i)];
    indices_.resize(static_cast<std::size_t>(offsets_.back()));
    parallel::for_each(n, [&](Index i) {
        Index k = offsets_[static_cast<std::size_t>(i)];
        scan(grid, cell_start, x, i, r2, phase, [&](Index j) { indices_[static_cast<std::size_t>(k++)] = j; });
    });
    reference_positions_.assign(x, x + n);
}

template <int Dim>
double NeighborList<Dim>::max_displacement2(const Vec* x, Index n) const {
    if (static_cast<std::size_t>(n) != reference_positions_.size()) return 1e300;
    return parallel::max(n, 0.0, [&](Index i) { return core::norm2(x[i] - reference_positions_[i]); });
}

template class NeighborList<2>;
template class NeighborList<3>;

}  // namespace grit::neighbors
