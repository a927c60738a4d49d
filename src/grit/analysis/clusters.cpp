// Clusters as exchangeable labels: the members binned on a cell grid of the link distance, joined by
// union-find, each cluster named by its smallest id.
#include "grit/analysis/clusters.hpp"

#include <algorithm>
#include <array>
#include <limits>
#include <stdexcept>

#include "grit/core/disjoint_sets.hpp"
#include "grit/domain/halo.hpp"
#include "grit/neighbors/cell_grid.hpp"

namespace grit::analysis {

namespace {

/// A cell size of at least `link` whose grid over x[0..n) stays small: sparse damage spread over a
/// large solid would otherwise ask CellGrid::covering for far more cells than particles.
template <int Dim>
double cell_size_for(const core::Vec<Dim>* x, Index n, double link) {
    if (n == 0) return link;
    core::Vec<Dim> lo = x[0], hi = x[0];
    for (Index i = 1; i < n; ++i)
        for (int k = 0; k < Dim; ++k) {
            lo[k] = std::min(lo[k], x[i][k]);
            hi[k] = std::max(hi[k], x[i][k]);
        }
    double size = link;
    const double budget = 4.0 * (n + 1000.0);
    while (true) {
        double cells = 1.0;
        for (int k = 0; k < Dim; ++k) cells *= (hi[k] - lo[k]) / size + 2.0;
        if (cells <= budget) return size;
        size *= 2.0;
    }
}

}  // namespace

template <int Dim>
std::vector<domain::ParticleId> cluster_labels(const particles::SphParticles<Dim>& ps,
                                               const std::vector<std::uint8_t>& member, double link_distance,
                                               Index owned, const domain::ParticleId* ghost_labels,
                                               const neighbors::PeriodicBox<Dim>& box) {
    if (!(link_distance > 0.0)) throw std::invalid_argument("cluster_labels: the link distance must be > 0");
    for (int k = 0; k < Dim; ++k)
        if (box.periodic[k] && !(2.0 * link_distance < box.length(k)))
            throw std::invalid_argument("cluster_labels: the link distance must be less than half of each period");
    const auto* x = ps.position();
    const auto* id = ps.id();
    std::vector<domain::ParticleId> labels(static_cast<std::size_t>(ps.size()), -1);

    // The members, owned then ghosts, in index order.
    std::vector<Index> damaged;
    std::vector<core::Vec<Dim>> xd;
    for (Index i = 0; i < ps.size(); ++i) {
        if (!member[static_cast<std::size_t>(i)]) continue;
        damaged.push_back(i);
        xd.push_back(x[i]);
    }
    const auto n = static_cast<Index>(damaged.size());
    if (n == 0) return labels;
    // Along periodic axes, the images of the damaged particles within link_distance of a face stand past
    // the other face (points [n, points)), each linking for the particle it images.
    std::vector<Index> imaged(static_cast<std::size_t>(n));
    for (Index a = 0; a < n; ++a) imaged[static_cast<std::size_t>(a)] = a;
    if (box.any())
        for (const auto& [a, t] : domain::periodic_ghosts(xd.data(), n, box, link_distance)) {
            const auto image = t.position(xd[static_cast<std::size_t>(a)]);
            xd.push_back(image);
            imaged.push_back(a);
        }
    const auto points = static_cast<Index>(xd.size());

    // Links: each damaged particle against the 3^Dim cells around it (cells are >= link_distance).
    const double link2 = link_distance * link_distance;
    const auto grid =
        neighbors::CellGrid<Dim>::covering(xd.data(), points, cell_size_for(xd.data(), points, link_distance));
    std::vector<Index> order, cell_start;
    neighbors::sort_by_cell(grid, xd.data(), points, order, cell_start);
    core::DisjointSets sets(n);
    for (Index a = 0; a < n; ++a) {
        const auto c = grid.coords(xd[static_cast<std::size_t>(a)]);
        std::array<Index, Dim> lo{}, hi{};
        for (int k = 0; k < Dim; ++k) {
            lo[k] = std::max<Index>(c[k] - 1, 0);
            hi[k] = std::min<Index>(c[k] + 1, grid.dims[k] - 1);
        }
        auto cell = lo;
        while (true) {
            const auto at = static_cast<std::size_t>(grid.linear(cell));
            for (Index s = cell_start[at]; s < cell_start[at + 1]; ++s) {
                const Index b = order[static_cast<std::size_t>(s)];
                if (b > a && core::norm2(xd[static_cast<std::size_t>(a)] - xd[static_cast<std::size_t>(b)]) <= link2)
                    sets.unite(a, imaged[static_cast<std::size_t>(b)]);
            }
            // Next cell of the block, x fastest.
            int k = 0;
            for (; k < Dim && cell[k] == hi[k]; ++k) cell[k] = lo[k];
            if (k == Dim) break;
            ++cell[k];
        }
    }

    // A cluster's label: the smallest of its members' ids and of the labels its ghosts brought.
    std::vector<domain::ParticleId> smallest(static_cast<std::size_t>(n), std::numeric_limits<domain::ParticleId>::max());
    for (Index a = 0; a < n; ++a) {
        const Index i = damaged[static_cast<std::size_t>(a)];
        domain::ParticleId label = id[i];
        if (ghost_labels && i >= owned) label = std::min(label, ghost_labels[i - owned]);
        auto& root = smallest[static_cast<std::size_t>(sets.find(a))];
        root = std::min(root, label);
    }
    for (Index a = 0; a < n; ++a)
        labels[static_cast<std::size_t>(damaged[static_cast<std::size_t>(a)])] = smallest[static_cast<std::size_t>(sets.find(a))];
    return labels;
}

template std::vector<domain::ParticleId> cluster_labels<2>(const particles::SphParticles<2>&,
                                                           const std::vector<std::uint8_t>&, double, Index,
                                                           const domain::ParticleId*, const neighbors::PeriodicBox<2>&);
template std::vector<domain::ParticleId> cluster_labels<3>(const particles::SphParticles<3>&,
                                                           const std::vector<std::uint8_t>&, double, Index,
                                                           const domain::ParticleId*, const neighbors::PeriodicBox<3>&);

}  // namespace grit::analysis
