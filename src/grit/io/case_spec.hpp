// A case as read from its TOML file: plain data, validated, in SI units. sim/ builds a run from it.
#pragma once

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <memory>
#include <string>
#include <vector>

#include "grit/dem/grain_material.hpp"
#include "grit/dem/size_distribution.hpp"
#include "grit/material/material.hpp"
#include "grit/mesh/triangle_mesh.hpp"
#include "grit/wear/wear_models.hpp"

namespace grit::io {

/// A geometry primitive. Vectors have `dimension` components.
struct ShapeSpec {
    std::string kind;  ///< "box", "disc" (a sphere in 3D), "cylinder" (3D) or "tank" (walls around an inner box)
    std::vector<double> min, max;   ///< box, tank: corners [m]
    std::vector<double> center;     ///< disc: centre [m]
    double radius = 0.0;            ///< disc, cylinder: radius [m]
    double length = 0.0;            ///< cylinder: length along its axis [m]
    int axis = 0;                   ///< cylinder: 0 = x, 1 = y, 2 = z
    int layers = 0;                 ///< tank: wall thickness in particle layers
    std::vector<std::string> open;  ///< tank: sides left without wall ("top", "bottom", "left", ...)
    /// mesh (3D walls): the STL surface, placed; `layers` of particles on its `side`: "outside" (a closed
    /// container: the fluid is inside), "inside" (a closed obstacle), "front" or "back" (any mesh: the side
    /// its facet normals point to, or away from; a plate the fluid meets on the other side).
    std::shared_ptr<const mesh::TriangleMesh> mesh;
    std::string side = "outside";
    /// mesh, front/back: the surface is thinner than the kernel somewhere (a splitter edge, a sheet that
    /// folds back): wall particles are laid behind each facet even where that is in front of another
    /// part of the sheet, and particles on the two sides do not interact (their wall normals point away
    /// from each other; second seed paper, sec. 3.2).
    bool thin = false;
    /// mesh on a symmetry plane, the mesh symmetric about it: the particles at x >= 0 only, on a lattice
    /// aligned on x = 0 (their mirror images stand for the others).
    bool half = false;
};

/// A block of particles: fluid, solid or wall.
struct BlockSpec {
    std::string key;  ///< where it was defined, for messages: "fluid[0]"
    ShapeSpec shape;
    int material = 0;  ///< index into CaseSpec::materials
    std::vector<double> velocity;
    bool hydrostatic = false;  ///< fluid: start with the hydrostatic pressure of its own column
    /// solid: "uniform" (velocity), or "cantilever_mode" — the first bending mode of a cantilever
    /// clamped at x = mode_origin with free length mode_length, transverse (y) velocity mode_tip_velocity
    /// at the tip (Gray, Monaghan & Swift 2001), or "longitudinal_wave" — a velocity along the wave's axis
    /// wave_axis (0: x) of wave_amplitude sin(2 pi x / wave_length), x the coordinate along that axis.
    std::string velocity_profile = "uniform";
    double mode_origin = 0.0, mode_length = 0.0, mode_tip_velocity = 0.0;
    int wave_axis = 0;
    double wave_length = 0.0, wave_amplitude = 0.0;
};

/// A jet inlet: emits layers of particles through a segment (2D) or disc (3D).
struct InletSpec {
    std::string key;
    std::vector<double> position;   ///< centre of the inlet section [m]
    std::vector<double> direction;  ///< jet direction (normalised when read)
    double diameter = 0.0;          ///< [m]
    double velocity = 0.0;          ///< [m/s]
    int material = 0;
    double start = 0.0, stop = 1e300;  ///< emission window [s]
    /// Velocity of the nozzle itself (a traversing jet) [m/s]; the section is at position + motion t,
    /// and the emitted fluid moves at velocity direction + motion. Empty: at rest.
    std::vector<double> motion;
    /// On a symmetry plane, a section centred on it: only its x > 0 slots emit (their mirror images
    /// stand for the others).
    bool half = false;
};

/// [jet]: an abrasive water jet as the machine is set up (first seed paper section 4, Fig. 9). The
/// builder (io/jet_builder.hpp) turns it into an inlet aimed at the specimen (the first [[solid]], a
/// box), side outlets, side clamps, a crater analysis (2D) and, without [domain], the domain.
/// The vertical axis is the last one (y in 2D, z in 3D); the nozzle traverses along +x.
struct JetSpec {
    double diameter = 0.0;            ///< jet.diameter [m]
    double velocity = 0.0;            ///< jet.velocity [m/s], or from jet.pressure by eq. (52)
    double pressure = 0.0;            ///< jet.pressure [Pa] (0: velocity given)
    double volume_efficiency = 0.7;   ///< jet.volume_efficiency, kappa of eq. (52)
    double angle = 90.0;              ///< jet.angle [deg]: between the jet and the surface (90: normal)
    double standoff = 0.0;            ///< jet.standoff [m]: nozzle to target along the jet axis
    std::vector<double> target;       ///< jet.target [m]: the point aimed at (default: top centre of the specimen)
    double traverse_speed = 0.0;      ///< jet.traverse_speed [m/s]: the nozzle moves along +x
    double start = 0.0, stop = 1e300; ///< jet.start, jet.stop [s]
    int material = 0;                 ///< jet.material (index into CaseSpec::materials)
    bool side_outlets = true;         ///< jet.side_outlets: outlets at both sides (unless [[outlet]] given)
    bool clamp_sides = true;          ///< jet.clamp_sides: the specimen clamped at its sides (unless [[clamp]] given)
    bool clamp_bottom = false;        ///< jet.clamp_bottom: and at its bottom (a thick block: no spall from a free face)
    bool derive_domain = false;       ///< no [domain]: the builder sets it around the specimen and nozzle
    /// jet.symmetric: the jet's axis (x = 0) is a symmetry plane; the builder lays the x >= 0 half (2D,
    /// normal incidence, no traverse) and domain.symmetry is on.
    bool symmetric = false;
    double side_width = 0.0;          ///< width of the side outlets [m] (set by the builder)
    /// The crater the specimen implies (set by the builder): what the crater analysis measures when the
    /// case has no [crater] (modules/crater_table).
    struct Crater {
        double surface = 0.0;             ///< the specimen's top [m]
        double x_min = 0.0, x_max = 0.0;  ///< between the side outlets [m]
        double y_min = 0.0, y_max = 0.0;  ///< 3D: the same across the traverse [m]
    };
    std::optional<Crater> crater;
};

/// [abrasive]: grains fed into the jet, one at a random place in each liquid column of length
/// `spacing` (y_dis), entering at the jet's velocity (first seed paper Fig. 9, eqs. 54-55).
struct AbrasiveSpec {
    bool enabled = false;
    int material = 0;                               ///< abrasive.material (index into grain_materials)
    dem::SizeDistribution size = dem::FixedSize{};  ///< abrasive.diameter or abrasive.size
    double spacing = 0.0;          ///< abrasive.spacing, y_dis [m] (given, or from the mass flow rate)
    double mass_flow_rate = 0.0;   ///< abrasive.mass_flow_rate, M of eq. (55) [kg/s] (given, or from y_dis)
    double volume_fraction = 0.0;  ///< zeta of eq. (54) [-]
    /// The liquid column that holds one fed grain [m]: y_dis, or 2 y_dis on the half jet of a symmetry
    /// plane (each grain has its mirror twin in the other half).
    double feed_spacing = 0.0;
    /// The half jet of a symmetry plane at x = 0 (2D): grain centres across [0, d_jet/2 - d/2] from the
    /// plane, as the whole jet's |x|; a grain closer to the plane than its radius straddles it.
    bool half_jet = false;
    std::string rate_key = "abrasive.spacing";  ///< the key that set the feed (for messages)
    std::uint64_t seed = 1;        ///< abrasive.seed
    double start = 0.0, stop = 1e300;  ///< abrasive.start, abrasive.stop [s] (default: the jet's)
    int inlet = 0;                 ///< the jet's inlet in CaseSpec::inlets
    /// How far upstream of the nozzle section a grain joins the run [m] (set by the builder): beyond
    /// the coupling's reach of the water already emitted, so the grain never appears inside water (the
    /// porosity there would drop at once, a pressure jump); the water emitted around it is then new to
    /// the coupling and takes the porosity into its mass (eq. 21).
    double lead = 0.0;
};

/// An outlet (a box that removes the fluid particles entering it and books their mass), or a clamp
/// (a box whose solid particles move at a prescribed velocity, at rest by default).
struct OutletSpec {
    std::string key;
    std::vector<double> min, max;
    std::vector<double> velocity;  ///< clamps only [m/s]
};

/// A block of DEM grains: one grain at `position`, a lattice, or random non-overlapping grains in a box.
struct GrainBlockSpec {
    std::string key;
    int material = 0;                    ///< index into CaseSpec::grain_materials
    std::string arrangement = "single";  ///< "single", "lattice" or "random"
    std::vector<double> position;        ///< single: centre [m]
    std::vector<double> min, max;        ///< lattice, random: the box filled [m]
    double spacing = 0.0;                ///< lattice: spacing [m]
    double jitter = 0.0;                 ///< lattice: random shift per axis up to this [m]
    int count = 0;                       ///< random: number of grains
    dem::SizeDistribution size = dem::FixedSize{};  ///< diameters
    std::uint64_t seed = 1;              ///< of the size and position draws
    std::vector<double> velocity;        ///< [m/s]
    bool fixed = false;                  ///< grains held in place (a packed bed): never moved
};

/// A stream of grains poured in during the run ([[grain_feed]], LIGGGHTS' insert/stream).
struct GrainFeedSpec {
    std::string key;
    int material = 0;                               ///< index into CaseSpec::grain_materials
    dem::SizeDistribution size = dem::FixedSize{};  ///< diameters
    std::vector<double> min, max;                   ///< the box the centres are placed in [m]
    std::vector<double> velocity;                   ///< [m/s]
    double mass_flow_rate = 0.0;                    ///< [kg/s] (kg/s per metre in 2D)
    double interval = 0.0;                          ///< between insertions [s]
    double start = 0.0, stop = 1e300;               ///< [s]
    long count = 0;                                 ///< the most grains inserted (0: no limit)
    std::uint64_t seed = 1;
};

/// A plane wall for grains: a point on it and the normal towards the grains.
struct GrainWallSpec {
    std::string key;
    std::string name;  ///< target name in impacts.csv
    std::vector<double> point, normal;
    int material = 0;  ///< index into CaseSpec::grain_materials
};

/// A triangle-mesh wall ([[mesh]], 3D): read, checked and placed by the case reader.
struct MeshSpec {
    std::string key;
    std::string name;                  ///< target name in impacts.csv, wear_mass_<name> in series.csv
    std::filesystem::path file;        ///< the STL file (relative paths from the case file's folder)
    std::shared_ptr<const mesh::TriangleMesh> mesh;
    int material = 0;                  ///< contact material: index into CaseSpec::grain_materials
    wear::WearModel wear_model = wear::WearModel::none;
    wear::WearMaterial wear_material;  ///< the wall's wear material (wear_material, [wear_materials.<name>])
    std::vector<double> velocity, angular_velocity, centre;  ///< prescribed motion [m/s], [rad/s], [m]
};

/// [dem]: grain contact law and coupling settings.
struct DemSpec {
    std::string contact_law = "hertz";  ///< "linear" (first paper eqs. 2-11) or "hertz" (second paper)
    double skin = -1.0;                 ///< Verlet skin [m]; < 0: 0.2 x the largest diameter
    double overlap_coefficient = 0.0;   ///< chi of eq. (13)
    double solid_friction = -1.0;       ///< mu grain-SPH solid/wall; < 0: the grain material's
    /// Grains touch SPH wall particles (penalty contact); false where [[mesh]] walls stand for them.
    bool wall_particle_contact = true;
    /// Grains touch each other; false lets them pass through one another (a probe of what their
    /// collisions do, Figs. 14 and 21).
    bool grain_grain_contact = true;
};

/// [coupling]: the unresolved fluid-grain coupling (first paper section 2.5), on in every case with
/// grains and a fluid.
struct CouplingSpec {
    bool enabled = true;               ///< coupling.enabled
    double radius = 2.0;               ///< coupling.radius: R_c in grain diameters (R_c = 2 h_c)
    std::string drag = "gidaspow";     ///< coupling.drag: "gidaspow", "di_felice", "single_particle", "single_particle_as_printed"
    double min_porosity = 0.2;         ///< coupling.min_porosity: floor of the fluid particles' eps
};

/// The base of a spec a module reads from its own case table (io/case_tables.hpp): the module's own type
/// derives from it, and the module finds it with CaseSpec::module_spec<T>(key).
struct ModuleSpec {
    virtual ~ModuleSpec() = default;
};

struct CaseSpec {
    std::filesystem::path source;  ///< the case file
    std::string text;              ///< its text as read (a checkpoint keeps it; summary.json its digest)
    std::vector<std::string> overrides;  ///< the --set assignments applied to it, in order
    std::string name;              ///< output base name
    std::string title;
    int dimension = 2;

