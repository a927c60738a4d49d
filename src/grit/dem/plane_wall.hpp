// An infinite plane wall for grains: a point on it and the unit normal pointing into the grains' side.
#pragma once

#include <cstdint>

#include "grit/core/vec.hpp"

namespace grit::dem {

/// Grains touch the plane when their centre is closer than their radius to it on the normal's side.
/// The wall is fixed; it contacts grains with the system's law and the pair properties of its material.
template <int Dim>
struct PlaneWall {
    core::Vec<Dim> point = core::Vec<Dim>::zero();   ///< a point of the plane [m]
    core::Vec<Dim> normal = core::Vec<Dim>::zero();  ///< unit normal towards the grains
    std::int32_t material = 0;                       ///< index into the system's material table
    /// No friction (a symmetry plane: a grain meets its mirror twin there, their surfaces moving together).
    /// Grains flagged in the int32 grain field `straddling` (> 0) pass it: they lie across the plane
    /// (modules/symmetry_plane).
    bool frictionless = false;
};

/// The grain field of the grains a frictionless plane lets pass.
inline constexpr const char* straddling_field = "straddling";

}  // namespace grit::dem
