// Verlet neighbour lists: two passes over the cells (count, then fill), parallel over particles.
#include "grit/neighbors/neighbor_list.hpp"

#include <algorithm>
#include <atomic>
#include <utility>

#include "grit/parallel/parallel.hpp"

namespace grit::neighbors {

namespace {
std::atomic<std::uint64_t> last_version{0};  // shared by all lists, so no two lists have one version
}  // namespace

std::uint64_t next_list_version() { return ++last_version; }

template <int Dim>
template <class Image, class F>
void NeighborList<Dim>::scan(const CellGrid<Dim>& grid, const std::vector<Index>& cell_start, const Vec* x,
                             Index i, double r2max, const std::int32_t* phase, const Image& image, F&& visit) const {
    const auto c = grid.coords(x[i]);
    const auto wall = static_cast<std::int32_t>(Phase::wall);
    const bool skip_walls = phase && phase[i] == wall;
    // Cells are row-major with x fastest, so the three cells x-1..x+1 of one row are one contiguous
    // range of particles: Dim == 2 scans 3 ranges, Dim == 3 scans 9. A periodic x splits the row of a
    // cell at a face into two ranges (the cells on this side, then the one across the face).
    const Index nx = grid.dims[0];
    auto span = [&](std::array<Index, Dim> rc, Index from, Index to) {
        rc[0] = from;
        const Index first = cell_start[static_cast<std::size_t>(grid.linear(rc))];
        rc[0] = to;
        const Index last = cell_start[static_cast<std::size_t>(grid.linear(rc)) + 1];
        for (Index j = first; j < last; ++j) {
            if (j == i || (skip_walls && phase[j] == wall)) continue;
            if (core::norm2(image(x[i] - x[j])) < r2max) visit(j);
        }
    };
    auto row = [&](const std::array<Index, Dim>& rc) {
        if (!grid.periodic[0]) {
            span(rc, std::max<Index>(c[0] - 1, 0), std::min<Index>(c[0] + 1, nx - 1));
        } else if (nx == 1) {  // a short period: one cell, its own neighbour
            span(rc, 0, 0);
        } else if (c[0] == 0) {
            span(rc, 0, 1);
            span(rc, nx - 1, nx - 1);
        } else if (c[0] == nx - 1) {
            span(rc, nx - 2, nx - 1);
            span(rc, 0, 0);
        } else {
            span(rc, c[0] - 1, c[0] + 1);
        }
    };
    // The neighbour cells along y (and z): periodic axes wrap (three cells or more, so none comes
    // twice, or one, its own neighbour), open axes stop at the grid's edge.
    auto around = [&](int k, Index d, Index& out) {
        Index v = c[k] + d;
        if (grid.periodic[k] && grid.dims[k] == 1) {
            out = 0;
            return d == 0;
        }
        if (grid.periodic[k]) {
            out = v < 0 ? v + grid.dims[k] : (v >= grid.dims[k] ? v - grid.dims[k] : v);
            return true;
        }
        out = v;
        return v >= 0 && v < grid.dims[k];
    };
    if constexpr (Dim == 2) {
        for (Index dy = -1; dy <= 1; ++dy) {
            Index y = 0;
            if (around(1, dy, y)) row({0, y});
        }
    } else {
        for (Index dz = -1; dz <= 1; ++dz) {
            Index z = 0;
            if (!around(2, dz, z)) continue;
            for (Index dy = -1; dy <= 1; ++dy) {
                Index y = 0;
                if (around(1, dy, y)) row({0, y, z});
            }
        }
    }
}

template <int Dim>
void NeighborList<Dim>::build(const CellGrid<Dim>& grid, const std::vector<Index>& cell_start, const Vec* x,
                              Index n, double radius, const std::int32_t* phase, const PeriodicBox<Dim>& box,
                              const SideSeparation<Dim>* sides) {
    // One scan: each thread lists its contiguous chunk of particles into its own buffer, and the buffers
    // are joined in chunk order (a count pass and a fill pass scanned every cell twice).
    const double r2 = radius * radius;
    offsets_.assign(static_cast<std::size_t>(n) + 1, 0);
    chunk_entries_.resize(static_cast<std::size_t>(std::max(parallel::max_threads(), 1)));
    for (auto& found : chunk_entries_) found.clear();  // a chunk no thread runs this time adds nothing
    std::vector<Index> chunk_begin(chunk_entries_.size() + 1, n);
    with_image(box, [&](const auto& image) {
        parallel::for_each_chunk(n, [&](int chunk, Index begin, Index end) {
            auto& found = chunk_entries_[static_cast<std::size_t>(chunk)];
            chunk_begin[static_cast<std::size_t>(chunk)] = begin;
            for (Index i = begin; i < end; ++i) {
                const auto before = found.size();
                if (sides) {
                    scan(grid, cell_start, x, i, r2, phase, image, [&](Index j) {
                        if (!sides->apart(i, j)) found.push_back(j);
                    });
                } else {
                    scan(grid, cell_start, x, i, r2, phase, image, [&](Index j) { found.push_back(j); });
                }
                offsets_[static_cast<std::size_t>(i) + 1] = static_cast<Index>(found.size() - before);
            }
        });
    });
    for (Index i = 0; i < n; ++i) offsets_[static_cast<std::size_t>(i) + 1] += offsets_[static_cast<std::size_t>(i)];
    indices_.resize(static_cast<std::size_t>(offsets_.back()));
    for (std::size_t c = 0; c < chunk_entries_.size(); ++c) {
        const auto& found = chunk_entries_[c];
        if (found.empty()) continue;
        std::copy(found.begin(), found.end(),
                  indices_.begin() + offsets_[static_cast<std::size_t>(chunk_begin[c])]);
    }
    reference_positions_.assign(x, x + n);
    version_ = next_list_version();
}

template <int Dim>
void NeighborList<Dim>::compact(const std::vector<Index>& keep) {
    const auto n = static_cast<Index>(keep.size());
    std::vector<Index> renumber(static_cast<std::size_t>(particle_count()), -1);
    for (Index i = 0; i < n; ++i) renumber[static_cast<std::size_t>(keep[static_cast<std::size_t>(i)])] = i;
    std::vector<Index> offsets(static_cast<std::size_t>(n) + 1, 0);
    parallel::for_each(n, [&](Index i) {
        const Index a = keep[static_cast<std::size_t>(i)];
        Index count = 0;
        for (Index k = begin(a); k < end(a); ++k) count += renumber[static_cast<std::size_t>(indices_[static_cast<std::size_t>(k)])] >= 0;
        offsets[static_cast<std::size_t>(i) + 1] = count;
    });
    for (Index i = 0; i < n; ++i) offsets[static_cast<std::size_t>(i) + 1] += offsets[static_cast<std::size_t>(i)];
    std::vector<Index> indices(static_cast<std::size_t>(offsets.back()));
    std::vector<Vec> reference(static_cast<std::size_t>(n));
    parallel::for_each(n, [&](Index i) {
        const Index a = keep[static_cast<std::size_t>(i)];
        Index out = offsets[static_cast<std::size_t>(i)];
        for (Index k = begin(a); k < end(a); ++k) {
            const Index j = renumber[static_cast<std::size_t>(indices_[static_cast<std::size_t>(k)])];
            if (j >= 0) indices[static_cast<std::size_t>(out++)] = j;
        }
        reference[static_cast<std::size_t>(i)] = reference_positions_[static_cast<std::size_t>(a)];
    });
    offsets_ = std::move(offsets);
    indices_ = std::move(indices);
    reference_positions_ = std::move(reference);
    version_ = next_list_version();
}

template <int Dim>
void NeighborList<Dim>::assign(std::vector<Index> offsets, std::vector<Index> indices,
                               std::vector<Vec> reference_positions) {
    offsets_ = std::move(offsets);
    indices_ = std::move(indices);
    reference_positions_ = std::move(reference_positions);
    version_ = next_list_version();
}

template <int Dim>
double NeighborList<Dim>::max_displacement2(const Vec* x, Index n, const PeriodicBox<Dim>& box) const {
    if (static_cast<std::size_t>(n) != reference_positions_.size()) return 1e300;
    return with_image(box, [&](const auto& image) {
        return parallel::max(n, 0.0, [&](Index i) { return core::norm2(image(x[i] - reference_positions_[i])); });
    });
}

template class NeighborList<2>;
template class NeighborList<3>;

}  // namespace grit::neighbors