    double end_time = 0.0;         ///< time.end [s]
    double cfl = 0.2;              ///< time.cfl, C_F of eq. (51)
    double max_time_step = 1e300;  ///< time.max_step [s]

    double output_interval = 0.0;  ///< output.interval [s]
    bool write_snapshots = true;   ///< output.snapshots
    /// output.checkpoint_interval [s]: checkpoints during the run (0: only at the end and on SIGINT/SIGTERM)
    double checkpoint_interval = 0.0;
    int checkpoint_keep = 2;       ///< output.checkpoint_keep: the latest checkpoints kept in checkpoints/
    /// output.checkpoint_wall_interval [s of wall time]: a checkpoint at least this often, so a run killed
    /// without warning (SIGKILL, a node lost) loses at most this much work; 0: none on wall time.
    double checkpoint_wall_interval = 1800.0;

    double particle_spacing = 0.0;       ///< numerics.particle_spacing [m]
    double smoothing_ratio = 1.25;       ///< numerics.smoothing_ratio h/dx (paper: 1.25)
    std::string kernel = "cubic_spline"; ///< numerics.kernel
    double density_diffusion = 0.1;      ///< numerics.density_diffusion (delta; 0 = off)
    double neighbor_skin = 0.2;          ///< numerics.neighbor_skin, in units of h
    int check_interval = 50;             ///< numerics.check_interval [steps]
    double max_speed = 0.0;              ///< numerics.max_speed [m/s]: faster is a blow-up (0 = auto)
    double artificial_stress = 0.3;      ///< numerics.artificial_stress: epsilon of Gray et al. (2001)
    /// numerics.kernel_correction: the fluid sums use the corrected kernel gradient L_a grad W_ab of
    /// the second seed paper eq. (8) (Bonet & Lok 1999), exact for linear fields whatever the disorder.
    bool kernel_correction = false;  ///< default true under fluid.solver = "isph"
    /// numerics.shepard_interval [steps]: every so many steps the fluid density is reset to its Shepard
    /// average sum m W / sum (m/rho) W (0: never).
    int shepard_interval = 0;
    /// numerics.max_particles: a case whose estimated SPH particles plus grains exceed it is refused
    /// before anything is allocated (20 million: ~10 GB in 2D, ~14 GB in 3D; see io/particle_budget.cpp).
    Index max_particles = 20'000'000;

