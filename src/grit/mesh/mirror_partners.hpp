// Which triangle of a set is which other's mirror image across the plane x_axis = 0: a symmetry plane
// runs the x >= 0 half of a set-up, and a mesh wall standing across the plane wears on its x < 0 side as
// its mirror image does on the other (modules/mesh_wear).
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "grit/core/vec.hpp"

namespace grit::mesh {

using Corners = std::array<core::Vec<3>, 3>;

/// For each triangle, the index of the triangle whose corners are its own mirrored across x_axis = 0 (in
/// any order, each within `tolerance` [m]), or -1 if none is. A triangle that is its own mirror image
/// (one standing across the plane, symmetric about it) is its own partner.
std::vector<std::int64_t> mirror_partners(const std::vector<Corners>& triangles, int axis, double tolerance);

/// The tolerance a mirror image is found to: 1e-6 of the triangles' largest coordinate. STL corners are
/// single precision, so this is far above a mirror's round-off and far below any feature a mesh resolves.
double mirror_tolerance(const std::vector<Corners>& triangles);

}  // namespace grit::mesh
