// A uniform grid of cells over the particles' bounding box, and the counting sort that orders particles
// by cell (row-major, x fastest) so that each cell's particles are contiguous in memory.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "grit/core/error.hpp"
#include "grit/core/types.hpp"
#include "grit/core/vec.hpp"
#include "grit/parallel/parallel.hpp"

namespace grit::neighbors {

template <int Dim>
struct CellGrid {
    using Vec = core::Vec<Dim>;
    Vec origin = Vec::zero();
    double cell_size = 1.0;
    std::array<Index, Dim> dims{};

    Index cell_count() const {
        Index n = 1;
        for (int k = 0; k < Dim; ++k) n *= dims[k];
        return n;
    }
    std::array<Index, Dim> coords(const Vec& x) const noexcept {
        std::array<Index, Dim> c{};
        for (int k = 0; k < Dim; ++k) {
            const auto v = static_cast<Index>(std::floor((x[k] - origin[k]) / cell_size));
            c[k] = std::clamp<Index>(v, 0, dims[k] - 1);
        }
        return c;
    }
    Index linear(const std::array<Index, Dim>& c) const noexcept {
        Index id = c[Dim - 1];
        for (int k = Dim - 2; k >= 0; --k) id = id * dims[k] + c[k];
        return id;
    }
    Index cell_of(const Vec& x) const noexcept { return linear(coords(x)); }

    /// A grid with cells of at least `cell_size` covering points x[0..n).
    static CellGrid covering(const Vec* x, Index n, double cell_size) {
        CellGrid g;
        g.cell_size = cell_size;
        Vec lo = Vec::filled(0.0), hi = Vec::filled(0.0);
        for (int k = 0; k < Dim; ++k) {
            lo[k] = parallel::min(n, 0.0 + 1e300, [&](Index i) { return x[i][k]; });
            hi[k] = parallel::max(n, -1e300, [&](Index i) { return x[i][k]; });
            if (n == 0) lo[k] = hi[k] = 0.0;
        }
        double cells = 1.0;
        for (int k = 0; k < Dim; ++k) {
            g.origin[k] = lo[k] - 1e-9 * cell_size;
            const double extent = (hi[k] - lo[k]) / cell_size + 1.0;
            cells *= extent;
            if (!std::isfinite(extent) || cells > 64.0 * (n + 1000.0))
                throw core::BlowUpError("particles spread over a region far larger than the case's: "
                                        "the neighbour grid would need too many cells");
            g.dims[k] = static_cast<Index>(extent) + 1;
        }
        return g;
    }
};

/// Counting sort by cell: `order` lists particle indices cell by cell (stable, so deterministic), and
/// `cell_start[c] .. cell_start[c + 1]` is the range of cell c in `order`.
template <int Dim>
void sort_by_cell(const CellGrid<Dim>& grid, const core::Vec<Dim>* x, Index n, std::vector<Index>& order,
                  std::vector<Index>& cell_start) {
    const Index cells = grid.cell_count();
    std::vector<Index> cell(static_cast<std::size_t>(n));
    parallel::for_each(n, [&](Index i) { cell[i] = grid.cell_of(x[i]); });
    cell_start.assign(static_cast<std::size_t>(cells) + 1, 0);
    for (Index i = 0; i < n; ++i) ++cell_start[static_cast<std::size_t>(cell[i]) + 1];
    for (Index c = 0; c < cells; ++c) cell_start[c + 1] += cell_start[c];
    std::vector<Index> next(cell_start.begin(), cell_start.end() - 1);
    order.resize(static_cast<std::size_t>(n));
    for (Index i = 0; i < n; ++i) order[static_cast<std::size_t>(next[cell[i]]++)] = i;
}

}  // namespace grit::neighbors