    std::vector<double> gravity;  ///< physics.gravity [m/s^2]

    /// fluid.solver: "wcsph" (weakly compressible, pressure from the equation of state) or "isph"
    /// (incompressible, pressure from a Poisson equation each step; second seed paper eq. 6).
    std::string fluid_solver = "wcsph";
    std::string fluid_solver_key = "fluid.solver";  ///< where it was set (for messages)
    /// The incompressible solver's settings ([isph]).
    struct IsphSpec {
        double tolerance = 1e-6;       ///< isph.tolerance: relative residual |b - Ax| / |b| of the solve
        int max_iterations = 2000;     ///< isph.max_iterations: more is a failed solve (an error)
        /// isph.free_surface_divergence: a fluid particle whose div r = -sum V_b x_ab . grad W_ab is below
        /// this is on the free surface (p = 0 there); 0: 1.5 in 2D, 2.4 in 3D (Lee et al. 2008)
        double free_surface_divergence = 0.0;
        /// isph.density_relaxation: gamma of the density-invariance term gamma (rho0 - rho)/(rho tau^2)
        /// added to the divergence source (Asai et al. 2012); 0: the divergence-free projection alone
        double density_relaxation = 0.1;
        /// isph.shifting: A of the particle shift D = A h |v| dt (Lind et al. 2012); 0: no shifting
        double shifting = 2.0;
    } isph;

