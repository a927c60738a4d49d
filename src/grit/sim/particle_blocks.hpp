// The case's particle blocks ([[fluid]], [[solid]], [[wall]]) laid out as lattices with their starting state.
#pragma once

#include <functional>

#include "grit/core/vec.hpp"
#include "grit/io/case_spec.hpp"
#include "grit/neighbors/periodic_box.hpp"
#include "grit/particles/sph_particles.hpp"

namespace grit::sim {

/// Which lattice points of the blocks to add (a sub-domain's part): true keeps the point. An empty filter
/// keeps every point.
template <int Dim>
using LatticeFilter = std::function<bool(const core::Vec<Dim>&)>;

/// Appends every fluid, solid and wall block of `spec` to `particles` on lattices of spacing dx: each
/// particle's mass (rho0 dx^Dim), velocity (the block's, or its cantilever mode), pressure (hydrostatic
/// below the block's top when asked) and the density its equation of state gives at that pressure.
/// Thin mesh walls also fill ThinWallsModule's normal fields, which must be registered beforehand.
/// Throws core::InputError for a block that holds no particle. Each particle's id is by origin (its
/// block and lattice index, domain/particle_id.hpp); with `keep`, only the lattice points it accepts are
/// added (a sub-domain's part), with the ids and state they have in the whole block.
template <int Dim>
void add_particle_blocks(const io::CaseSpec& spec, double dx, particles::SphParticles<Dim>& particles,
                         const LatticeFilter<Dim>& keep = {});

/// Checks that every particle lies inside domain.min/domain.max (throws core::InputError naming the first
/// that does not), then wraps them along the periodic axes of `box` into [min, max) (a point on max is
/// the one on min).
template <int Dim>
void check_and_wrap_into_domain(const io::CaseSpec& spec, const neighbors::PeriodicBox<Dim>& box,
                                particles::SphParticles<Dim>& particles);

extern template void add_particle_blocks<2>(const io::CaseSpec&, double, particles::SphParticles<2>&,
                                            const LatticeFilter<2>&);
extern template void add_particle_blocks<3>(const io::CaseSpec&, double, particles::SphParticles<3>&,
                                            const LatticeFilter<3>&);
extern template void check_and_wrap_into_domain<2>(const io::CaseSpec&, const neighbors::PeriodicBox<2>&,
                                                   particles::SphParticles<2>&);
extern template void check_and_wrap_into_domain<3>(const io::CaseSpec&, const neighbors::PeriodicBox<3>&,
                                                   particles::SphParticles<3>&);

}  // namespace grit::sim
