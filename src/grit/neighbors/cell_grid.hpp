// A uniform grid of cells, one type for SPH particles and DEM grains, and the counting sort that orders
// points by cell so that each cell's points are contiguous in memory.
//
// Two ways to lay a grid: covering() puts cubic cells over the points' bounding box (SPH particles,
// crack links, grains seen from the SPH side); over_box() divides each periodic axis of a box into a
// whole number of cells and covers the points along the open axes (DEM grains). The cell numbering is a
// template parameter (CellOrder), fixed by what each user does with the sorted order.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "grit/core/error.hpp"
#include "grit/core/types.hpp"
#include "grit/core/vec.hpp"
#include "grit/parallel/parallel.hpp"

namespace grit::neighbors {

/// How cell coordinates c[0..Dim) become one cell number.
enum class CellOrder {
    /// Row-major with x fastest: c[0] + dims[0] * (c[1] + dims[1] * c[2]). The three cells x-1..x+1 of
    /// one row are one contiguous range of sorted points, which the SPH neighbour scan reads in one go.
    x_fastest,
    /// x slowest: c[Dim-1] + dims[Dim-1] * (c[Dim-2] + ...). Grains sorted by cell are split between
    /// threads statically along the sorted order, so along x each thread gets its share of a settled
    /// bed (with z slowest one thread got the bed, the other the grains falling above it).
    x_slowest,
};

template <int Dim, CellOrder Order = CellOrder::x_fastest>
struct CellGrid {
    using Vec = core::Vec<Dim>;
    using Coords = std::array<Index, Dim>;

    Vec origin = Vec::zero();
    Vec cell_size = Vec::filled(1.0);          ///< per axis [m]
    Vec inverse_cell_size = Vec::filled(1.0);  ///< cells per metre, per axis
    std::array<Index, Dim> dims{};
    std::array<bool, Dim> periodic{};  ///< axes that wrap (whole cells from origin over the box's length)
    /// How coords() turns a distance from the origin into cells: covering() grids divide by cell_size,
    /// over_box() grids multiply by inverse_cell_size. The two forms round differently right at a cell
    /// boundary; each is the arithmetic of the grid it replaced, so points keep their cells bit for bit.
    bool divides = true;

    Index cell_count() const noexcept {
        Index n = 1;
        for (int k = 0; k < Dim; ++k) n *= dims[k];
        return n;
    }
    /// The cell coordinates of x, clamped to the grid (points outside it go to the nearest edge cell).
    Coords coords(const Vec& x) const noexcept {
        Coords c{};
        for (int k = 0; k < Dim; ++k) {
            const double d = x[k] - origin[k];
            const auto v = static_cast<Index>(std::floor(divides ? d / cell_size[k] : d * inverse_cell_size[k]));
            c[k] = v < 0 ? 0 : (v >= dims[k] ? dims[k] - 1 : v);
        }
        return c;
    }
    Index linear(const Coords& c) const noexcept {
        if constexpr (Order == CellOrder::x_fastest) {
            Index id = c[Dim - 1];
            for (int k = Dim - 2; k >= 0; --k) id = id * dims[k] + c[k];
            return id;
        } else {
            Index id = c[0];
            for (int k = 1; k < Dim; ++k) id = id * dims[k] + c[k];
            return id;
        }
    }
    Index cell_of(const Vec& x) const noexcept { return linear(coords(x)); }

    /// Calls f(cell) for the 3^Dim cells around coordinates c (x fastest, then y, then z): periodic axes
    /// wrap (they have three cells or more, so no cell comes twice, or one, which is its own neighbour),
    /// open axes stop at the grid's edge.
    template <class F>
    void for_each_cell_around(const Coords& c, F&& f) const {
        Coords lo{}, hi{};
        for (int k = 0; k < Dim; ++k) {
            const bool wraps = periodic[k] && dims[k] > 1;
            lo[k] = wraps ? c[k] - 1 : std::max<Index>(c[k] - 1, 0);
            hi[k] = wraps ? c[k] + 1 : std::min<Index>(c[k] + 1, dims[k] - 1);
        }
        Coords nc{};
        auto visit = [&]() {
            Coords w = nc;
            for (int k = 0; k < Dim; ++k) w[k] = (w[k] + dims[k]) % dims[k];
            f(linear(w));
        };
        if constexpr (Dim == 2) {
            for (nc[1] = lo[1]; nc[1] <= hi[1]; ++nc[1])
                for (nc[0] = lo[0]; nc[0] <= hi[0]; ++nc[0]) visit();
        } else {
            for (nc[2] = lo[2]; nc[2] <= hi[2]; ++nc[2])
                for (nc[1] = lo[1]; nc[1] <= hi[1]; ++nc[1])
                    for (nc[0] = lo[0]; nc[0] <= hi[0]; ++nc[0]) visit();
        }
    }