    std::vector<double> domain_min, domain_max;  ///< domain.min, domain.max [m]
    bool remove_leaving = false;                 ///< domain.on_exit = "remove" (else "error")
    /// domain.periodic (or its older spelling dem.periodic): per axis, whether the axis wraps between
    /// domain.min and domain.max, for the SPH particles and the grains alike.
    std::vector<bool> periodic;
    std::string periodic_key = "domain.periodic";  ///< the key that set `periodic` (for messages)
    bool any_periodic() const {
        for (bool p : periodic)
            if (p) return true;
        return false;
    }

    std::vector<material::Material> materials;  ///< the materials the case uses
    std::vector<BlockSpec> fluids;
    std::vector<BlockSpec> solids;
    std::vector<BlockSpec> walls;
    std::vector<OutletSpec> clamps;  ///< boxes: solid particles inside at the start move at the clamp's velocity
    std::vector<InletSpec> inlets;
    std::vector<OutletSpec> outlets;

    /// domain.symmetry = ["x"] (or jet.symmetric): the plane x = 0 is a symmetry plane; only x >= 0 is
    /// laid and run (modules/symmetry_plane).
    bool symmetry_plane = false;
    std::string symmetry_key = "domain.symmetry";  ///< the key that set it (for messages)
    std::vector<dem::GrainMaterial> grain_materials;  ///< the grain (and grain-wall) materials used
    std::vector<GrainBlockSpec> grains;
    std::vector<GrainWallSpec> grain_walls;
    std::vector<MeshSpec> meshes;
    std::vector<GrainFeedSpec> grain_feeds;
    bool has_jet = false;  ///< [jet] given
    JetSpec jet;
    AbrasiveSpec abrasive;
    DemSpec dem;
    CouplingSpec coupling;
    /// What the modules that read their own case table (io/case_tables.hpp) read, by the table's key.
    std::map<std::string, std::shared_ptr<const ModuleSpec>> module_specs;

    /// The spec read from table `key`, as the module's type T; null when the case has no such table.
    template <class T>
    const T* module_spec(const std::string& key) const {
        const auto it = module_specs.find(key);
        return it == module_specs.end() ? nullptr : dynamic_cast<const T*>(it->second.get());
    }
    bool has_sph() const { return !fluids.empty() || !solids.empty() || !inlets.empty() || !walls.empty(); }
    bool has_thin_walls() const {
        return std::any_of(walls.begin(), walls.end(), [](const BlockSpec& w) { return w.shape.thin; });
    }
    /// Grains at the start ([[grains]]) or fed during the run ([abrasive], [[grain_feed]]).
    bool has_grains() const { return !grains.empty() || abrasive.enabled || !grain_feeds.empty(); }
    /// The material of the first grains: the first [[grains]] block's, else the abrasive's.
    int first_grain_material() const {
        return !grains.empty() ? grains.front().material : !grain_feeds.empty() ? grain_feeds.front().material : abrasive.material;
    }
};

}  // namespace grit::io
