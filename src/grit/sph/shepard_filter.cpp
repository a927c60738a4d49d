// Shepard density filter: one gather loop over fluid particles.
#include "grit/sph/shepard_filter.hpp"

#include <cmath>

#include "grit/parallel/parallel.hpp"

namespace grit::sph {

template <int Dim>
void shepard_density(const particles::SphParticles<Dim>& ps, const neighbors::NeighborList<Dim>& nl,
                     const Kernel<Dim>& kernel, const neighbors::PeriodicBox<Dim>& box, std::vector<double>& out) {
    using Vec = core::Vec<Dim>;
    const Index n = ps.size();
    out.resize(static_cast<std::size_t>(n));
    const Vec* x = ps.position();
    const double* rho = ps.density();
    const double* m = ps.mass();
    const std::int32_t* ph = ps.phase();
    const Index* nbr = nl.indices();
    const auto fluid = static_cast<std::int32_t>(Phase::fluid);
    double* result = out.data();
    std::visit(
        [&](const auto& k) {
            neighbors::with_image(box, [&](const auto image) {
                const double w0 = k.value(0.0);
                parallel::for_each(n, [&](Index a) {
                    if (ph[a] != fluid) {
                        result[a] = rho[a];
                        return;
                    }
                    double mass_sum = m[a] * w0,
                           volume_sum = m[a] / rho[a] * w0;  // the particle itself
                    for (Index e = nl.begin(a); e < nl.end(a); ++e) {
                        const Index b = nbr[e];
                        if (ph[b] != fluid) continue;
                        const double w = k.value(std::sqrt(core::norm2(image(x[a] - x[b]))));
                        mass_sum += m[b] * w;
                        volume_sum += m[b] / rho[b] * w;
                    }
                    result[a] = mass_sum / volume_sum;
                });
            });
        },
        kernel);
}

template void shepard_density<2>(const particles::SphParticles<2>&, const neighbors::NeighborList<2>&, const Kernel<2>&,
                                 const neighbors::PeriodicBox<2>&, std::vector<double>&);
template void shepard_density<3>(const particles::SphParticles<3>&, const neighbors::NeighborList<3>&, const Kernel<3>&,
                                 const neighbors::PeriodicBox<3>&, std::vector<double>&);

}  // namespace grit::sph
