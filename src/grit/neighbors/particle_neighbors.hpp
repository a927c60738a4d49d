// The neighbour lists of an SPH particle set, with what keeps them valid: the cell grid and sort that
// order the particles before each build, and the particle set's generation at the build (lists are
// stale once particles were added, removed or reordered, or one has moved more than skin / 2). With
// periodic axes the grid is laid over the periodic box (CellGrid::over_box) and wraps, and
// displacements are measured to the nearest image.
#pragma once

#include <algorithm>
#include <cstdint>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "grit/io/hdf5_file.hpp"
#include "grit/neighbors/cell_grid.hpp"
#include "grit/neighbors/neighbor_list.hpp"
#include "grit/neighbors/periodic_box.hpp"
#include "grit/parallel/parallel.hpp"
#include "grit/particles/sph_particles.hpp"

namespace grit::neighbors {

template <int Dim>
class ParticleNeighbors {
public:
    using Vec = core::Vec<Dim>;

    /// Brings the lists up to date for `particles` with list radius `radius` (support + skin): when
    /// forced, when the set changed since the build, or when a particle has moved more than skin / 2,
    /// the particles are sorted by cell (every field) and the lists rebuilt. Returns true if rebuilt.
    /// With periodic axes in `box`, a rebuild first wraps every position into the box (particles an
    /// inlet placed across a face).
    /// Lists of a set that has only lost particles since the build are compacted, not rebuilt: at an
    /// outlet that removes a particle every few steps, rebuilds (and re-sorts) were most of the builds.
    bool update(particles::SphParticles<Dim>& particles, double radius, double skin, bool force,
                const PeriodicBox<Dim>& box = {}) {
        Index n = particles.size();
        if (!force && built_() && !valid_for(particles)) {
            if (const auto* keep = particles.kept_since(built_generation_)) {
                list_.compact(*keep);
                built_generation_ = particles.generation();
                ++compactions_;
            }
        }
        if (!force && valid_for(particles) &&
            list_.max_displacement2(particles.position(), n, box) < 0.25 * skin * skin)
            return false;
        if (before_build_) {  // a symmetry plane makes its images for the new lists
            before_build_(particles);
            n = particles.size();
        }
        if (box.any()) {
            Vec* x = particles.position();
            parallel::for_each(n, [&](Index i) { x[i] = box.wrap(x[i]); });
        }
        // Sorting keeps neighbours close in memory.
        grid_ = make_grid(particles.position(), n, radius, box);
        sort_by_cell(grid_, particles.position(), n, order_, cell_start_);
        particles.gather(order_);
        if (refresh_sides_) refresh_sides_(particles);
        const auto separation = sides(particles);
        list_.build(grid_, cell_start_, particles.position(), n, radius, particles.phase(), box,
                    separation.normal ? &separation : nullptr);
        built_generation_ = particles.generation();
        ++builds_;
        return true;
    }

    /// True while the lists belong to the set as it is (no particle added, removed or reordered since).
    bool valid_for(const particles::SphParticles<Dim>& particles) const {
        return built_() && built_generation_ == particles.generation();
    }
    const NeighborList<Dim>& list() const noexcept { return list_; }
    long builds() const noexcept { return builds_; }
    /// How often the lists were compacted after removals instead of rebuilt.
    long compactions() const noexcept { return compactions_; }

