// Particle lattices for geometry primitives.
#include "grit/sim/geometry.hpp"

#include "grit/mesh/signed_distance.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

namespace grit::sim {

namespace {

/// Calls f(point) for each cell centre of the lattice over [lo, hi) with spacing dx aligned at lo.
template <int Dim, class F>
void for_each_lattice_point(const core::Vec<Dim>& lo, const core::Vec<Dim>& hi, double dx, F&& f) {
    std::array<long, Dim> n{};
    for (int k = 0; k < Dim; ++k) n[k] = std::max(0L, std::lround(std::floor((hi[k] - lo[k]) / dx + 1e-6)));
    std::array<long, Dim> i{};
    long total = 1;
    for (int k = 0; k < Dim; ++k) total *= n[k];
    for (long flat = 0; flat < total; ++flat) {
        long rest = flat;
        for (int k = 0; k < Dim; ++k) {
            i[k] = rest % n[k];
            rest /= n[k];
        }
        core::Vec<Dim> x{};
        for (int k = 0; k < Dim; ++k) x[k] = lo[k] + (static_cast<double>(i[k]) + 0.5) * dx;
        f(x);
    }
}

using core::to_vec;

}  // namespace

template <int Dim>
std::vector<core::Vec<Dim>> lattice_points(const io::ShapeSpec& shape, double dx,
                                           WallNormals<Dim>* normals) {
    using Vec = core::Vec<Dim>;
    std::vector<Vec> points;
    if (shape.kind == "box") {
        for_each_lattice_point<Dim>(to_vec<Dim>(shape.min), to_vec<Dim>(shape.max), dx,
                                    [&](const Vec& x) { points.push_back(x); });
    } else if (shape.kind == "disc") {
        const Vec c = to_vec<Dim>(shape.center);
        // Align the lattice so that a point sits a half spacing off the centre in every direction.
        const double r = shape.radius;
        const double half = std::ceil(r / dx) * dx;
        for_each_lattice_point<Dim>(c - Vec::filled(half), c + Vec::filled(half), dx, [&](const Vec& x) {
            if (core::norm2(x - c) <= r * r) points.push_back(x);
        });
    } else if (shape.kind == "cylinder") {
        // A lattice aligned with the cylinder's end face, cut to its radius.
        const Vec c = to_vec<Dim>(shape.center);
        const double half = std::ceil(shape.radius / dx) * dx;
        Vec lo = c - Vec::filled(half), hi = c + Vec::filled(half);
        lo[shape.axis] = c[shape.axis] - 0.5 * shape.length;
        hi[shape.axis] = c[shape.axis] + 0.5 * shape.length;
        for_each_lattice_point<Dim>(lo, hi, dx, [&](const Vec& x) {
            double r2 = 0.0;
            for (int k = 0; k < Dim; ++k)
                if (k != shape.axis) r2 += (x[k] - c[k]) * (x[k] - c[k]);
            if (r2 <= shape.radius * shape.radius) points.push_back(x);
        });
    } else if (shape.kind == "mesh") {
        if constexpr (Dim == 3) {
            // The lattice of the mesh's box widened by the layers, aligned at its low corner as a tank's,
            // so that a face on a lattice plane of an axis-aligned mesh lies half a spacing from the
            // nearest particles; kept: the points within the layers' thickness on the wall's side.
            // outside/inside: a closed mesh; front/back: any mesh, by its facet normals, without wrapping
            // round the rim of an open one.
            const bool closed = shape.side == "outside" || shape.side == "inside";
            mesh::SignedDistance distance(*shape.mesh, closed);
            const double t = shape.layers * dx;
            Vec lo = shape.mesh->vertices().front(), hi = lo;
            for (const Vec& v : shape.mesh->vertices())
                for (int k = 0; k < 3; ++k) lo[k] = std::min(lo[k], v[k]), hi[k] = std::max(hi[k], v[k]);
            // The water's side: +1 in front of the facets (particles behind them), -1 behind.
            const double water = shape.side == "outside" || shape.side == "front" ? -1.0 : 1.0;
            if (shape.thin) distance.bin(t);
            Vec from = lo - Vec::filled(t);
            if (shape.half) from[0] = 0.0;  // on a symmetry plane: the x >= 0 half, the lattice mirror-symmetric
            for_each_lattice_point<3>(from, hi + Vec::filled(t), dx, [&](const Vec& x) {
                const auto q = distance.query(x);
                const double d = -water * q.distance;  // > 0 on the particles' side
                if (d > 0.0 && d <= t && (closed || !q.on_rim)) {
                    points.push_back(x);
                    if (shape.thin && normals) {
                        normals->normal.push_back(q.normal * water);
                        normals->far_side.push_back(0);
                    }
                } else if (shape.thin && d < 0.0) {
                    // On the water's side of the sheet, yet just behind one of its facets: where the
                    // sheet folds back (a splitter edge), the wall of the far side. The water on this
                    // side does not see it: their normals point away from each other.
                    const Vec n = distance.face_behind(x, water);
                    if (core::norm2(n) > 0.0) {
                        points.push_back(x);
                        if (normals) {
                            normals->normal.push_back(n);
                            normals->far_side.push_back(1);
                        }
                    }
                }
            });
        }
    } else if (shape.kind == "tank") {
        const Vec lo = to_vec<Dim>(shape.min), hi = to_vec<Dim>(shape.max);
        const double t = shape.layers * dx;
        auto is_open = [&](const char* side) {
            return std::find(shape.open.begin(), shape.open.end(), std::string(side)) != shape.open.end();
        };
        // Sides per axis: x: left/right, y (2D): bottom/top; 3D: y front/back, z bottom/top.
        const char* low_side[3] = {"left", Dim == 2 ? "bottom" : "front", "bottom"};
        const char* high_side[3] = {"right", Dim == 2 ? "top" : "back", "top"};
        Vec outer_lo = lo, outer_hi = hi;
        for (int k = 0; k < Dim; ++k) {
            if (!is_open(low_side[k])) outer_lo[k] -= t;
            if (!is_open(high_side[k])) outer_hi[k] += t;
        }
        for_each_lattice_point<Dim>(outer_lo, outer_hi, dx, [&](const Vec& x) {
            bool inside = true;
            for (int k = 0; k < Dim; ++k) inside = inside && x[k] > lo[k] && x[k] < hi[k];
            if (!inside) points.push_back(x);
        });
    }
    return points;
}

template std::vector<core::Vec<2>> lattice_points<2>(const io::ShapeSpec&, double, WallNormals<2>*);
template std::vector<core::Vec<3>> lattice_points<3>(const io::ShapeSpec&, double, WallNormals<3>*);

}  // namespace grit::sim
