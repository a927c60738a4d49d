// Fluid particles enclosed by a solid: a check that the water stays out of the specimen. SPH keeps phases
// apart only through the pressure between them, so a fluid particle can slip between the particles of a
// solid that a grain has opened or that is in tension; this counts such particles (zero expected).
#pragma once

#include "grit/core/types.hpp"
#include "grit/neighbors/periodic_box.hpp"
#include "grit/particles/sph_particles.hpp"

namespace grit::analysis {

/// Cone half-angle around each axis direction within which a solid neighbour closes that side [rad].
inline constexpr double enclosure_cone = 0.5235987755982988;  // 30 degrees

/// The fluid particles with a solid particle within `reach` on every side: in each of the 2 Dim axis
/// directions (+-x, +-y, +-z), within a cone of half-angle `enclosure_cone` around it. A fluid particle on a
/// solid surface, or at the bottom of a crater open to the jet, has a free side; one wedged between two
/// rows of a solid lattice has none. Distances are nearest-image along `box`'s periodic axes. Serial
/// and independent of the particle order.
template <int Dim>
Index count_fluid_in_solids(const particles::SphParticles<Dim>& particles, double reach,
                            const neighbors::PeriodicBox<Dim>& box = {});

extern template Index count_fluid_in_solids<2>(const particles::SphParticles<2>&, double,
                                                const neighbors::PeriodicBox<2>&);
extern template Index count_fluid_in_solids<3>(const particles::SphParticles<3>&, double,
                                                const neighbors::PeriodicBox<3>&);

}  // namespace grit::analysis
