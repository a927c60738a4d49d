#include "grit/sim/output_units.hpp"

#include <array>
#include <string_view>
#include <utility>

namespace grit::sim {

namespace {

// "per_length" where a 2D run's value is per metre of thickness: the 3D unit and the 2D one.
struct Unit {
    std::string_view name;
    std::string_view unit_3d, unit_2d;
};

constexpr std::array units = {
    // the run and the SPH particles
    Unit{"time", "s", "s"},
    Unit{"step", "-", "-"},
    Unit{"dt", "s", "s"},
    Unit{"kinetic_energy", "J", "J/m"},
    Unit{"mass_total", "kg", "kg/m"},
    Unit{"mass_in", "kg", "kg/m"},
    Unit{"mass_out", "kg", "kg/m"},
    Unit{"max_velocity", "m/s", "m/s"},
    Unit{"particles", "-", "-"},
    // solids
    Unit{"eroded_mass", "kg", "kg/m"},
    Unit{"first_removal_time", "s", "s"},
    Unit{"max_plastic_strain", "-", "-"},
    Unit{"internal_energy", "J", "J/m"},
    Unit{"damaged_area", "m^3", "m^2"},
    Unit{"crack_count", "-", "-"},
    Unit{"fluid_in_solid", "-", "-"},
    Unit{"fluid_near_thin_walls", "-", "-"},
    // the crater
    Unit{"crater_depth", "m", "m"},
    Unit{"crater_width", "m", "m"},
    Unit{"crater_rim_width", "m", "m"},
    Unit{"crater_lip_height", "m", "m"},
    Unit{"crater_area", "m^2", "m^2"},
    Unit{"crater_shape_factor", "-", "-"},
    Unit{"crater_length", "m", "m"},
    // grains (spheres in 2D too)
    Unit{"grains", "-", "-"},
    Unit{"grain_kinetic_energy", "J", "J"},
    Unit{"grains_out", "-", "-"},
    Unit{"grain_mass_out", "kg", "kg"},
    Unit{"impacts", "-", "-"},
    Unit{"grain_collisions", "-", "-"},
    Unit{"grains_injected", "-", "-"},
    Unit{"grains_fed", "-", "-"},
    Unit{"grains_not_placed", "-", "-"},
    Unit{"abrasive_mass_flow_rate", "kg/s", "kg/s"},
    Unit{"abrasive_spacing", "m", "m"},
    Unit{"abrasive_volume_fraction", "-", "-"},
    // the fluid-grain coupling
    Unit{"min_porosity", "-", "-"},
    Unit{"grain_porosity", "-", "-"},
    Unit{"bed_porosity", "-", "-"},
    Unit{"grain_speed", "m/s", "m/s"},
    Unit{"settling_velocity", "m/s", "m/s"},
    Unit{"terminal_velocity", "m/s", "m/s"},
    Unit{"contact_velocity", "m/s", "m/s"},
    Unit{"superficial_velocity", "m/s", "m/s"},
    Unit{"pressure_gradient", "Pa/m", "Pa/m"},
    Unit{"coupling_pairs", "-", "-"},
    // the incompressible solver
    Unit{"pressure_iterations", "-", "-"},
    Unit{"pressure_iterations_mean", "-", "-"},
    Unit{"pressure_residual", "-", "-"},
    Unit{"pressure_restarts", "-", "-"},
    Unit{"free_surface_particles", "-", "-"},
    // wear on mesh walls (wear_mass_<mesh> below)
    Unit{"wear_mass_total", "kg", "kg"},
};

}  // namespace

std::string output_unit(const std::string& name, int dim) {
    for (const auto& u : units)
        if (u.name == name) return std::string(dim == 2 ? u.unit_2d : u.unit_3d);
    if (name.rfind("wear_mass_", 0) == 0) return "kg";
    return "";
}

}  // namespace grit::sim
