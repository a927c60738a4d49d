// The unit of every output value (a series.csv column, a summary.json key), for summary.json's "units"
// map. In 2D the particles are a slab one metre thick, so masses, energies and volumes are per metre
// (kg/m, J/m, m^2); the DEM grains are spheres in both dimensions (kg, J).
#pragma once

#include <string>

namespace grit::sim {

/// The unit of the output value `name` in a run of dimension `dim` ("-" for a count or a pure number),
/// or empty for a name this table does not know (a probe: its module gives its own).
std::string output_unit(const std::string& name, int dim);

}  // namespace grit::sim
