// Helpers for tests that run the cases in cases/ in memory (no files written).
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "grit/analysis/diagnostics.hpp"
#include "grit/io/case_reader.hpp"
#include "grit/mesh/stl_file.hpp"
#include "grit/modules/probes_table.hpp"
#include "grit/sim/simulation.hpp"

namespace grit::testing {

/// Whether the long forms of the validation tests run (GRIT_LONG_TESTS=1, `make test-long`); by default
/// (`make test`, CI) they run in a reduced form that still checks against the same reference.
inline bool long_tests() {
    const char* value = std::getenv("GRIT_LONG_TESTS");
    return value != nullptr && std::string(value) != "" && std::string(value) != "0";
}

/// The output value `name` (a series.csv column) of `sim` now: a test failure, and NaN, where it has none.
template <int Dim>
double output_value(const sim::Simulation<Dim>& sim, const std::string& name) {
    for (const auto& v : sim.output_values())
        if (v.name == name) return v.value;
    ADD_FAILURE() << "no output value '" << name << "'";
    return std::nan("");
}

/// Every case file under cases/, sorted (the tests that run them all: determinism, restart, units).
inline std::vector<std::filesystem::path> all_cases() {
    std::vector<std::filesystem::path> out;
    for (const auto& e : std::filesystem::recursive_directory_iterator(std::filesystem::path(GRIT_SOURCE_DIR) / "cases"))
        if (e.path().extension() == ".toml") out.push_back(e.path());
    std::sort(out.begin(), out.end());
    return out;
}

/// Reads cases/<relative> with overrides (reduced sizes for CI).
inline io::CaseSpec load_case(const std::string& relative, const std::vector<std::string>& overrides = {}) {
    return io::read_case(std::filesystem::path(GRIT_SOURCE_DIR) / "cases" / relative, overrides);
}

/// Reads a case given as TOML text (written to a temporary file named after `name`, then removed).
inline io::CaseSpec read_case_text(const std::string& text, const std::string& name) {
    const auto file = std::filesystem::temp_directory_path() / ("grit_test_" + name + ".toml");
    std::ofstream(file) << text;
    io::CaseSpec spec = io::read_case(file);
    std::filesystem::remove(file);
    return spec;
}

/// The hydrostatic case's water and numerics as a free disc (sphere) of radius 0.06 m centred at 0.1 m,
/// with no walls, probes or gravity, in a 2 m box: nothing outside acts on it (conservation tests).
template <int Dim>
io::CaseSpec free_blob_case(std::vector<std::string> overrides) {
    overrides.insert(overrides.begin(),
                     "physics.gravity=[" + std::string(Dim == 2 ? "0.0, 0.0" : "0.0, 0.0, 0.0") + "]");
    auto spec = load_case(Dim == 2 ? "hydrostatic_2d/case.toml" : "hydrostatic_3d/case.toml", overrides);
    spec.walls.clear();
    spec.module_specs.erase(modules::ProbesSpec::key);
    spec.fluids[0].hydrostatic = false;
    spec.fluids[0].shape.kind = "disc";
    spec.fluids[0].shape.center.assign(Dim, 0.1);
    spec.fluids[0].shape.radius = 0.06;
    spec.domain_min.assign(Dim, -1.0);
    spec.domain_max.assign(Dim, 1.0);
    return spec;
}

/// dem_settling_3d with three layers of grains and its floor plane replaced by the STL plate of
/// cases/wear_angle_sweep_3d, scaled to cover the periodic box, booking `wear_model` wear: a bed settling
/// on a mesh wall, with mesh contacts and their tangential histories throughout.
inline io::CaseSpec settling_on_mesh_case(const std::string& wear_model, std::vector<std::string> overrides = {}) {
    overrides.push_back("grains[0].max=[0.099, 0.099, 0.01]");
    auto spec = load_case("dem_settling_3d/case.toml", overrides);
    spec.grain_walls.clear();
    io::MeshSpec m;
    m.key = "mesh[0]";
    m.name = "floor";
    m.file = std::filesystem::path(GRIT_SOURCE_DIR) / "cases" / "wear_angle_sweep_3d" / "plate.stl";
    mesh::Placement place;
    place.scale = 5.0;  // [-0.1, 0.1]^2
    place.translate = core::Vec<3>{{0.05, 0.05, 0.0}};
    m.mesh = std::make_shared<const mesh::TriangleMesh>(
        mesh::TriangleMesh::from_facets(mesh::read_stl(m.file), place, m.file.string(), false));
    m.material = 0;
    m.wear_model = *wear::wear_model_named(wear_model);
    m.wear_material = *wear::find_wear_material("steel");
    m.velocity = m.angular_velocity = m.centre = {0.0, 0.0, 0.0};
    spec.meshes.push_back(std::move(m));
    return spec;
}

inline sim::RunOptions in_memory() {
    sim::RunOptions o;
    o.write_files = false;
    o.quiet = true;
    return o;
}

}  // namespace grit::testing
