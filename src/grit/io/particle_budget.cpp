// The particle budget: counts from the shapes' sizes alone (closed forms, no points generated), each an
// upper bound of what sim/geometry.cpp's lattices and the inlets make.
#include "grit/io/particle_budget.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

#include "grit/core/error.hpp"
#include "grit/dem/grain_set.hpp"
#include "grit/dem/size_distribution.hpp"

namespace grit::io {

namespace {

// Memory per particle, measured as the growth of the peak resident size of `grit run` (Release, one
// thread, output.snapshots = false, a few steps so that the neighbour lists exist) between two spacings
// of the same case: 2D dam break 86k -> 332k particles: 475 B each; 3D dam break 74k -> 124k: 620 B;
// 3D hydrostatic 12k -> 21k: 660 B; 3D grains (dem_settling_3d) 11k -> 50k: 640 B. The fields alone
// are 116 B (2D) / 148 B (3D), plus 100 B in cases with solids; the rest is mostly the full Verlet
// neighbour rows (~25 neighbours in 2D, ~90 in 3D, 4 B each) and sorting scratch. Rounded up:
constexpr double sph_bytes_2d = 500.0;
constexpr double sph_bytes_3d = 700.0;
constexpr double grain_bytes = 700.0;

/// Lattice points along an axis of length `length`: the count sim/geometry.cpp's lattices use.
double points_along(double length, double dx) { return std::max(0.0, std::floor(length / dx + 1e-6)); }

/// Points of a lattice of spacing dx within a ball of radius r in `dim` dimensions (dim = 2: a disc;
/// dim = 3: a sphere), bounded above: the cells (side dx) around such points are disjoint and lie in
/// the ball of radius r + sqrt(dim) dx / 2; nor can there be more than the bounding square or cube holds.
double ball_bound(double r, int dim, double dx) {
    const double grown = r / dx + 0.5 * std::sqrt(static_cast<double>(dim));
    const double ball = dim == 2 ? std::numbers::pi * grown * grown
                                 : 4.0 / 3.0 * std::numbers::pi * grown * grown * grown;
    const double side = 2.0 * std::ceil(r / dx);
    return std::min(ball, std::pow(side, dim));
}

/// Upper bound of the particles a jet inlet emits by time `end`: layers of diameter/dx points (2D) or
/// (diameter/dx)^2 (3D, the square around the disc), one at the start and one per dx the jet advances.
/// With `reach`, at most the layers within that distance of the nozzle: those still in the domain when
/// the particles that crossed `reach` have left.
double inlet_bound(const InletSpec& in, int dim, double dx, double end,
                   double reach = std::numeric_limits<double>::infinity()) {
    const double duration = std::min(in.stop, end) - in.start;
    if (!(duration > 0.0)) return 0.0;
    const double across = points_along(in.diameter, dx);
    const double per_layer = dim == 2 ? across : across * across;
    const double layers = 1.0 + std::floor(std::min(in.velocity * duration, reach) / dx);
    return per_layer * layers;
}

/// Grains a block makes: one, `count`, or the lattice of dem/grain_fill.hpp.
double grain_count(const GrainBlockSpec& g, int dim) {
    if (g.arrangement == "single") return 1.0;
    if (g.arrangement == "random") return static_cast<double>(g.count);
    double n = 1.0;
    for (std::size_t k = 0; k < static_cast<std::size_t>(dim); ++k)
        n *= std::max(0.0, std::floor((g.max[k] - g.min[k]) / g.spacing + 1e-9));
    return n;
}

}  // namespace

double shape_particle_bound(const ShapeSpec& shape, int dim, double dx) {
    const auto at = [](const std::vector<double>& v, int k) { return v[static_cast<std::size_t>(k)]; };
    if (shape.kind == "box") {
        double n = 1.0;
        for (int k = 0; k < dim; ++k) n *= points_along(at(shape.max, k) - at(shape.min, k), dx);
        return n;
    }
    if (shape.kind == "disc") return ball_bound(shape.radius, dim, dx);
    if (shape.kind == "cylinder") return ball_bound(shape.radius, 2, dx) * points_along(shape.length, dx);
    if (shape.kind == "tank") {
        // The lattice over the outer box (the inner box grown by `layers` spacings on each closed side),
        // less its points strictly inside the inner box. The lattice is aligned with the inner min (the
        // layers are whole spacings), so per axis the inner points are those at (j + 1/2) dx < length,
        // j >= 0: ceil(length / dx - 1/2) of them, or floor(length / dx) where the high side is open (the
        // outer box ends at the inner max). The 1e-6 margins take the smaller count where rounding
        // decides, so that the result stays an upper bound.
        const char* low_side[3] = {"left", dim == 2 ? "bottom" : "front", "bottom"};
        const char* high_side[3] = {"right", dim == 2 ? "top" : "back", "top"};
        const auto is_open = [&](const char* side) {
            return std::find(shape.open.begin(), shape.open.end(), std::string(side)) != shape.open.end();
        };
        const double t = shape.layers * dx;
        double outer = 1.0, inner = 1.0;
        for (int k = 0; k < dim; ++k) {
            const double length = at(shape.max, k) - at(shape.min, k);
            const double grown = length + (is_open(low_side[k]) ? 0.0 : t) + (is_open(high_side[k]) ? 0.0 : t);
            outer *= points_along(grown, dx);
            const double below_max = std::max(0.0, std::ceil(length / dx - 0.5 - 1e-6));
            inner *= is_open(high_side[k]) ? std::min(points_along(length, dx), below_max) : below_max;
        }
        return std::max(0.0, outer - inner);
    }
    if (shape.kind == "mesh" && shape.mesh) {
        // A shell `layers` thick over the mesh's area, with a margin for edges and corners.
        double area = 0.0;
        for (std::size_t t = 0; t < shape.mesh->triangle_count(); ++t) area += shape.mesh->area(t);
        return 2.0 * area / (dx * dx) * shape.layers + 1000.0;
    }
    return 0.0;
}

double domain_particle_room(const CaseSpec& c) {
    if (c.domain_min.size() < static_cast<std::size_t>(c.dimension) || !(c.particle_spacing > 0.0))
        return std::numeric_limits<double>::infinity();
    double room = 1.1;
    for (std::size_t k = 0; k < static_cast<std::size_t>(c.dimension); ++k)
        room *= (c.domain_max[k] - c.domain_min[k]) / c.particle_spacing + 1.0;
    return room;
}

double domain_diagonal(const CaseSpec& c) {
    if (c.domain_min.size() < static_cast<std::size_t>(c.dimension)) return std::numeric_limits<double>::infinity();
    double d2 = 0.0;
    for (std::size_t k = 0; k < static_cast<std::size_t>(c.dimension); ++k)
        d2 += (c.domain_max[k] - c.domain_min[k]) * (c.domain_max[k] - c.domain_min[k]);
    return std::sqrt(d2);
}

double domain_grain_room(const CaseSpec& c, double d) {
    if (c.domain_min.size() < static_cast<std::size_t>(c.dimension) || !(d > 0.0))
        return std::numeric_limits<double>::infinity();
    double room = 1.5;
    for (std::size_t k = 0; k < static_cast<std::size_t>(c.dimension); ++k)
        room *= (c.domain_max[k] - c.domain_min[k]) / d;
    return room;
}

ParticleEstimate estimate_particles(const CaseSpec& c) {
    ParticleEstimate e;
    const int dim = c.dimension;
    const double dx = c.particle_spacing;
    double blocks = 0.0;
    for (const auto* list : {&c.fluids, &c.solids, &c.walls})
        for (const auto& b : *list)
            blocks += shape_particle_bound(b.shape, dim, dx);
    // Outlets drain what the inlets emit: a jet's water crosses the domain and leaves, so at a time the
    // domain holds about what enters while a particle crosses its diagonal (a run's own count is lower:
    // the water leaves by the nearest outlet, not along the diagonal).
    const bool drained = !c.outlets.empty();
    const double diagonal = domain_diagonal(c);
    double crossing = 0.0;
    for (const auto& in : c.inlets) {
        e.inlets += inlet_bound(in, dim, dx, c.end_time);
        crossing += inlet_bound(in, dim, dx, c.end_time, diagonal);
    }
    e.inlets_held = std::min(e.inlets, std::max(0.0, domain_particle_room(c) - blocks));
    e.inlets_in_flight = drained ? std::min(e.inlets_held, crossing) : e.inlets_held;
    e.sph = blocks + e.inlets_held;

    double placed = 0.0, smallest = std::numeric_limits<double>::infinity();
    double abrasive_fed = 0.0, abrasive_in_flight = 0.0;
    for (const auto& g : c.grains) {
        placed += grain_count(g, dim);
        smallest = std::min(smallest, dem::smallest_diameter(g.size));
    }
    if (c.abrasive.enabled && c.abrasive.spacing > 0.0) {
        // One grain per column of the jet that enters by time.end (and one that joins ahead of it).
        const auto& jet = c.inlets[static_cast<std::size_t>(c.abrasive.inlet)];
        const double duration = std::min(c.abrasive.stop, c.end_time) - c.abrasive.start;
        if (duration > 0.0) {
            const double fed = 2.0 + std::floor(jet.velocity * duration / c.abrasive.spacing);
            e.grains_fed += fed;
            abrasive_fed = fed;
            abrasive_in_flight = drained ? std::min(fed, 2.0 + std::floor(diagonal / c.abrasive.spacing)) : fed;
        }
        smallest = std::min(smallest, dem::smallest_diameter(c.abrasive.size));
    }
    for (const auto& f : c.grain_feeds) {
        // Insertions at start + k interval up to the earlier of stop and time.end; each inserts the nearest
        // whole number of grains to the mass due (at most its mass over the smallest grain's, plus one).
        const double duration = std::min(f.stop, c.end_time) - f.start;
        if (!(duration >= 0.0) || !(f.interval > 0.0)) continue;
        const double insertions = std::floor(duration / f.interval + 1e-9) + 1.0;
        const double d = dem::smallest_diameter(f.size);
        const double density = c.grain_materials[static_cast<std::size_t>(f.material)].density;
        const double m = dim == 2 ? dem::grain_mass<2>(density, 0.5 * d) : dem::grain_mass<3>(density, 0.5 * d);
        double n = insertions * (f.mass_flow_rate * f.interval / m + 1.0);
        if (f.count > 0) n = std::min(n, static_cast<double>(f.count));
        e.grains_fed += n;
        smallest = std::min(smallest, d);
    }
    e.grains = placed + e.grains_fed;
    if (e.grains_fed > 0.0) e.grains = std::min(e.grains, std::max(placed, domain_grain_room(c, smallest)));
    e.grains_in_flight = std::min(e.grains, placed + (e.grains_fed - abrasive_fed) + abrasive_in_flight);
    e.bytes = e.sph * (dim == 2 ? sph_bytes_2d : sph_bytes_3d) + e.grains * grain_bytes;
    return e;
}

void check_particle_budget(const CaseSpec& c) {
    const ParticleEstimate e = estimate_particles(c);
    if (e.total() <= static_cast<double>(c.max_particles)) return;
    // Name the key that makes the most: the SPH spacing, or the grains block with the most grains.
    std::string cause = fmt::format("numerics.particle_spacing = {} m", c.particle_spacing);
    if (e.inlets_held > 0.5 * e.sph) cause += fmt::format(" with inlets until time.end = {} s", c.end_time);
    double most = e.sph;
    for (const auto& g : c.grains) {
        const double n = grain_count(g, c.dimension);
        if (n <= most) continue;
        most = n;
        cause = g.arrangement == "lattice" ? fmt::format("{}.spacing = {} m", g.key, g.spacing)
                                           : fmt::format("{}.count = {}", g.key, g.count);
    }
    const std::string limit =
        fmt::format("the limit is numerics.max_particles = {} (raise it to allow more)", c.max_particles);
    // A spacing near the smallest double overflows the counts.
    if (!std::isfinite(e.total()) || !std::isfinite(e.bytes))
        throw core::InputError(fmt::format("{} would make more particles than a double can count; {}", cause, limit));
    const std::string grains = e.sph > 0.0 && e.grains > 0.0 ? fmt::format(" ({:.1e} of them grains)", e.grains) : "";
    throw core::InputError(fmt::format("{} would make about {:.1e} {}{} (~{:.1e} bytes); {}", cause, e.total(),
                                       e.sph > 0.0 ? "particles" : "grains", grains, e.bytes, limit));
}

namespace {

/// The smallest size of a block's shape [m]: a box's thinnest side, a disc's or sphere's diameter, the
/// lesser of a cylinder's diameter and length. A tank's walls are `layers` spacings thick by
/// construction, so it has no size to compare (0).
double thinnest(const ShapeSpec& shape, int dim) {
    if (shape.kind == "box") {
        double t = std::numeric_limits<double>::infinity();
        for (std::size_t k = 0; k < static_cast<std::size_t>(dim); ++k) t = std::min(t, shape.max[k] - shape.min[k]);
        return t;
    }
    if (shape.kind == "disc") return 2.0 * shape.radius;
    if (shape.kind == "cylinder") return std::min(2.0 * shape.radius, shape.length);
    return 0.0;
}

}  // namespace

void check_resolution(const CaseSpec& c) {
    const double dx = c.particle_spacing;
    for (const auto* blocks : {&c.fluids, &c.solids}) {
        for (const auto& b : *blocks) {
            const double size = thinnest(b.shape, c.dimension);
            if (size <= 0.0 || size >= min_particles_across * dx) continue;
            throw core::InputError(fmt::format(
                "key 'numerics.particle_spacing' = {} m: {} ({}) is {:.3g} m across at its thinnest, {:.2g} particles; "
                "a body needs at least {} (lengths are in metres: 0.1 mm is 1e-4)",
                dx, b.key, b.shape.kind, size, size / dx, min_particles_across));
        }
    }
}

}  // namespace grit::io
