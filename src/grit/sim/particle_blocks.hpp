// The case's particle blocks ([[fluid]], [[solid]], [[wall]]) laid out as lattices with their starting state.
#pragma once

#include "grit/io/case_spec.hpp"
#include "grit/neighbors/periodic_box.hpp"
#include "grit/particles/sph_particles.hpp"

namespace grit::sim {

/// Appends every fluid, solid and wall block of `spec` to `particles` on lattices of spacing dx: each
/// particle's mass (rho0 dx^Dim), velocity (the block's, or its cantilever mode), pressure (hydrostatic
/// below the block's top when asked) and the density its equation of state gives at that pressure.
/// Thin mesh walls also fill ThinWallsModule's normal fields, which must be registered beforehand.
/// Throws core::InputError for a block that holds no particle.
template <int Dim>
void add_particle_blocks(const io::CaseSpec& spec, double dx, particles::SphParticles<Dim>& particles);

/// Checks that every particle lies inside domain.min/domain.max (throws core::InputError naming the first
/// that does not), then wraps them along the periodic axes of `box` into [min, max) (a point on max is
/// the one on min).
template <int Dim>
void check_and_wrap_into_domain(const io::CaseSpec& spec, const neighbors::PeriodicBox<Dim>& box,
                                particles::SphParticles<Dim>& particles);

extern template void add_particle_blocks<2>(const io::CaseSpec&, double, particles::SphParticles<2>&);
extern template void add_particle_blocks<3>(const io::CaseSpec&, double, particles::SphParticles<3>&);
extern template void check_and_wrap_into_domain<2>(const io::CaseSpec&, const neighbors::PeriodicBox<2>&,
                                                   particles::SphParticles<2>&);
extern template void check_and_wrap_into_domain<3>(const io::CaseSpec&, const neighbors::PeriodicBox<3>&,
                                                   particles::SphParticles<3>&);

}  // namespace grit::sim
