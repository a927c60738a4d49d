// Crater analysis of an eroded solid surface: in 2D the surface profile, crater depth C_d and width C_w;
// in 3D the surface as a map over x and y, C_d, the width across the cut (y) and the length along it (x).
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
    double y_min = 0.0, y_max = 0.0;  ///< 3D: the map's range along y, across the jet's traverse [m]
};

struct CraterProfile {
    std::vector<double> x;        ///< bin centres [m]
    std::vector<double> surface;  ///< surface height in each bin [m]; NaN where no solid is left
    double depth = 0.0;           ///< C_d: deepest point below the original surface [m] (>= 0)
    double width = 0.0;           ///< C_w: width of the crater at the original surface level [m]
    double rim_width = 0.0;       ///< distance between the crests of the lips piled up either side [m]
    double lip_height = 0.0;      ///< the two lips' mean height above the original surface [m]
    double area = 0.0;            ///< the crater's section below the original surface, within C_w [m^2]
    double shape_factor = 0.0;    ///< area / (C_d C_w): V 0.5, semicircle pi/4, box 1 (0 without a crater)
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
/// width >= C_w; a crater without lips has rim width = C_w). The area is the sum over the bins between
/// the two crossings of spacing x (y0 - surface) (a bin with no solid left counts at C_d), and the shape
/// factor area / (C_d C_w) tells a V (0.5) from a U (a semicircle pi/4, a flat-bottomed box nearly 1).
/// Symmetry planes' images are left out (with `mirror`, each particle counts twice).
CraterProfile analyse_crater(const particles::SphParticles<2>& particles, const CraterRegion& region, double spacing);

/// The local pass of analyse_crater: the bins (x, surface) from the solid particles of `particles` only,
/// not measured. The bins of sub-domains combine by their element-wise maximum (NaN: no solid there), and
/// measure_profile of the combined bins is the whole set's crater.
CraterProfile crater_bins(const particles::SphParticles<2>& particles, const CraterRegion& region, double spacing);

/// C_d, C_w, rim width, lip height, area and shape factor of a profile whose bins (x, surface) are filled, by the rules above;
/// `surface` is the original surface's height y0.
void measure_profile(CraterProfile& profile, double surface, double spacing);

/// The 3D surface: the top of the solid in square cells one spacing wide over the region (x and y), by
/// the 2D rule in both directions (a particle counts in its cell and the cells within a quarter spacing
/// of it). C_d is the deepest cell below the original surface z0 (`region.surface`). The section across
/// the cut (along y) through the deepest cell gives C_w, the rim width and the lips' height by the 2D
/// rules (the area and shape factor too: the section's); the crater's length is C_w's rule applied along the cut (x, the traverse) to the deepest cell
/// of each x, so that pits struck at different y along the nozzle's path join into one kerf. For a
/// round crater length and width are both its diameter.
struct CraterMap {
    std::vector<double> x, y;      ///< cell centres along x and along y [m]
    std::vector<double> surface;   ///< surface[j * x.size() + i]: the cell at (x[i], y[j]) [m]; NaN: no solid
    double depth = 0.0;            ///< C_d [m]
    double width = 0.0;            ///< C_w across the cut (y) through the deepest cell [m]
    double rim_width = 0.0;        ///< lip crest to lip crest across the cut [m]
    double lip_height = 0.0;       ///< the lips' mean height above z0 across the cut [m]
    double area = 0.0;             ///< the section across the cut below z0, within C_w [m^2]
    double shape_factor = 0.0;     ///< that section's area / (C_d C_w)
    double length = 0.0;           ///< along the cut (x), over the deepest cell of each x [m]
};

CraterMap analyse_crater(const particles::SphParticles<3>& particles, const CraterRegion& region, double spacing);
/// The local pass of the 3D analysis: the cells (x, y, surface), not measured; they combine as the 2D bins.
CraterMap crater_bins(const particles::SphParticles<3>& particles, const CraterRegion& region, double spacing);

/// C_d, the section's measures and the length of a map whose cells (x, y, surface) are filled, by the
/// rules above; `surface` is the original surface's height z0.
void measure_map(CraterMap& map, double surface, double spacing);

}  // namespace grit::analysis
