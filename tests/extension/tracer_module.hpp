// A module that lives outside grit's sources, with its own case table: the proof that adding a module is new
// files plus registrations, without editing the reader (src/grit/io) or the run (src/grit/sim).
//
//   [tracer]
//   centre = [x, y]      # [m], inside the domain
//   radius = 0.05        # [m], at least a particle spacing
//   phase = "fluid"      # or "solid" (then the case needs a [[solid]])
//
// It counts the particles of that phase within `radius` of `centre` at the end of every step, and reports
// the count as the output value `tracer_particles` (series.csv, summary.json).
#pragma once

#include <string>
#include <vector>

#include "grit/io/case_spec.hpp"

namespace grit::testing {

struct TracerSpec : io::ModuleSpec {
    std::vector<double> centre;
    double radius = 0.0;
    int phase = 0;  ///< Phase::fluid or Phase::solid, as an integer code
};

/// Registers the [tracer] table and the tracer module (idempotent; the registrar in tracer_module.cpp calls it).
void register_tracer();

}  // namespace grit::testing
