// Pressure of fluid particles from their density: one loop per material, dispatched once on its EOS.
#pragma once

#include <vector>

#include "grit/material/material.hpp"
#include "grit/parallel/parallel.hpp"
#include "grit/particles/sph_particles.hpp"

namespace grit::sph {

/// p_a = max(EOS(rho_a, e_a), p_min) for every particle of the given phase; e_a = 0 without
/// `specific_energy` (barotropic). With `porosity` (fluid coupled to grains) the particle density is the
/// locally averaged rho_bar and the EOS takes rho = rho_bar / eps (first paper eq. 21).
template <int Dim>
void update_pressure(particles::SphParticles<Dim>& ps, const std::vector<material::Material>& materials,
                     Phase phase, const double* specific_energy = nullptr, const double* porosity = nullptr) {
    const double* rho = ps.density();
    double* p = ps.pressure();
    const std::int32_t* mat = ps.material();
    const std::int32_t* ph = ps.phase();
    const auto want = static_cast<std::int32_t>(phase);
    for (std::size_t m = 0; m < materials.size(); ++m) {
        const auto id = static_cast<std::int32_t>(m);
        const double floor = materials[m].min_pressure;
        std::visit(
            [&](const auto& eos) {
                parallel::for_each(ps.size(), [&](Index i) {
                    if (ph[i] != want || mat[i] != id) return;
                    const double r = porosity ? rho[i] / porosity[i] : rho[i];
                    const double value = eos.pressure(r, specific_energy ? specific_energy[i] : 0.0);
                    p[i] = value < floor ? floor : value;
                });
            },
            materials[m].eos);
    }
}

}  // namespace grit::sph
