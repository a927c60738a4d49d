// The axes of a nozzle section: orthonormal directions across a jet of unit direction d.
#pragma once

#include <array>
#include <cmath>

#include "grit/core/vec.hpp"

namespace grit::boundary {

/// Orthonormal directions spanning the plane normal to the unit vector `d`: (-d_y, d_x) in 2D; in 3D
/// t1 from the coordinate axis least aligned with d (Gram-Schmidt) and t2 = d x t1.
template <int Dim>
std::array<core::Vec<Dim>, Dim - 1> section_axes(const core::Vec<Dim>& d) {
    using Vec = core::Vec<Dim>;
    Vec t1 = Vec::zero();
    if constexpr (Dim == 2) {
        t1[0] = -d[1];
        t1[1] = d[0];
        return {t1};
    } else {
        Vec helper = Vec::zero();
        helper[std::abs(d[0]) < 0.9 ? 0 : 1] = 1.0;
        t1 = helper - d * core::dot(helper, d);
        t1 *= 1.0 / core::norm(t1);
        Vec t2 = Vec::zero();
        t2[0] = d[1] * t1[2] - d[2] * t1[1];
        t2[1] = d[2] * t1[0] - d[0] * t1[2];
        t2[2] = d[0] * t1[1] - d[1] * t1[0];
        return {t1, t2};
    }
}

}  // namespace grit::boundary
