// Crack analysis: damaged solid particles clustered (analysis/clusters).
#include "grit/analysis/cracks.hpp"

#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

#include "grit/analysis/clusters.hpp"
#include "grit/core/error.hpp"

namespace grit::analysis {

template <int Dim>
std::vector<domain::ParticleId> crack_labels(const particles::SphParticles<Dim>& ps, const double* damage,
                                             const CrackOptions& options, Index owned,
                                             const domain::ParticleId* ghost_labels,
                                             const neighbors::PeriodicBox<Dim>& box) {
    if (!(options.link_distance > 0.0))
        throw core::InputError("crack analysis: link_distance = " + std::to_string(options.link_distance) +
                               " must be > 0");
    for (int k = 0; k < Dim; ++k)
        if (box.periodic[k] && !(2.0 * options.link_distance < box.length(k)))
            throw core::InputError("crack analysis: link_distance = " + std::to_string(options.link_distance) +
                                   " m must be less than half the period along each periodic axis (" +
                                   std::to_string(box.length(k)) + " m): a particle would link to two images of one");
    // Damaged solid particles; a symmetry plane's images are not particles of their own.
    const auto* phase = ps.phase();
    const auto solid = static_cast<std::int32_t>(Phase::solid);
    std::vector<std::uint8_t> damaged(static_cast<std::size_t>(ps.size()), 0);
    for (Index i = 0; i < ps.size(); ++i)
        damaged[static_cast<std::size_t>(i)] =
            phase[i] == solid && damage[i] >= options.damage_threshold && !ps.is_image(i);
    return cluster_labels(ps, damaged, options.link_distance, owned, ghost_labels, box);
}

std::map<domain::ParticleId, Index> crack_sizes(const std::vector<domain::ParticleId>& labels, Index owned) {
    std::map<domain::ParticleId, Index> sizes;
    for (Index i = 0; i < owned; ++i)
        if (labels[static_cast<std::size_t>(i)] >= 0) ++sizes[labels[static_cast<std::size_t>(i)]];
    return sizes;
}

void count_cracks(const std::map<domain::ParticleId, Index>& sizes, const CrackOptions& options, CrackMeasures& out) {
    out.crack_count = 0;
    out.largest_crack = 0;
    for (const auto& [label, count] : sizes) {
        if (count >= options.min_particles) ++out.crack_count;
        out.largest_crack = std::max(out.largest_crack, count);
    }
}

template <int Dim>
CrackMeasures analyse_cracks(const particles::SphParticles<Dim>& ps, const double* damage, const CrackOptions& options,
                             const neighbors::PeriodicBox<Dim>& box) {
    CrackMeasures out;
    const auto* phase = ps.phase();
    const auto* m = ps.mass();
    const auto* rho = ps.density();
    const auto solid = static_cast<std::int32_t>(Phase::solid);
    const auto labels = crack_labels(ps, damage, options, ps.size(), nullptr, box);
    // The area is summed serially in index order (deterministic).
    for (Index i = 0; i < ps.size(); ++i) {
        if (phase[i] != solid || !(damage[i] >= options.damage_threshold) || ps.is_image(i)) continue;
        out.damaged_area += m[i] / rho[i];
        ++out.damaged_particles;
    }
    count_cracks(crack_sizes(labels, ps.size()), options, out);
    return out;
}

template std::vector<domain::ParticleId> crack_labels<2>(const particles::SphParticles<2>&, const double*,
                                                         const CrackOptions&, Index, const domain::ParticleId*,
                                                         const neighbors::PeriodicBox<2>&);
template std::vector<domain::ParticleId> crack_labels<3>(const particles::SphParticles<3>&, const double*,
                                                         const CrackOptions&, Index, const domain::ParticleId*,
                                                         const neighbors::PeriodicBox<3>&);
template CrackMeasures analyse_cracks<2>(const particles::SphParticles<2>&, const double*, const CrackOptions&,
                                         const neighbors::PeriodicBox<2>&);
template CrackMeasures analyse_cracks<3>(const particles::SphParticles<3>&, const double*, const CrackOptions&,
                                         const neighbors::PeriodicBox<3>&);

}  // namespace grit::analysis
