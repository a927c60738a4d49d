// The jet builder: completes a case that has [jet] (and [abrasive]) into the inlet, outlets, clamps,
// crater analysis and domain of the first seed paper's AWJ set-up (Fig. 9), and converts between the
// abrasive mass flow rate and the column length y_dis (eqs. 54-55).
#pragma once

#include "grit/io/case_spec.hpp"

namespace grit::io {

/// Eq. (52): the jet velocity a pump pressure P gives, v = kappa sqrt(2 P / rho) [m/s]; with
/// kappa = 0.7 and rho = 1000 kg/m^3 this is eq. (53), v = 31.3 sqrt(P [MPa]).
double jet_velocity_from_pressure(double pressure, double volume_efficiency, double density);

/// V_a of eqs. (54)-(55) for a grain of diameter d in a jet of diameter d_jet [m^3]: the sphere in 3D;
/// in 2D the grain's disc across a slab as thick as the jet, pi d^2 / 4 d_jet (the paper's 2D model is
/// a slab of the jet; docs/theory.md, eq. 55).
double abrasive_volume(int dimension, double diameter, double jet_diameter);

/// Eq. (55): M = rho_dem v_jet V_a / y_dis [kg/s].
double abrasive_mass_flow_rate(double grain_density, double jet_velocity, double volume, double spacing);

/// Completes `c` (which has [jet]): adds the jet's inlet, the side outlets and clamps unless the case
/// gives its own, the crater analysis in 2D unless [crater] is given, the domain without [domain], and
/// the abrasive feed's y_dis, M and zeta. Throws core::InputError naming the key for a geometry that
/// cannot work (a nozzle inside the specimen, a grain larger than the jet, grains packed closer than
/// their diameter).
void build_jet(CaseSpec& c);

}  // namespace grit::io
