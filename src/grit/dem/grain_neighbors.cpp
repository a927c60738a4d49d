// Grain neighbour search: the grid over the grain domain, and the two-pass (count, fill) list build.
#include "grit/dem/grain_neighbors.hpp"

#include <algorithm>
#include <string>

#include "grit/core/error.hpp"
#include "grit/dem/grain_loop.hpp"
#include "grit/neighbors/neighbor_list.hpp"

namespace grit::dem {

template <int Dim>
typename GrainNeighborList<Dim>::Grid GrainNeighborList<Dim>::make_grid(const GrainDomain<Dim>& domain, const Vec* x,
                                                                        Index n, double cell_size) {
    for (int k = 0; k < Dim; ++k)
        if (domain.periodic[k] && !(domain.length(k) > 2.0 * cell_size))
            throw core::InputError("grain domain: periodic axis " + std::to_string(k) + " is " +
                                   std::to_string(domain.length(k)) + " m long, not more than twice " +
                                   std::to_string(cell_size) +
                                   " m (the largest grain diameter + skin): a grain would reach two periodic images "
                                   "of one grain");
    return Grid::over_box(domain.periodic, domain.lower, domain.upper, x, n, cell_size);
}

template <int Dim>
void GrainNeighborList<Dim>::build(const Grid& grid, const std::vector<Index>& cell_start,
                                   const GrainDomain<Dim>& domain, const Vec* x, const double* radius, Index n,
                                   double skin) {
    skin_ = skin;
    // Visits every grain j > i within R_i + R_j + skin in the 3^Dim cells around i's cell. Grains are
    // sorted by cell: a cell numbered below i's holds only grains of lower index, one above only higher.
    auto scan = [&](Index i, auto&& visit) {
        const Index own = grid.cell_of(x[i]);
        grid.for_each_cell_around(grid.coords(x[i]), [&](Index cell) {
            if (cell < own) return;
            for (Index j = cell == own ? i + 1 : cell_start[cell]; j < cell_start[cell + 1]; ++j) {
                const double reach = radius[i] + radius[j] + skin;
                if (core::norm2(domain.nearest_image(x[j] - x[i])) < reach * reach) visit(j);
            }
        });
    };

    offsets_.assign(static_cast<std::size_t>(n) + 1, 0);
    for_each_grain(n, [&](Index i) {
        Index count = 0;
        scan(i, [&](Index) { ++count; });
        offsets_[static_cast<std::size_t>(i) + 1] = count;
    });
    for (Index i = 0; i < n; ++i) offsets_[static_cast<std::size_t>(i) + 1] += offsets_[static_cast<std::size_t>(i)];
    indices_.resize(static_cast<std::size_t>(offsets_.back()));
    for_each_grain(n, [&](Index i) {
        Index k = offsets_[static_cast<std::size_t>(i)];
        scan(i, [&](Index j) { indices_[static_cast<std::size_t>(k++)] = j; });
        std::sort(indices_.begin() + offsets_[static_cast<std::size_t>(i)], indices_.begin() + k);
    });
    reference_positions_.assign(x, x + n);
    // x is the slowest axis of the cell numbering: slab s is the run of cells s * cells_per_slab onwards.
    const Index cells_per_slab = grid.cell_count() / grid.dims[0];
    slab_starts_.resize(static_cast<std::size_t>(grid.dims[0]) + 1);
    for (Index s = 0; s <= grid.dims[0]; ++s)
        slab_starts_[static_cast<std::size_t>(s)] = cell_start[static_cast<std::size_t>(s * cells_per_slab)];
    version_ = neighbors::next_list_version();
}

template <int Dim>
bool GrainNeighborList<Dim>::stale(const Vec* x, Index n) const {
    if (static_cast<std::size_t>(n) != reference_positions_.size()) return true;
    return stale(max_over_grains(n, 0.0, [&](Index i) { return core::norm2(x[i] - reference_positions_[i]); }), n);
}

template class GrainNeighborList<2>;
template class GrainNeighborList<3>;

}  // namespace grit::dem
