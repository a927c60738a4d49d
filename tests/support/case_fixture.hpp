// Helpers for tests that run the cases in cases/ in memory (no files written).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "grit/analysis/diagnostics.hpp"
#include "grit/io/case_reader.hpp"
#include "grit/sim/simulation.hpp"

namespace grit::testing {

/// Reads cases/<relative> with overrides (reduced sizes for CI).
inline io::CaseSpec load_case(const std::string& relative, const std::vector<std::string>& overrides = {}) {
    return io::read_case(std::filesystem::path(GRIT_SOURCE_DIR) / "cases" / relative, overrides);
}

/// The hydrostatic case's water and numerics as a free disc (sphere) of radius 0.06 m centred at 0.1 m,
/// with no walls, probes or gravity, in a 2 m box: nothing outside acts on it (conservation tests).
template <int Dim>
io::CaseSpec free_blob_case(std::vector<std::string> overrides) {
    overrides.insert(overrides.begin(),
                     "physics.gravity=[" + std::string(Dim == 2 ? "0.0, 0.0" : "0.0, 0.0, 0.0") + "]");
    auto spec = load_case(Dim == 2 ? "hydrostatic_2d/case.toml" : "hydrostatic_3d/case.toml", overrides);
    spec.walls.clear();
    spec.probes.clear();
    spec.fluids[0].hydrostatic = false;
    spec.fluids[0].shape.kind = "disc";
    spec.fluids[0].shape.center.assign(Dim, 0.1);
    spec.fluids[0].shape.radius = 0.06;
    spec.domain_min.assign(Dim, -1.0);
    spec.domain_max.assign(Dim, 1.0);
    return spec;
}

inline sim::RunOptions in_memory() {
    sim::RunOptions o;
    o.write_files = false;
    o.quiet = true;
    return o;
}

}  // namespace grit::testing
