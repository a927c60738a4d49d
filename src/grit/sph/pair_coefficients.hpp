// Per-material coefficients the SPH pair sums read, indexed by a particle's material.
#pragma once

namespace grit::sph {

struct PairCoefficients {
    double sound_speed;          ///< c0 [m/s]
    double reference_density;    ///< rho0 [kg/m^3]
    double alpha;                ///< artificial viscosity alpha_pi [-]
    double beta;                 ///< artificial viscosity beta_pi [-]
    double kinematic_viscosity;  ///< nu = mu_f / rho0 [m^2/s]
};

}  // namespace grit::sph
