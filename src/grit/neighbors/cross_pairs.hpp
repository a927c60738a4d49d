// Pairs between two sets: for each point a of a set A (SPH particles, filtered by a predicate such as
// their phase), the bodies b of a set B (grains, with radii) whose centres are closer than
// radius[b] + reach, in compressed rows in ascending b. B is binned on a CellGrid with cells of
// (largest radius + reach); space is open, or periodic along the axes of a PeriodicBox (B binned on a
// grid over the box, distances of the nearest image). Two passes over A (count, then fill),
// each parallel over points and writing only to its point's row: the list does not depend on the thread
// count.
#pragma once

#include <algorithm>
#include <vector>

#include "grit/core/types.hpp"
#include "grit/core/vec.hpp"
#include "grit/neighbors/cell_grid.hpp"
#include "grit/neighbors/periodic_box.hpp"
#include "grit/parallel/parallel.hpp"

namespace grit::neighbors {

template <int Dim>
class CrossPairList {
public:
    using Vec = core::Vec<Dim>;

    /// Lists, for each a in [0, na) with keep(a), the b in [0, nb) with |xa[a] - xb[b]| < radius[b] +
    /// reach, in ascending b; points with !keep(a) get empty rows. Points outside the box of B grown by
    /// (largest radius + reach) are skipped without a look at the grid. With periodic axes in `box`
    /// (points of A inside it along them, B near it), pairs across a periodic face are found too, and
    /// |xa - xb| is the distance of the nearest image.
    template <class Keep>
    void build(const Vec* xa, Index na, Keep&& keep, const Vec* xb, const double* radius, Index nb, double reach,
               const PeriodicBox<Dim>& box = {}) {
        offsets_.assign(static_cast<std::size_t>(na) + 1, 0);
        indices_.clear();
        if (na == 0 || nb == 0) return;
        if (box.any())
            build_with(xa, na, keep, xb, radius, nb, reach, box, PeriodicImage<Dim>(box));
        else
            build_with(xa, na, keep, xb, radius, nb, reach, box, OpenImage<Dim>{});
    }

    /// The pairs of `wider` (a list built with a larger reach) that are closer than radius[b] + reach,
    /// by the test build() applies: the list build() would give at these positions, wherever the wider
    /// list's pairs still hold every such pair (points and bodies have moved less than its extra reach
    /// together). Rows keep their ascending b.
    void refine(const CrossPairList& wider, const Vec* xa, const Vec* xb, const double* radius, double reach,
                const PeriodicBox<Dim>& box = {}) {
        if (box.any())
            refine_with(wider, xa, xb, radius, reach, PeriodicImage<Dim>(box));
        else
            refine_with(wider, xa, xb, radius, reach, OpenImage<Dim>{});
    }

