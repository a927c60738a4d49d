// Grain neighbour search: grid, counting sort by cell, and two-pass (count, fill) list build.
#include "grit/dem/grain_neighbors.hpp"

#include <algorithm>
#include <string>

#include "grit/core/error.hpp"
#include "grit/dem/grain_loop.hpp"

namespace grit::dem {

template <int Dim>
GrainGrid<Dim> GrainNeighborList<Dim>::make_grid(const GrainDomain<Dim>& domain, const Vec* x, Index n,
                                                 double cell_size) {
    GrainGrid<Dim> g;
    g.periodic = domain.periodic;
    double cells = 1.0;
    for (int k = 0; k < Dim; ++k) {
        if (domain.periodic[k]) {
            const double length = domain.length(k);
            const auto count = static_cast<Index>(std::floor(length / cell_size));
            if (count < 3)
                throw core::InputError("grain domain: periodic axis " + std::to_string(k) + " is " +
                                       std::to_string(length) + " m long, less than three neighbour cells of " +
                                       std::to_string(cell_size) + " m (largest grain diameter + skin)");
            g.origin[k] = domain.lower[k];
            g.dims[k] = count;
            g.inverse_cell_size[k] = count / length;
        } else {
            const double lo = min_over_grains(n, 1e300, [&](Index i) { return x[i][k]; });
            const double hi = max_over_grains(n, -1e300, [&](Index i) { return x[i][k]; });
            const double extent = n == 0 ? 1.0 : (hi - lo) / cell_size + 1.0;
            if (!std::isfinite(extent) || extent * cells > 64.0 * (n + 1000.0))
                throw core::BlowUpError("grains spread over a region far larger than the case's: the grain "
                                        "neighbour grid would need too many cells");
            g.origin[k] = n == 0 ? 0.0 : lo - 1e-9 * cell_size;
            g.dims[k] = static_cast<Index>(extent) + 1;
            g.inverse_cell_size[k] = 1.0 / cell_size;
        }
        cells *= g.dims[k];
    }
    return g;
}

template <int Dim>
void GrainNeighborList<Dim>::sort_by_cell(const GrainGrid<Dim>& grid, const Vec* x, Index n,
                                          std::vector<Index>& order) {
    std::vector<Index> cell(static_cast<std::size_t>(n));
    for_each_grain(n, [&](Index i) { cell[i] = grid.linear(grid.coords(x[i])); });
    std::vector<Index> start(static_cast<std::size_t>(grid.cell_count()) + 1, 0);
    for (Index i = 0; i < n; ++i) ++start[static_cast<std::size_t>(cell[i]) + 1];
    for (std::size_t c = 1; c < start.size(); ++c) start[c] += start[c - 1];
    order.resize(static_cast<std::size_t>(n));
    for (Index i = 0; i < n; ++i) order[static_cast<std::size_t>(start[cell[i]]++)] = i;
}

template <int Dim>
void GrainNeighborList<Dim>::build(const GrainGrid<Dim>& grid, const GrainDomain<Dim>& domain, const Vec* x,
                                   const double* radius, const std::int32_t* id, Index n, double skin) {
    skin_ = skin;
    const Index cells = grid.cell_count();
    cell_start_.assign(static_cast<std::size_t>(cells) + 1, 0);
    for (Index i = 0; i < n; ++i) ++cell_start_[static_cast<std::size_t>(grid.linear(grid.coords(x[i]))) + 1];
    for (Index c = 0; c < cells; ++c) cell_start_[c + 1] += cell_start_[c];

    // Visits every grain j != i within R_i + R_j + skin in the 3^Dim cells around i's cell. Periodic
    // axes have at least three cells, so no cell is visited twice.
    auto scan = [&](Index i, auto&& visit) {
        const auto c = grid.coords(x[i]);
        std::array<Index, Dim> lo{}, hi{};
        for (int k = 0; k < Dim; ++k) {
            lo[k] = grid.periodic[k] ? c[k] - 1 : std::max<Index>(c[k] - 1, 0);
            hi[k] = grid.periodic[k] ? c[k] + 1 : std::min<Index>(c[k] + 1, grid.dims[k] - 1);
        }
        std::array<Index, Dim> nc{};
        auto visit_cell = [&]() {
            std::array<Index, Dim> w = nc;
            for (int k = 0; k < Dim; ++k) w[k] = (w[k] + grid.dims[k]) % grid.dims[k];
            const Index cell = grid.linear(w);
            for (Index j = cell_start_[cell]; j < cell_start_[cell + 1]; ++j) {
                if (j == i) continue;
                const double reach = radius[i] + radius[j] + skin;
                if (core::norm2(domain.nearest_image(x[j] - x[i])) < reach * reach) visit(j);
            }
        };
        if constexpr (Dim == 2) {
            for (nc[1] = lo[1]; nc[1] <= hi[1]; ++nc[1])
                for (nc[0] = lo[0]; nc[0] <= hi[0]; ++nc[0]) visit_cell();
        } else {
            for (nc[2] = lo[2]; nc[2] <= hi[2]; ++nc[2])
                for (nc[1] = lo[1]; nc[1] <= hi[1]; ++nc[1])
                    for (nc[0] = lo[0]; nc[0] <= hi[0]; ++nc[0]) visit_cell();
        }
    };

    offsets_.assign(static_cast<std::size_t>(n) + 1, 0);
    for_each_grain(n, [&](Index i) {
        Index count = 0;
        scan(i, [&](Index) { ++count; });
        offsets_[static_cast<std::size_t>(i) + 1] = count;
    });
    for (Index i = 0; i < n; ++i) offsets_[static_cast<std::size_t>(i) + 1] += offsets_[static_cast<std::size_t>(i)];
    indices_.resize(static_cast<std::size_t>(offsets_.back()));
    split_.resize(static_cast<std::size_t>(n));
    for_each_grain(n, [&](Index i) {
        Index k = offsets_[static_cast<std::size_t>(i)];
        scan(i, [&](Index j) { indices_[static_cast<std::size_t>(k++)] = j; });
        // Partners of higher id first (this grain's pairs), then lower; ascending index within each part.
        const auto row = indices_.begin() + offsets_[static_cast<std::size_t>(i)];
        std::sort(row, indices_.begin() + k, [&](Index p, Index q) {
            const bool pa = id[p] > id[i], qa = id[q] > id[i];
            return pa != qa ? pa : p < q;
        });
        split_[static_cast<std::size_t>(i)] = static_cast<Index>(
            std::partition_point(row, indices_.begin() + k, [&](Index p) { return id[p] > id[i]; }) - indices_.begin());
    });
    mirror_.resize(indices_.size());
    for_each_grain(n, [&](Index i) {
        for (Index k = offsets_[static_cast<std::size_t>(i)]; k < offsets_[static_cast<std::size_t>(i) + 1]; ++k) {
            const Index j = indices_[static_cast<std::size_t>(k)];
            Index m = offsets_[static_cast<std::size_t>(j)];
            while (indices_[static_cast<std::size_t>(m)] != i) ++m;
            mirror_[static_cast<std::size_t>(k)] = m;
        }
    });
    reference_positions_.assign(x, x + n);
}

template <int Dim>
bool GrainNeighborList<Dim>::stale(const Vec* x, Index n) const {
    if (static_cast<std::size_t>(n) != reference_positions_.size()) return true;
    return stale(max_over_grains(n, 0.0, [&](Index i) { return core::norm2(x[i] - reference_positions_[i]); }), n);
}

template class GrainNeighborList<2>;
template class GrainNeighborList<3>;

}  // namespace grit::dem
