// Fragments of fractured rock: fractured particles clustered as labels, anchored by intact neighbours.
#include "grit/analysis/fragments.hpp"

#include <algorithm>
#include <cstdint>

#include "grit/analysis/clusters.hpp"
#include "grit/parallel/parallel.hpp"

namespace grit::analysis {

namespace {
bool fractured(std::int32_t phase, double damage) {
    return phase == static_cast<std::int32_t>(Phase::solid) && damage >= 1.0;
}
}  // namespace

template <int Dim>
std::vector<domain::ParticleId> fragment_labels(const particles::SphParticles<Dim>& ps, const double* damage,
                                                double link, Index owned, const domain::ParticleId* ghost_labels,
                                                const neighbors::PeriodicBox<Dim>& box) {
    const std::int32_t* phase = ps.phase();
    std::vector<std::uint8_t> member(static_cast<std::size_t>(ps.size()), 0);
    for (Index i = 0; i < ps.size(); ++i) member[static_cast<std::size_t>(i)] = fractured(phase[i], damage[i]);
    return cluster_labels(ps, member, link, owned, ghost_labels, box);
}

template <int Dim>
std::vector<domain::ParticleId> anchored_fragments(const particles::SphParticles<Dim>& ps, const double* damage,
                                                   const std::vector<domain::ParticleId>& labels,
                                                   const neighbors::NeighborList<Dim>& list, double link, Index owned,
                                                   const neighbors::PeriodicBox<Dim>& box) {
    const std::int32_t* phase = ps.phase();
    const auto* x = ps.position();
    const Index* nb = list.indices();
    const double link2 = link * link;
    const auto solid = static_cast<std::int32_t>(Phase::solid);
    std::vector<std::uint8_t> touches(static_cast<std::size_t>(owned), 0);
    parallel::for_each(owned, [&](Index i) {
        if (!fractured(phase[i], damage[i])) return;
        for (Index k = list.begin(i); k < list.end(i); ++k) {
            const Index j = nb[k];
            if (phase[j] == solid && damage[j] < 1.0 && core::norm2(box.nearest_image(x[j] - x[i])) <= link2) {
                touches[static_cast<std::size_t>(i)] = 1;
                return;
            }
        }
    });
    std::vector<domain::ParticleId> out;
    for (Index i = 0; i < owned; ++i)
        if (touches[static_cast<std::size_t>(i)]) out.push_back(labels[static_cast<std::size_t>(i)]);
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
}

template std::vector<domain::ParticleId> fragment_labels<2>(const particles::SphParticles<2>&, const double*, double,
                                                            Index, const domain::ParticleId*,
                                                            const neighbors::PeriodicBox<2>&);
template std::vector<domain::ParticleId> fragment_labels<3>(const particles::SphParticles<3>&, const double*, double,
                                                            Index, const domain::ParticleId*,
                                                            const neighbors::PeriodicBox<3>&);
template std::vector<domain::ParticleId> anchored_fragments<2>(const particles::SphParticles<2>&, const double*,
                                                               const std::vector<domain::ParticleId>&,
                                                               const neighbors::NeighborList<2>&, double, Index,
                                                               const neighbors::PeriodicBox<2>&);
template std::vector<domain::ParticleId> anchored_fragments<3>(const particles::SphParticles<3>&, const double*,
                                                               const std::vector<domain::ParticleId>&,
                                                               const neighbors::NeighborList<3>&, double, Index,
                                                               const neighbors::PeriodicBox<3>&);

}  // namespace grit::analysis
