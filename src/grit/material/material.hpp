// A material: its equation of state and the per-material coefficients the SPH sums use.
#pragma once

#include <cmath>
#include <limits>
#include <string>

#include "grit/core/types.hpp"
#include "grit/material/equation_of_state.hpp"
#include "grit/material/solid_model.hpp"

namespace grit::material {

struct Material {
    std::string name;
    std::string description;  ///< one line, with the source of the parameters
    Phase phase = Phase::fluid;
    EquationOfState eos = TaitEos{1000.0, 1480.0, 7.0};
    double dynamic_viscosity = 0.0;  ///< mu_f [Pa s]; eq. (25) uses nu = mu_f / rho0
    double artificial_viscosity_alpha = 0.1;  ///< alpha_pi of eq. (26) [-]
    double artificial_viscosity_beta = 0.1;   ///< beta_pi of eq. (26) [-]
    /// Pressure floor [Pa]: the EOS result is limited to at least this value (cavitation in tension).
    double min_pressure = -std::numeric_limits<double>::infinity();

    // Solids (phase == Phase::solid) only.
    SolidModel solid_model = ElasticSolid{};  ///< constitutive model: strength and failure
    SolidProperties solid;                    ///< shear modulus and thermal data

    double reference_density() const { return material::reference_density(eos); }
    double sound_speed() const { return reference_sound_speed(eos); }
    /// The fastest wave [m/s]: c0 in a fluid, the longitudinal c_L = sqrt(c0^2 + 4G / (3 rho0)) in a solid
    /// (up to 1.4x c0 in rock), which the time step and the runaway check must follow (docs/theory.md).
    double signal_speed() const {
        if (phase != Phase::solid) return sound_speed();
        return std::sqrt(sound_speed() * sound_speed() + 4.0 * solid.shear_modulus / (3.0 * reference_density()));
    }
};

}  // namespace grit::material