    /// The bodies of point a: indices()[begin(a) .. end(a)).
    Index begin(Index a) const noexcept { return offsets_[static_cast<std::size_t>(a)]; }
    Index end(Index a) const noexcept { return offsets_[static_cast<std::size_t>(a) + 1]; }
    const Index* indices() const noexcept { return indices_.data(); }
    Index point_count() const noexcept { return static_cast<Index>(offsets_.size()) - 1; }
    std::size_t pair_count() const noexcept { return indices_.size(); }

private:
    template <class Keep, class Image>
    void build_with(const Vec* xa, Index na, Keep& keep, const Vec* xb, const double* radius, Index nb, double reach,
                    const PeriodicBox<Dim>& box, const Image& image) {
        const double largest = parallel::max(nb, 0.0, [&](Index b) { return radius[b]; });
        const double cell = largest + reach;  // no pair is more than one cell apart along an axis
        CellGrid<Dim> grid;
        if (!box.any()) {
            grid = CellGrid<Dim>::covering(xb, nb, cell);
            sort_by_cell(grid, xb, nb, order_, cell_start_);
        } else {
            // B binned at its positions wrapped into the box (grains are wrapped only when their own
            // lists are rebuilt, so they may lie a little outside).
            wrapped_.resize(static_cast<std::size_t>(nb));
            parallel::for_each(nb, [&](Index b) { wrapped_[static_cast<std::size_t>(b)] = box.wrap(xb[b]); });
            grid = CellGrid<Dim>::over_box(box.periodic, box.lower, box.upper, wrapped_.data(), nb, cell);
            sort_by_cell(grid, wrapped_.data(), nb, order_, cell_start_);
        }
        const Vec* xs = box.any() ? wrapped_.data() : xb;
        Vec lo = Vec::zero(), hi = Vec::zero();
        for (int k = 0; k < Dim; ++k) {
            lo[k] = parallel::min(nb, 1e300, [&](Index b) { return xs[b][k]; }) - cell;
            hi[k] = parallel::max(nb, -1e300, [&](Index b) { return xs[b][k]; }) + cell;
        }
        auto candidate = [&](Index a) {
            if (!keep(a)) return false;
            for (int k = 0; k < Dim; ++k)
                if (!box.periodic[k] && (xa[a][k] < lo[k] || xa[a][k] > hi[k])) return false;
            return true;
        };
        // Calls visit(b) for every b within reach of point a, in the order of the cells.
        auto scan = [&](Index a, auto&& visit) {
            grid.for_each_cell_around(grid.coords(xa[a]), [&](Index c) {
                for (Index s = cell_start_[static_cast<std::size_t>(c)]; s < cell_start_[static_cast<std::size_t>(c) + 1];
                     ++s) {
                    const Index b = order_[static_cast<std::size_t>(s)];
                    const double r = radius[b] + reach;
                    if (core::norm2(image(xa[a] - xb[b])) < r * r) visit(b);
                }
            });
        };

        fill_rows(
            na,
            [&](Index a) {
                Index count = 0;
                if (candidate(a)) scan(a, [&](Index) { ++count; });
                return count;
            },
            [&](Index a, Index* row) {
                Index* out = row;
                scan(a, [&](Index b) { *out++ = b; });
                std::sort(row, out);
            });
    }

    /// Compressed rows in two passes over the points, each parallel and writing only its point's row:
    /// count(a) gives the length of row a, then fill(a, row) writes it (rows of length 0 are not filled).
    template <class Count, class Fill>
    void fill_rows(Index na, Count&& count, Fill&& fill) {
        parallel::for_each(na, [&](Index a) { offsets_[static_cast<std::size_t>(a) + 1] = count(a); });
        for (Index a = 0; a < na; ++a) offsets_[static_cast<std::size_t>(a) + 1] += offsets_[static_cast<std::size_t>(a)];
        indices_.resize(static_cast<std::size_t>(offsets_.back()));
        if (indices_.empty()) return;
        parallel::for_each(na, [&](Index a) {
            if (begin(a) < end(a)) fill(a, indices_.data() + begin(a));
        });
    }

    template <class Image>
    void refine_with(const CrossPairList& wider, const Vec* xa, const Vec* xb, const double* radius, double reach,
                     const Image& image) {
        const Index na = wider.point_count();
        offsets_.assign(static_cast<std::size_t>(na) + 1, 0);
        indices_.clear();
        const Index* from = wider.indices();
        auto near = [&](Index a, Index b) {
            const double r = radius[b] + reach;
            return core::norm2(image(xa[a] - xb[b])) < r * r;
        };
        fill_rows(
            na,
            [&](Index a) {
                Index count = 0;
                for (Index s = wider.begin(a); s < wider.end(a); ++s) count += near(a, from[s]) ? 1 : 0;
                return count;
            },
            [&](Index a, Index* row) {
                for (Index s = wider.begin(a); s < wider.end(a); ++s)
                    if (near(a, from[s])) *row++ = from[s];
            });
    }

    std::vector<Index> offsets_{0};
    std::vector<Index> indices_;
    std::vector<Index> order_, cell_start_;  // B by cell (grid work arrays, kept between builds)
    std::vector<Vec> wrapped_;               // B wrapped into the periodic box (periodic axes only)
};

}  // namespace grit::neighbors
