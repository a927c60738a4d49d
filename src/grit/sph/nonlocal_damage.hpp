// Non-local damage for Johnson-Cook solids (integral type: Pijaudier-Cabot & Bazant 1987; for ductile
// damage Tvergaard & Needleman 1995). A material with a damage length l > 0 accumulates at each
// particle, instead of its own increment of eq. (36), the average of its material's increments within l:
//   dD_i = sum_j w_ij V_j dD_j / sum_j w_ij V_j,   w_ij = (1 - r_ij^2 / l^2)^2 for r_ij < l,
// over the particles of the same material, itself included (so a surface particle averages over the
// solid side only). Why: with local damage a surface particle fails after about as many impacts at any
// spacing and its removal takes rho0 dx^Dim, so the crater does not converge (docs/theory.md,
// "Removal"); the average ties the failure to a length of the material instead of the particle.
// Images of a symmetry plane stand in the sums for the mirrored half and carry their sources'
// increments. The pairs are listed within l plus a skin between the members in ascending id, kept when
// particles are removed (outlets, erosion) or reordered (the members found again by id), and rebuilt
// when a member has moved half the skin or a particle has become one; the sums take the pairs closer
// than l in ascending id, so they do not depend on when the list was built (restarts continue bit for
// bit) or on the thread count.
#pragma once

#include <cstdint>
#include <unordered_map>
#include <vector>

#include "grit/neighbors/cross_pairs.hpp"
#include "grit/neighbors/periodic_box.hpp"
#include "grit/particles/sph_particles.hpp"

namespace grit::sph {

template <int Dim>
class NonlocalDamage {
public:
    NonlocalDamage() = default;
    /// `length[m]`: the damage length of material m [m] (0: local damage, not averaged).
    NonlocalDamage(std::vector<double> length, const neighbors::PeriodicBox<Dim>& box);

    /// True when some material averages its damage.
    bool active() const noexcept { return largest_ > 0.0; }
    /// True when material m averages its damage.
    bool averages(std::int32_t m) const noexcept { return length_[static_cast<std::size_t>(m)] > 0.0; }

    /// For every solid particle of a non-local material that is not an image, `averaged[i]` = the
    /// average above of `local` (per particle, this step's local increments dD_j); others are left.
    void average(const particles::SphParticles<Dim>& ps, const double* local, double* averaged);

private:
    /// The members (solid particles of non-local materials, images included) and their pairs afresh.
    void rebuild(const particles::SphParticles<Dim>& ps);
    /// After removals only (`kept`: SphParticles::kept_since): the members' new indices, -1 for those
    /// removed; the pairs stay.
    void compact(const std::vector<Index>& kept, std::uint64_t generation);
    /// After a reordering: the members' new indices found by id (-1 for those gone); false when a
    /// particle has become a member since the build.
    bool relocate(const particles::SphParticles<Dim>& ps);
    bool is_member(const particles::SphParticles<Dim>& ps, Index i) const;
    bool moved_past_skin(const particles::SphParticles<Dim>& ps) const;

    std::vector<double> length_;  ///< per material [m]
    neighbors::PeriodicBox<Dim> box_;
    double largest_ = 0.0, skin_ = 0.0;
    /// Per slot (the members in ascending id at the build): its particle index now (-1: gone since).
    std::vector<Index> members_;
    std::vector<Index> source_slot_;  ///< per slot: the slot whose increment it carries (an image's source)
    std::unordered_map<domain::ParticleId, Index> slot_of_id_;
    std::vector<core::Vec<Dim>> built_at_;  ///< members' positions at the build
    std::vector<double> radius_;            ///< per member: its material's length
    neighbors::CrossPairList<Dim> pairs_;   ///< between slots, within length + skin
    /// Per slot, this call: position, volume m / rho, increment and material (-1: gone).
    std::vector<core::Vec<Dim>> at_;
    std::vector<double> volume_, increment_;
    std::vector<std::int32_t> material_;
    std::uint64_t generation_ = ~std::uint64_t{0};
};

extern template class NonlocalDamage<2>;
extern template class NonlocalDamage<3>;

}  // namespace grit::sph