    /// For a checkpoint: whether the lists are valid, the lists themselves (compacted lists are not what a
    /// build from the same positions gives) and the positions they were built at. Lists that only miss
    /// removals (erosion at the end of the step) are saved compacted, as the run would compact them.
    void save(io::Hdf5Group& group, const particles::SphParticles<Dim>& particles) const {
        group.write("builds", static_cast<std::int64_t>(builds_));
        group.write("compactions", static_cast<std::int64_t>(compactions_));
        const NeighborList<Dim>* lists = valid_for(particles) ? &list_ : nullptr;
        NeighborList<Dim> compacted;
        if (!lists && built_()) {
            if (const auto* keep = particles.kept_since(built_generation_)) {
                compacted = list_;
                compacted.compact(*keep);
                lists = &compacted;
            }
        }
        group.write("valid", std::int64_t{lists != nullptr});
        if (!lists) return;
        const auto n = static_cast<std::size_t>(lists->particle_count());
        group.write("reference_positions", reinterpret_cast<const double*>(lists->reference_positions()), n, Dim);
        group.write("offsets", lists->offsets(), n + 1, 1);
        group.write("indices", lists->indices(), lists->pair_count(), 1);
    }
    /// Reads back the lists of a loaded set (checkpoints without them: rebuilt from the positions they
    /// were built at; the particles are still in that build's cell order, so the lists come out as they were).
    void load(const io::Hdf5Group& group, const particles::SphParticles<Dim>& particles, double radius,
              const PeriodicBox<Dim>& box = {}) {
        builds_ = static_cast<long>(group.read_int("builds"));
        compactions_ = group.has_attribute("compactions") ? static_cast<long>(group.read_int("compactions")) : 0;
        built_generation_ = never;
        list_ = NeighborList<Dim>();
        if (group.read_int("valid") == 0) return;
        std::size_t rows = 0;
        const auto raw = group.read_doubles("reference_positions", Dim, rows);
        const Index n = particles.size();
        if (rows != static_cast<std::size_t>(n))
            throw io::Hdf5Error(group.path() + "/reference_positions: one row per particle expected");
        std::vector<Vec> reference(rows);
        for (std::size_t i = 0; i < rows; ++i)
            for (int k = 0; k < Dim; ++k) reference[i][k] = raw[i * Dim + static_cast<std::size_t>(k)];
        if (group.has("offsets")) {
            std::size_t offset_rows = 0, index_rows = 0;
            auto offsets = group.read_int32("offsets", 1, offset_rows);
            auto indices = group.read_int32("indices", 1, index_rows);
            if (offset_rows != rows + 1 || offsets.front() != 0 ||
                static_cast<std::size_t>(offsets.back()) != index_rows ||
                !std::is_sorted(offsets.begin(), offsets.end()) ||
                std::any_of(indices.begin(), indices.end(), [&](Index j) { return j < 0 || j >= n; }))
                throw io::Hdf5Error(group.path() + ": neighbour lists do not match the particles");
            list_.assign(std::move(offsets), std::move(indices), std::move(reference));
            built_generation_ = particles.generation();
            return;
        }
        grid_ = make_grid(reference.data(), n, radius, box);
        sort_by_cell(grid_, reference.data(), n, order_, cell_start_);
        for (Index i = 0; i < n; ++i)
            if (order_[static_cast<std::size_t>(i)] != i)
                throw io::Hdf5Error(group.path() + ": the particles are not in the order of their neighbour lists");
        const auto separation = sides(particles);
        list_.build(grid_, cell_start_, reference.data(), n, radius, particles.phase(), box,
                    separation.normal ? &separation : nullptr);
        built_generation_ = particles.generation();
    }

    /// Walls thinner than the kernel: before each build, `refresh` brings the particles' wall normals
    /// (the vector field `normal_field`) up to date, and the pairs SideSeparation sets apart (with the
    /// int32 field `far_field` and `far_cos`) are left out of the lists.
    void separate_sides(std::string normal_field, std::string far_field, double far_cos,
                        std::function<void(particles::SphParticles<Dim>&)> refresh) {
        normal_field_ = std::move(normal_field);
        far_field_ = std::move(far_field);
        far_cos_ = far_cos;
        refresh_sides_ = std::move(refresh);
    }

    /// Called at each build before the particles are sorted: the symmetry plane replaces its images
    /// (modules/symmetry_plane.*), so that the lists hold the images of the particles near the plane.
    void before_build(std::function<void(particles::SphParticles<Dim>&)> make) { before_build_ = std::move(make); }

private:
    SideSeparation<Dim> sides(const particles::SphParticles<Dim>& particles) const {
        SideSeparation<Dim> s;
        const auto& fields = particles.fields();
        if (normal_field_.empty() || !fields.has(normal_field_) || !fields.has(far_field_)) return s;
        s.normal = fields.template get<Vec>(normal_field_).data();
        s.far_side = fields.template get<std::int32_t>(far_field_).data();
        s.far_cos = far_cos_;
        return s;
    }

    // Without periodic axes, cubic cells over the particles; with them, the periodic axes of the box in
    // whole cells of at least `radius` (the others over the particles).
    static CellGrid<Dim> make_grid(const Vec* x, Index n, double radius, const PeriodicBox<Dim>& box) {
        if (!box.any()) return CellGrid<Dim>::covering(x, n, radius);
        return CellGrid<Dim>::over_box(box.periodic, box.lower, box.upper, x, n, radius);
    }

    static constexpr std::uint64_t never = ~std::uint64_t{0};
    bool built_() const noexcept { return built_generation_ != never; }

    CellGrid<Dim> grid_;
    NeighborList<Dim> list_;
    std::vector<Index> order_, cell_start_;
    std::uint64_t built_generation_ = never;
    long builds_ = 0, compactions_ = 0;
    std::string normal_field_, far_field_;
    double far_cos_ = 0.5;
    std::function<void(particles::SphParticles<Dim>&)> refresh_sides_;
    std::function<void(particles::SphParticles<Dim>&)> before_build_;
};

}  // namespace grit::neighbors