    /// Cubic cells of `cell_size` (larger where the points are dilute: cover_open_axes) covering points
    /// x[0..n), no periodic axes. Throws BlowUpError when the points have spread so far that the grid
    /// would be huge.
    static CellGrid covering(const Vec* x, Index n, double cell_size) {
        CellGrid g;
        g.cover_open_axes(x, n, cell_size, 1.0);
        return g;
    }

    /// A grid over the box [lower, upper) whose `periodic` axes are divided into a whole number of cells
    /// of at least `cell_size` (from lower), and whose other axes cover points x[0..n) with cells of
    /// `cell_size` (or larger: cover_open_axes). Points are expected inside the box along the periodic
    /// axes. A periodic axis shorter than three cells is one cell: a cell's neighbours along it would be
    /// one cell met twice, so all its points are candidates once (whether a pair is near is then the
    /// nearest image's business). Throws BlowUpError when the points have spread so far that the grid
    /// would be huge.
    static CellGrid over_box(const std::array<bool, Dim>& periodic, const Vec& lower, const Vec& upper,
                             const Vec* x, Index n, double cell_size) {
        CellGrid g;
        g.divides = false;
        g.periodic = periodic;
        double cells = 1.0;  // of the periodic axes
        for (int k = 0; k < Dim; ++k) {
            if (!periodic[k]) continue;
            const double length = upper[k] - lower[k];
            auto count = static_cast<Index>(std::floor(length / cell_size));
            if (count < 3) count = 1;
            g.origin[k] = lower[k];
            g.dims[k] = count;
            g.cell_size[k] = length / count;
            g.inverse_cell_size[k] = count / length;
            cells *= count;
        }
        g.cover_open_axes(x, n, cell_size, cells);
        return g;
    }

private:
    // The open (non-periodic) axes cover x[0..n) from just below the lowest point, with cubic cells of
    // `size`, doubled while the grid (times `periodic_cells`) would have more than max(64 (n + 1000),
    // 4 million) cells: grains strewn through a tank are dilute, not blown up, and cells larger than the
    // reach only add candidates. A spread that needs cells over 8 times `size` (a cluster with an outlier
    // far away would then have 512 times the candidates in its cells), or a point that is not finite, is a
    // blow-up.
    void cover_open_axes(const Vec* x, Index n, double size, double periodic_cells) {
        Vec lo = Vec::zero(), hi = Vec::zero();
        for (int k = 0; k < Dim; ++k) {
            if (periodic[k] || n == 0) continue;
            constexpr double nan_as = -std::numeric_limits<double>::infinity();  // makes the grid infinite
            lo[k] = parallel::min(n, 1e300, [&](Index i) { return std::isnan(x[i][k]) ? nan_as : x[i][k]; });
            hi[k] = parallel::max(n, -1e300, [&](Index i) { return x[i][k]; });
        }
        auto cells_at = [&](double s) {
            double cells = periodic_cells;
            for (int k = 0; k < Dim; ++k)
                if (!periodic[k]) cells *= (hi[k] - lo[k]) / s + 1.0;
            return cells;
        };
        const double budget = std::max(64.0 * (static_cast<double>(n) + 1000.0), 4.0e6);
        double s = size;
        while (!(cells_at(s) <= budget)) {
            s *= 2.0;
            if (!std::isfinite(cells_at(s)) || s > 8.0 * size)
                throw core::BlowUpError("particles spread over a region far larger than the case's: "
                                        "a neighbour grid would need too many cells");
        }
        for (int k = 0; k < Dim; ++k) {
            if (periodic[k]) continue;
            origin[k] = lo[k] - 1e-9 * s;
            cell_size[k] = s;
            inverse_cell_size[k] = 1.0 / s;
            dims[k] = static_cast<Index>((hi[k] - lo[k]) / s + 1.0) + 1;
        }
    }
};

/// Counting sort by cell: `order` lists point indices cell by cell (stable, so deterministic), and
/// `cell_start[c] .. cell_start[c + 1]` is the range of cell c in `order`.
template <int Dim, CellOrder Order>
void sort_by_cell(const CellGrid<Dim, Order>& grid, const core::Vec<Dim>* x, Index n, std::vector<Index>& order,
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
