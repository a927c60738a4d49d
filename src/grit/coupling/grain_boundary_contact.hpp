// Contact between rigid DEM grains and SPH solid or wall particles by the penalty method of the first
// seed paper (eqs. 12-14): an SPH particle closer than one initial spacing d_ini to a grain's surface is
// pushed out along the grain's normal with the force that would remove the overlap in one step, plus a
// tangential force capped by Coulomb friction; the grain takes the opposite force at the contact point.
// Both are scaled by the grain's share M / (M + sum m_a) of the particles it touches, so that particles
// as heavy as the grain do not make the contact unstable (docs/theory.md, "the grain's share").
#pragma once

#include <vector>

#include "grit/core/types.hpp"
#include "grit/core/vec.hpp"
#include "grit/dem/grain_set.hpp"
#include "grit/neighbors/cross_pairs.hpp"
#include "grit/particles/sph_particles.hpp"

namespace grit::coupling {

/// Settings of the penalty contact.
struct PenaltyContactParameters {
    double spacing = 0.0;              ///< d_ini, the initial SPH particle spacing [m]
    double overlap_coefficient = 0.0;  ///< chi of eq. (13), 0 = no overlap allowed [-]
    double friction = 0.3;             ///< mu between grains and SPH solids and walls [-]
    bool walls = true;                 ///< grains touch SPH wall particles (off where mesh walls stand in)
};

/// One grain-particle pair of the current step: in contact (closer than d_ini to the grain's surface),
/// or only near (closer than 2 d_ini), which the impact log uses so that a grain rattling on a surface
/// is not counted as a new impact at every step it loses contact.
template <int Dim>
struct PenaltyContact {
    bool touching = false;
    Index grain = 0;     ///< grain index (this step's order)
    Index particle = 0;  ///< SPH particle index
    core::Vec<Dim> normal = core::Vec<Dim>::zero();  ///< unit normal from the grain centre to the particle
    core::Vec<Dim> lever = core::Vec<Dim>::zero();   ///< x_p - x_i: the contact point from the grain centre
    core::Vec<Dim> force = core::Vec<Dim>::zero();   ///< F_ia, on the particle [N] (N/m in 2D)
};

/// The contacts of one step and their forces. Each pair's force is computed once; the particle side and
/// the grain side then gather them in fixed orders, so the sums are equal and opposite and do not depend
/// on the thread count.
template <int Dim>
class GrainBoundaryContact {
public:
    using Vec = core::Vec<Dim>;

    GrainBoundaryContact() = default;
    explicit GrainBoundaryContact(PenaltyContactParameters parameters) : parameters_(parameters) {}

    /// Finds the contacts (and near pairs) of grains with solid and wall particles at the current
    /// positions and computes the contacts' forces (eq. 13) for a step of dt. Along the periodic axes of
    /// `box`, across the faces too (nearest image).
    void compute(const dem::GrainSet<Dim>& grains, const particles::SphParticles<Dim>& particles, double dt,
                 const neighbors::PeriodicBox<Dim>& box = {});

    /// Adds the forces: F / m_a to the acceleration of solid particles (walls and clamped particles keep
    /// their prescribed motion), and -F with its moment about the centre (eq. 14) to the grains.
    void apply(dem::GrainSet<Dim>& grains, particles::SphParticles<Dim>& particles,
               const std::int32_t* fixed) const;

    const std::vector<PenaltyContact<Dim>>& contacts() const noexcept { return contacts_; }
    const PenaltyContactParameters& parameters() const noexcept { return parameters_; }

private:
    PenaltyContactParameters parameters_;
    neighbors::CrossPairList<Dim> pairs_;          // grains near each solid or wall particle
    std::vector<PenaltyContact<Dim>> contacts_;   // ordered as pairs_: by particle, then grain
    std::vector<Index> grain_start_, grain_order_;  // contacts of grain g: grain_order_[grain_start_[g] ..]
};

extern template class GrainBoundaryContact<2>;
extern template class GrainBoundaryContact<3>;

}  // namespace grit::coupling
