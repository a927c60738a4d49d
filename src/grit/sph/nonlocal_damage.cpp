// Non-local damage: the average of the local increments of eq. (36) over a material's damage length.
#include "grit/sph/nonlocal_damage.hpp"

#include <algorithm>
#include <unordered_map>
#include <utility>

#include "grit/core/types.hpp"
#include "grit/parallel/parallel.hpp"

namespace grit::sph {

namespace {
/// The skin of the pair list, as a fraction of the largest damage length: the list is rebuilt when a
/// member has moved half of it.
constexpr double skin_fraction = 0.25;
}  // namespace

template <int Dim>
NonlocalDamage<Dim>::NonlocalDamage(std::vector<double> length, const neighbors::PeriodicBox<Dim>& box)
    : length_(std::move(length)), box_(box) {
    for (const double l : length_) largest_ = std::max(largest_, l);
    skin_ = skin_fraction * largest_;
}

template <int Dim>
bool NonlocalDamage<Dim>::moved_past_skin(const particles::SphParticles<Dim>& ps) const {
    const auto* x = ps.position();
    const double limit2 = 0.25 * skin_ * skin_;
    const auto n = static_cast<Index>(members_.size());
    return parallel::max(n, 0.0, [&](Index a) {
               const auto k = static_cast<std::size_t>(a);
               return members_[k] < 0 ? 0.0 : core::norm2(box_.nearest_image(x[members_[k]] - built_at_[k]));
           }) > limit2;
}

template <int Dim>
bool NonlocalDamage<Dim>::is_member(const particles::SphParticles<Dim>& ps, Index i) const {
    return ps.phase()[i] == static_cast<std::int32_t>(Phase::solid) &&
           length_[static_cast<std::size_t>(ps.material()[i])] > 0.0;
}

template <int Dim>
void NonlocalDamage<Dim>::rebuild(const particles::SphParticles<Dim>& ps) {
    // Slots in ascending id: the rows of the pair list, and so the sums, follow the ids, which neither a
    // reordering of the particles nor a restart changes.
    const domain::ParticleId* id = ps.id();
    members_.clear();
    for (Index i = 0; i < ps.size(); ++i)
        if (is_member(ps, i)) members_.push_back(i);
    std::sort(members_.begin(), members_.end(), [id](Index a, Index b) { return id[a] < id[b]; });
    const auto n = static_cast<Index>(members_.size());
    slot_of_id_.clear();
    slot_of_id_.reserve(members_.size());
    for (std::size_t k = 0; k < members_.size(); ++k) slot_of_id_.emplace(id[members_[k]], static_cast<Index>(k));
    source_slot_.resize(members_.size());
    built_at_.resize(members_.size());
    radius_.resize(members_.size());
    const auto* x = ps.position();
    for (std::size_t k = 0; k < members_.size(); ++k) {
        const Index i = members_[k];
        source_slot_[k] = static_cast<Index>(k);
        if (ps.is_image(i)) {
            const auto it = slot_of_id_.find(particles::SphParticles<Dim>::image_source(id[i]));
            if (it != slot_of_id_.end()) source_slot_[k] = it->second;
        }
        built_at_[k] = x[i];
        radius_[k] = length_[static_cast<std::size_t>(ps.material()[i])];
    }
    pairs_.build(built_at_.data(), n, [](Index) { return true; }, built_at_.data(), radius_.data(), n, skin_, box_);
    generation_ = ps.generation();
}

template <int Dim>
void NonlocalDamage<Dim>::compact(const std::vector<Index>& kept, std::uint64_t generation) {
    // kept[i]: the index before the removals of the particle now at i (ascending).
    std::vector<Index> now(kept.empty() ? 0 : static_cast<std::size_t>(kept.back()) + 1, -1);
    for (std::size_t i = 0; i < kept.size(); ++i) now[static_cast<std::size_t>(kept[i])] = static_cast<Index>(i);
    for (Index& i : members_)
        if (i >= 0) i = static_cast<std::size_t>(i) < now.size() ? now[static_cast<std::size_t>(i)] : Index{-1};
    generation_ = generation;
}

template <int Dim>
bool NonlocalDamage<Dim>::relocate(const particles::SphParticles<Dim>& ps) {
    // The members found again by id after a reordering; a new member (a particle that became an image)
    // needs a new list.
    const domain::ParticleId* id = ps.id();
    std::fill(members_.begin(), members_.end(), Index{-1});
    for (Index i = 0; i < ps.size(); ++i) {
        if (!is_member(ps, i)) continue;
        const auto it = slot_of_id_.find(id[i]);
        if (it == slot_of_id_.end()) return false;
        members_[static_cast<std::size_t>(it->second)] = i;
    }
    generation_ = ps.generation();
    return true;
}

template <int Dim>
void NonlocalDamage<Dim>::average(const particles::SphParticles<Dim>& ps, const double* local, double* averaged) {
    if (!active()) return;
    if (generation_ != ps.generation()) {
        // Outlets and erosion remove particles nearly every step: the pairs of the members kept stay
        // (their order too), so the list is compacted, not rebuilt.
        const auto* kept = ps.kept_since(generation_);
        if (kept) compact(*kept, ps.generation());
        else if (!relocate(ps)) rebuild(ps);
    }
    if (moved_past_skin(ps)) rebuild(ps);
    // The members' positions, volumes, materials and increments in slot order (an image's increment is
    // its source's; a member gone has material -1): the pair loop reads them contiguously.
    const auto* x = ps.position();
    const double* m = ps.mass();
    const double* rho = ps.density();
    const std::int32_t* mat = ps.material();
    const auto n = static_cast<Index>(members_.size());
    at_.resize(members_.size());
    volume_.resize(members_.size());
    increment_.resize(members_.size());
    material_.resize(members_.size());
    parallel::for_each(n, [&](Index a) {
        const auto k = static_cast<std::size_t>(a);
        const Index i = members_[k];
        if (i < 0) {
            material_[k] = -1;
            return;
        }
        const Index source = members_[static_cast<std::size_t>(source_slot_[k])];
        at_[k] = x[i];
        volume_[k] = m[i] / rho[i];
        increment_[k] = local[source >= 0 ? source : i];  // an image whose source left: it leaves next
        material_[k] = mat[i];
    });
    const Index* row = pairs_.indices();
    neighbors::with_image(box_, [&](const auto image) {
        parallel::for_each(n, [&](Index a) {
            const auto k = static_cast<std::size_t>(a);
            const Index i = members_[k];
            if (i < 0 || ps.is_image(i)) return;
            const double l2 = radius_[k] * radius_[k];
            const std::int32_t own = material_[k];
            double sum = 0.0, weight = 0.0;
            for (Index p = pairs_.begin(a); p < pairs_.end(a); ++p) {
                const auto b = static_cast<std::size_t>(row[p]);
                if (material_[b] != own) continue;
                const double r2 = core::norm2(image(at_[k] - at_[b]));
                if (r2 >= l2) continue;
                const double q = 1.0 - r2 / l2;
                const double w = q * q * volume_[b];
                sum += w * increment_[b];
                weight += w;
            }
            averaged[i] = weight > 0.0 ? sum / weight : local[i];
        });
    });
}

template class NonlocalDamage<2>;
template class NonlocalDamage<3>;

}  // namespace grit::sph
