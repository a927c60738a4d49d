// Crater analysis of an eroded solid surface (2D): the surface profile, crater depth C_d and width C_w.
#pragma once

#include <vector>

#include "grit/particles/sph_particles.hpp"

namespace grit::analysis {

/// Where the original surface is and which part of it to profile.
struct CraterRegion {
    double surface = 0.0;          ///< original surface height y0 [m]
    double x_min = 0.0, x_max = 0.0;  ///< profiled range along x [m]
    /// A symmetry plane at x = 0 (modules/symmetry_plane): each particle also stands at -x, so the
    /// profile is the whole crater's (x_min = -x_max).
    bool mirror = false;
};

struct CraterProfile {
    std::vector<double> x;        ///< bin centres [m]
    std::vector<double> surface;  ///< surface height in each bin [m]; NaN where no solid is left
    double depth = 0.0;           ///< C_d: deepest point below the original surface [m] (>= 0)
    double width = 0.0;           ///< C_w: width of the crater at the original surface level [m]
    double rim_width = 0.0;       ///< distance between the crests of the lips piled up either side [m]
    double lip_height = 0.0;      ///< the two lips' mean height above the original surface [m]
};

/// Profile of the solid's top surface in bins of width `spacing`: in each bin, the highest centre, plus
/// half a spacing (its edge), of the solid particles within the bin widened by a quarter spacing on
/// each side. With bins centred on the lattice's columns a pit one column wide is resolved.
/// C_d = y0 - min(surface), or 0. C_w: from the deepest bin, the profile is followed left and right to
/// where it first rises back to y0 - spacing/2 (the original surface, less the lattice's half spacing);
/// the crossings are interpolated linearly and C_w is their distance (0 when there is no crater deeper
/// than half a spacing). The rim width is the distance between the crests of the lips a ductile crater
/// piles up either side: walking out from each crossing, within C_w / 2 of it, the highest surface at
/// least half a spacing above y0, until the profile falls a spacing below it; the crest is the middle of
/// the bins within half a spacing of that top. A side without such a lip keeps its crossing (so rim
/// width >= C_w; a crater without lips has rim width = C_w). Symmetry planes' images are left out (with
/// `mirror`, each particle counts twice).
CraterProfile analyse_crater(const particles::SphParticles<2>& particles, const CraterRegion& region, double spacing);

}  // namespace grit::analysis
