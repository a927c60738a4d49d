// Wall pressure extrapolation (Adami et al. 2012), a gather loop over wall particles.
#include "grit/boundary/wall_pressure.hpp"

#include <cmath>

#include "grit/parallel/parallel.hpp"

namespace grit::boundary {

template <int Dim>
void update_wall_pressure(particles::SphParticles<Dim>& ps, const neighbors::NeighborList<Dim>& nl,
                          const sph::Kernel<Dim>& kernel, const core::Vec<Dim>& gravity,
                          const std::vector<material::Material>& materials, const neighbors::PeriodicBox<Dim>& box) {
    using Vec = core::Vec<Dim>;
    const Vec* x = ps.position();
    double* rho = ps.density();
    double* p = ps.pressure();
    const std::int32_t* phase = ps.phase();
    const std::int32_t* mat = ps.material();
    const Index* nbr = nl.indices();
    const auto wall = static_cast<std::int32_t>(Phase::wall);
    const auto fluid = static_cast<std::int32_t>(Phase::fluid);

    std::visit(
        [&](const auto& k) {
            neighbors::with_image(box, [&](const auto image) {
                const double support2 = k.support() * k.support();
                parallel::for_each(ps.size(), [&](Index w) {
                    if (phase[w] != wall) return;
                    double sum_w = 0.0, sum_pw = 0.0, sum_rho_gx_w = 0.0;
                    for (Index n = nl.begin(w); n < nl.end(w); ++n) {
                        const Index f = nbr[n];
                        if (phase[f] != fluid) continue;
                        const Vec xwf = image(x[w] - x[f]);
                        const double r2 = core::norm2(xwf);
                        if (r2 >= support2) continue;
                        const double wgt = k.value(std::sqrt(r2));
                        sum_w += wgt;
                        sum_pw += p[f] * wgt;
                        sum_rho_gx_w += rho[f] * core::dot(gravity, xwf) * wgt;
                    }
                    const double pw = sum_w > 0.0 ? (sum_pw + sum_rho_gx_w) / sum_w : 0.0;
                    p[w] = pw > 0.0 ? pw : 0.0;
                });
            });
        },
        kernel);
    for (std::size_t m = 0; m < materials.size(); ++m) {
        const auto id = static_cast<std::int32_t>(m);
        std::visit(
            [&](const auto& eos) {
                parallel::for_each(ps.size(), [&](Index w) {
                    if (phase[w] == wall && mat[w] == id) rho[w] = eos.density(p[w]);
                });
            },
            materials[m].eos);
    }
}

template void update_wall_pressure<2>(particles::SphParticles<2>&, const neighbors::NeighborList<2>&,
                                      const sph::Kernel<2>&, const core::Vec<2>&,
                                      const std::vector<material::Material>&, const neighbors::PeriodicBox<2>&);
template void update_wall_pressure<3>(particles::SphParticles<3>&, const neighbors::NeighborList<3>&,
                                      const sph::Kernel<3>&, const core::Vec<3>&,
                                      const std::vector<material::Material>&, const neighbors::PeriodicBox<3>&);

}  // namespace grit::boundary
