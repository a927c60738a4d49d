// Particle lattices for the geometry primitives of a case file (box, disc/sphere, tank walls).
#pragma once

#include <vector>

#include "grit/core/vec.hpp"
#include "grit/io/case_spec.hpp"

namespace grit::sim {

/// True when x lies inside the box [lo, hi] (bounds included).
template <int Dim>
bool inside(const core::Vec<Dim>& x, const std::vector<double>& lo, const std::vector<double>& hi) {
    for (int k = 0; k < Dim; ++k)
        if (x[k] < lo[static_cast<std::size_t>(k)] || x[k] > hi[static_cast<std::size_t>(k)]) return false;
    return true;
}

/// Lattice points (spacing dx, cell-centred, aligned with the shape's min corner) filling `shape`.
/// A tank yields its walls: `layers` of points outside the inner box on every side not listed as open.
/// A thin mesh wall (shape.thin) also gives each point's wall normal in `normals` (ThinWallsModule).
template <int Dim>
struct WallNormals {
    std::vector<core::Vec<Dim>> normal;  ///< unit, of the surface the point stands behind, to the water
    std::vector<std::int32_t> far_side;  ///< 1: behind a facet, yet on the water's side of the sheet (a fold)
};

template <int Dim>
std::vector<core::Vec<Dim>> lattice_points(const io::ShapeSpec& shape, double dx,
                                           WallNormals<Dim>* normals = nullptr);

extern template std::vector<core::Vec<2>> lattice_points<2>(const io::ShapeSpec&, double, WallNormals<2>*);
extern template std::vector<core::Vec<3>> lattice_points<3>(const io::ShapeSpec&, double, WallNormals<3>*);

}  // namespace grit::sim
