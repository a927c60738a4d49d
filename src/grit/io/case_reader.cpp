// The case reader: every key is read through a Section that remembers it, so that any key left unread
// at the end is reported as unknown (a typo must never be silently ignored). The key machinery is in
// case_section.hpp, materials in material_tables.hpp, shapes and meshes in shape_reader.hpp.
#include "grit/io/case_reader.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <functional>
#include <iterator>
#include <limits>
#include <optional>
#include <set>
#include <toml++/toml.h>

#include "grit/core/error.hpp"
#include "grit/core/types.hpp"
#include "grit/io/case_section.hpp"
#include "grit/io/case_tables.hpp"
#include "grit/io/jet_builder.hpp"
#include "grit/io/material_tables.hpp"
#include "grit/io/particle_budget.hpp"
#include "grit/io/shape_reader.hpp"
#include "grit/mesh/mirror_partners.hpp"
#include "grit/sph/kernels.hpp"

namespace grit::io {

namespace {

using core::InputError;

/// An array of axis names ("x", "y", and "z" in 3D) as one flag per axis.
std::vector<bool> read_axes(const Section& s, std::string_view key, int dim) {
    std::vector<bool> out(static_cast<std::size_t>(dim), false);
    for (const auto& a : s.strings_or(key, {})) {
        const int k = a.size() == 1 ? a[0] - 'x' : -1;
        if (k < 0 || k >= dim) s.fail(key, fmt::format("names axes \"x\", \"y\"{}", dim == 3 ? ", \"z\"" : ""));
        out[static_cast<std::size_t>(k)] = true;
    }
    return out;
}

std::string axes_text(const std::vector<bool>& axes) {
    std::string out;
    for (std::size_t k = 0; k < axes.size(); ++k)
        if (axes[k]) out += fmt::format("{}\"{}\"", out.empty() ? "" : ", ", static_cast<char>('x' + k));
    return "[" + out + "]";
}

/// domain.periodic, or dem.periodic (its older spelling): the periodic axes of the SPH particles and
/// the grains. Both given must agree. Refuses what cannot be periodic: a lattice that does not close
/// across a face, and outlets that cross a periodic face.
void read_periodic(CaseSpec& c, const Section& domain, const std::optional<std::vector<bool>>& dem_periodic) {
    const auto dim = static_cast<std::size_t>(c.dimension);
    c.periodic.assign(dim, false);
    if (domain.has("periodic")) {
        c.periodic = read_axes(domain, "periodic", c.dimension);
        if (dem_periodic && *dem_periodic != c.periodic)
            throw InputError(fmt::format(
                "keys 'domain.periodic' = {} and 'dem.periodic' = {} differ: the periodic axes are those of the "
                "SPH particles and the grains alike; give domain.periodic only",
                axes_text(c.periodic), axes_text(*dem_periodic)));
    } else if (dem_periodic) {
        c.periodic = *dem_periodic;
        c.periodic_key = "dem.periodic";
    }
    if (!c.any_periodic()) return;
    const char* axis = "xyz";
    // The particle lattice closes across a periodic face only if the period holds whole spacings.
    if (c.has_sph())
        for (std::size_t k = 0; k < dim; ++k) {
            if (!c.periodic[k]) continue;
            const double spacings = (c.domain_max[k] - c.domain_min[k]) / c.particle_spacing;
            if (std::abs(spacings - std::round(spacings)) > 1e-6 * std::max(1.0, spacings))
                domain.fail("max", fmt::format("the period along the periodic axis {} ({} m, domain.max - domain.min) "
                                               "is {:.6g} particle spacings, not a whole number: the particle "
                                               "lattice would not close across the periodic face",
                                               axis[k], c.domain_max[k] - c.domain_min[k], spacings));
        }
    for (const auto& o : c.outlets)
        for (std::size_t k = 0; k < dim; ++k) {
            if (!c.periodic[k]) continue;
            const bool within = o.min[k] >= c.domain_min[k] && o.max[k] <= c.domain_max[k];
            const bool across = o.min[k] <= c.domain_min[k] && o.max[k] >= c.domain_max[k];
            if (!within && !across)
                throw InputError(fmt::format(
                    "key '{}.min'/'{}.max': the outlet box crosses a periodic face of the domain along {} ({} = {}); "
                    "keep it inside [domain.min, domain.max] along {} or let it span the whole period",
                    o.key, o.key, axis[k], c.periodic_key, axes_text(c.periodic), axis[k]));
        }
}

/// domain.symmetry = ["x"], or jet.symmetric: the plane x = 0 is a symmetry plane (modules/symmetry_plane).
/// Refuses what the images do not support, each with its reason: a periodic x axis.
void read_symmetry(CaseSpec& c, const Section& domain) {
    if (domain.has("symmetry")) {
        const auto axes = read_axes(domain, "symmetry", c.dimension);
        for (std::size_t k = 1; k < axes.size(); ++k)
            if (axes[k])
                domain.fail("symmetry", "supports the plane x = 0 only ([\"x\"]): lay the set-up so that its plane "
                                        "of symmetry is x = 0");
        c.symmetry_plane = c.symmetry_plane || axes[0];
    }
    if (c.jet.symmetric) c.symmetry_key = "jet.symmetric";
    if (!c.symmetry_plane) return;
    const std::string key = c.symmetry_key;
    if (!c.periodic.empty() && c.periodic[0])
        throw InputError(fmt::format("keys '{}' and '{}' = [\"x\", ...]: the x axis cannot be periodic and mirrored "
                                     "at once (the mirror images are made for the plane x = 0 alone, not for its "
                                     "periodic copies); lay the whole period, or make another axis periodic",
                                     key, c.periodic_key));
    // A wall laid on a mesh that reaches x < 0 lays its x >= 0 half, if the mesh is symmetric about the plane
    // (a thin wall's sides are read from the whole sheet, the mirror images' too).
    for (BlockSpec& w : c.walls) {
        if (w.shape.kind != "mesh") continue;
        const auto& m = *w.shape.mesh;
        std::vector<mesh::Corners> corners;
        double lowest = 0.0;
        for (const auto& t : m.triangles()) {
            corners.push_back({m.vertices()[static_cast<std::size_t>(t[0])], m.vertices()[static_cast<std::size_t>(t[1])],
                               m.vertices()[static_cast<std::size_t>(t[2])]});
            for (const auto& corner : corners.back()) lowest = std::min(lowest, corner[0]);
        }
        const double tolerance = mesh::mirror_tolerance(corners);
        if (!(lowest < -tolerance)) continue;
        const auto partner = mesh::mirror_partners(corners, 0, tolerance);
        for (std::size_t t = 0; t < partner.size(); ++t)
            if (partner[t] < 0) {
                const auto centre = (corners[t][0] + corners[t][1] + corners[t][2]) * (1.0 / 3.0);
                throw InputError(fmt::format(
                    "key '{}.file': with '{}' a wall mesh that reaches x < 0 must be symmetric about the plane x = 0, "
                    "but its triangle {} at ({:.6g}, {:.6g}, {:.6g}) m has no mirror image; give the mesh whole and "
                    "symmetric, or only its x >= 0 part",
                    w.key, key, t, centre[0], centre[1], centre[2]));
            }
        w.shape.half = true;
    }
    // An inlet whose section reaches x < 0 emits its x > 0 half, if it is symmetric about the plane.
    for (InletSpec& in : c.inlets) {
        const double dx_dir = in.direction[0];
        const double extent = 0.5 * in.diameter * std::sqrt(std::max(0.0, 1.0 - dx_dir * dx_dir));
        const double tolerance = 1e-9 * in.diameter;
        if (!(in.position[0] - extent < -tolerance)) continue;
        const bool moving = !in.motion.empty() && in.motion[0] != 0.0;
        if (std::abs(in.position[0]) > tolerance || dx_dir != 0.0 || moving)
            throw InputError(fmt::format(
                "key '{}.position' = [{}]: with '{}' an inlet whose section reaches x < 0 must be centred on the "
                "plane x = 0 and aimed along it (direction with x = 0), so that it emits the x > 0 half of a "
                "symmetric jet; lay it on the x >= 0 side otherwise",
                in.key, fmt::join(in.position, ", "), key));
        in.half = true;
    }
    // A grain feed whose box reaches x < 0 fills the box's x >= 0 half at half the rate, if it is symmetric
    // about the plane (a grain fed within a radius of the plane straddles it, as [abrasive]'s do).
    for (GrainFeedSpec& f : c.grain_feeds) {
        if (!(f.min[0] < 0.0)) continue;
        if (std::abs(f.min[0] + f.max[0]) > 1e-9 * (f.max[0] - f.min[0]) || f.velocity[0] != 0.0)
            throw InputError(fmt::format(
                "key '{}.min' = [{}]: with '{}' a grain feed whose box reaches x < 0 must be symmetric about the plane "
                "(min x = -max x) and feed along it (velocity with x = 0), so that it feeds the x >= 0 half of a "
                "symmetric stream; lay it on the x >= 0 side otherwise",
                f.key, fmt::join(f.min, ", "), key));
        if (f.count % 2 != 0)
            throw InputError(fmt::format("key '{}.count' = {}: with '{}' the feed's x >= 0 half inserts half the grains, "
                                         "and an odd count has no half",
                                         f.key, f.count, key));
        f.min[0] = 0.0;
        f.mass_flow_rate *= 0.5;
        f.count /= 2;
    }
    if (!c.domain_min.empty() && c.domain_max[0] <= 0.0)
        throw InputError(fmt::format("key 'domain.max' = [{}]: with {} the domain must reach x > 0 (the half that "
                                     "is run)", fmt::join(c.domain_max, ", "), key));
}

/// [jet]: the jet as the machine is set up. The geometry it implies is built by io/jet_builder.
void read_jet(const Section& j, CaseSpec& c, MaterialTable& table) {
    JetSpec& jet = c.jet;
    c.has_jet = true;
    jet.diameter = j.number("diameter", positive("[m]"));
    jet.material = table.resolve(j, "material", j.text_or("material", "water"));
    if (j.has("velocity") && j.has("pressure")) j.fail("pressure", "give either jet.velocity or jet.pressure, not both");
    if (j.has("pressure")) {
        // Pump pressures are hundreds of MPa; a value below 10 kPa is almost surely in MPa.
        jet.pressure = j.number("pressure", [](double v) {
            return v >= 1e4 ? std::string{}
                            : fmt::format("is in Pa and must be at least 1e4 (did you mean {} MPa = {:g} Pa?)", v, v * 1e6);
        });
        jet.volume_efficiency = j.number_or("volume_efficiency", jet.volume_efficiency, in_range(0.01, 1.0));
        const double rho = c.materials[static_cast<std::size_t>(jet.material)].reference_density();
        jet.velocity = jet_velocity_from_pressure(jet.pressure, jet.volume_efficiency, rho);
    } else {
        if (!j.has("velocity")) j.fail("velocity", "is required (or jet.pressure, the pump pressure [Pa], eq. 52)");
        jet.velocity = j.number("velocity", positive("[m/s]"));
    }
    jet.angle = j.number_or("angle", jet.angle, [](double v) {
        return v > 0.0 && v <= 90.0 ? std::string{} : std::string("must lie in (0, 90] [deg] (90: normal to the surface)");
    });
    jet.standoff = j.number("standoff", positive("[m]"));
    jet.target = j.vector_or("target", c.dimension, "[m]", {});
    jet.traverse_speed = j.number_or("traverse_speed", 0.0, non_negative("[m/s]"));
    jet.start = j.number_or("start", 0.0, non_negative("[s]"));
    jet.stop = j.number_or("stop", 1e300, non_negative("[s]"));
    if (jet.stop <= jet.start) j.fail("stop", "must come after jet.start");
    jet.side_outlets = j.flag_or("side_outlets", true);
    jet.clamp_sides = j.flag_or("clamp_sides", true);
    jet.clamp_bottom = j.flag_or("clamp_bottom", false);
    jet.symmetric = j.flag_or("symmetric", false);
}

/// [abrasive]: the grains fed into the jet; y_dis or M is completed by io/jet_builder.
void read_abrasive(const Section& a, CaseSpec& c, GrainMaterialTable& grain_table) {
    if (!c.has_jet)
        throw InputError("key 'abrasive': the abrasive feed rides a [jet]; add one, or place grains with [[grains]]");
    AbrasiveSpec& ab = c.abrasive;
    ab.enabled = true;
    ab.material = grain_table.resolve(a, "material", a.text_or("material", "garnet"));
    ab.size = read_grain_size(a, c.grain_materials[static_cast<std::size_t>(ab.material)]);
    if (a.has("mass_flow_rate") && a.has("spacing"))
        a.fail("spacing", "give either abrasive.mass_flow_rate or abrasive.spacing (y_dis), not both (eq. 55)");
    if (a.has("mass_flow_rate")) {
        ab.rate_key = "abrasive.mass_flow_rate";
        ab.mass_flow_rate = a.number("mass_flow_rate", positive("[kg/s]"));
    } else {
        if (!a.has("spacing"))
            a.fail("mass_flow_rate", "is required (or abrasive.spacing, the liquid column length y_dis of eq. 55)");
        ab.rate_key = "abrasive.spacing";
        ab.spacing = a.number("spacing", positive("[m]"));
    }
    ab.seed = static_cast<std::uint64_t>(a.integer_or("seed", 1, 0, 2147483647));
    ab.start = a.number_or("start", c.jet.start, non_negative("[s]"));
    ab.stop = a.number_or("stop", c.jet.stop, non_negative("[s]"));
    if (ab.stop <= ab.start) a.fail("stop", "must come after abrasive.start");
}

/// fluid.solver: a setting of the fluid as a whole. The fluid blocks are an array of tables
/// ([[fluid]]), so the key sits in the blocks (all that give it must agree; `--set fluid.solver=isph`
/// sets it in each), or, in a case without fluid blocks, in a [fluid] table of its own. Then [isph].
void read_fluid_solver(const Section& top, CaseSpec& c) {
    const std::vector<std::string> solvers = {"wcsph", "isph"};
    if (top.has("fluid") && top.node_is_table("fluid")) {
        // A [fluid] table (no blocks): only the fluid's settings; take it out of the way of the blocks.
        const Section f = top.section("fluid");
        c.fluid_solver = f.choice("solver", c.fluid_solver, solvers);
    } else {
        std::string first_key;
        for (const Section& f : top.sections("fluid")) {
            if (!f.has("solver")) continue;
            const std::string s = f.choice("solver", c.fluid_solver, solvers);
            if (first_key.empty()) {
                c.fluid_solver = s;
                first_key = f.key_path("solver");
            } else if (s != c.fluid_solver) {
                f.fail("solver", fmt::format("differs from {} = \"{}\": one solver integrates all the fluid",
                                             first_key, c.fluid_solver));
            }
        }
        if (!first_key.empty()) c.fluid_solver_key = first_key;
    }
    const Section isph = top.section("isph");
    if (top.has("isph") && c.fluid_solver != "isph")
        throw InputError(fmt::format("key 'isph': the settings of the incompressible solver, but {} = \"{}\"; set "
                                     "fluid.solver = \"isph\" or remove [isph]", c.fluid_solver_key, c.fluid_solver));
    c.isph.tolerance = isph.number_or("tolerance", c.isph.tolerance, in_range(1e-14, 1e-2));
    c.isph.max_iterations = isph.integer_or("max_iterations", c.isph.max_iterations, 1, 1000000);
    const double interior = c.dimension == 2 ? 2.0 : 3.0;
    c.isph.free_surface_divergence =
        isph.number_or("free_surface_divergence", c.dimension == 2 ? 1.5 : 2.4, in_range(0.1 * interior, interior));
    c.isph.density_relaxation = isph.number_or("density_relaxation", c.isph.density_relaxation, in_range(0.0, 1.0));
    c.isph.shifting = isph.number_or("shifting", c.isph.shifting, in_range(0.0, 10.0));
}

/// What the incompressible solver does not (yet) integrate: refused with the key that asked for it.
void check_fluid_solver(const CaseSpec& c) {
    if (c.fluid_solver != "isph") return;
    auto refuse = [&](const std::string& what) {
        throw InputError(fmt::format("key '{}' = \"isph\": the incompressible solver does not yet handle {}; use "
                                     "\"wcsph\" for this case",
                                     c.fluid_solver_key, what));
    };
    if (!c.solids.empty()) refuse(fmt::format("SPH solids ({})", c.solids.front().key));
    if (c.has_jet) refuse("a [jet]");
    if (!c.inlets.empty()) refuse(fmt::format("inlets ({})", c.inlets.front().key));
    if (c.fluids.empty()) refuse("a case without [[fluid]] blocks");
    if (c.shepard_interval > 0)
        throw InputError(fmt::format("key 'numerics.shepard_interval' = {}: the incompressible solver keeps every "
                                     "particle at its reference density, so there is no density to filter; set it to "
                                     "0 with {} = \"isph\"", c.shepard_interval, c.fluid_solver_key));
}

/// The case in `root` (parsed from `file`, whose folder relative paths start from), with `overrides`.
CaseSpec read_case_table(toml::table root, const std::filesystem::path& file, std::string text,
                         const std::vector<std::string>& overrides) {
    for (const auto& o : overrides) apply_override(root, o);

    KeyRecord keys;
    const Section top(&keys, &root, "");
    CaseSpec c;
    c.source = file;
    c.text = std::move(text);
    c.overrides = overrides;
    c.name = file.stem().string() == "case" ? file.parent_path().filename().string() : file.stem().string();
    if (c.name.empty()) c.name = "case";

    const Section sim = top.section("simulation");
    c.title = sim.text_or("title", c.name);
    c.dimension = sim.integer_or("dimension", 2, 2, 3);
    const int dim = c.dimension;

    const Section time = top.section("time");
    c.end_time = time.number("end", non_negative("[s]"));
    c.cfl = time.number_or("cfl", c.cfl, in_range(1e-3, 1.0));
    c.max_time_step = time.number_or("max_step", c.max_time_step, positive("[s]"));

    const Section output = top.section("output");
    c.output_interval = output.number("interval", positive("[s]"));
    c.write_snapshots = output.flag_or("snapshots", true);
    c.checkpoint_interval = output.number_or("checkpoint_interval", 0.0, non_negative("[s]"));
    c.checkpoint_keep = output.integer_or("checkpoint_keep", c.checkpoint_keep, 1, 1000000);
    c.checkpoint_wall_interval =
        output.number_or("checkpoint_wall_interval", c.checkpoint_wall_interval, non_negative("[s]"));
    // A time.end in the wrong unit (10 s for 10 us) would write millions of outputs: refuse it here.
    const double max_outputs = output.number_or("max_outputs", 100000.0, positive("[-]"));
    if (c.end_time / c.output_interval + 1.0 > max_outputs)
        time.fail("end", fmt::format("with output.interval = {} s the run writes {:.0f} outputs (snapshots and series "
                                     "rows), more than output.max_outputs = {:g}; raise output.interval, or "
                                     "output.max_outputs to allow it",
                                     c.output_interval, std::floor(c.end_time / c.output_interval) + 1.0, max_outputs));

    const Section numerics = top.section("numerics");
    const bool sph_blocks = top.has("fluid") || top.has("solid") || top.has("inlet") || top.has("wall");
    c.particle_spacing = sph_blocks ? numerics.number("particle_spacing", positive("[m]"))
                                    : numerics.number_or("particle_spacing", 1.0, positive("[m]"));
    c.smoothing_ratio = numerics.number_or("smoothing_ratio", c.smoothing_ratio, in_range(0.5, 3.0));
    std::vector<std::string> kernels(std::begin(sph::kernel_names), std::end(sph::kernel_names));
    c.kernel = numerics.choice("kernel", c.kernel, kernels);
    c.density_diffusion = numerics.number_or("density_diffusion", c.density_diffusion, in_range(0.0, 1.0));
    c.neighbor_skin = numerics.number_or("neighbor_skin", c.neighbor_skin, in_range(0.0, 2.0));
    c.check_interval = numerics.integer_or("check_interval", c.check_interval, 1, 1000000);
    c.max_speed = numerics.number_or("max_speed", 0.0, non_negative("[m/s]"));
    c.artificial_stress = numerics.number_or("artificial_stress", c.artificial_stress, in_range(0.0, 1.0));
    c.kernel_correction = numerics.flag_or("kernel_correction", c.kernel_correction);
    c.shepard_interval = numerics.integer_or("shepard_interval", c.shepard_interval, 0, 1000000);
    // Particle indices are 32-bit (grit::Index): no case can hold more.
    c.max_particles = numerics.integer_or("max_particles", c.max_particles, 1, std::numeric_limits<Index>::max());
    const double dx = c.particle_spacing;

    const Section physics = top.section("physics");
    c.gravity = physics.vector_or("gravity", dim, "[m/s^2]", std::vector<double>(static_cast<std::size_t>(dim), 0.0));

    const Section materials = top.section("materials");
    MaterialTable table(materials, c.materials);

    read_fluid_solver(top, c);
    // The projection is first-order only with the corrected gradient: uncorrected, the surface
    // particles of the tank at rest sank (0.2 m/s) and its pressure was 20 % off.
    if (c.fluid_solver == "isph" && !numerics.has("kernel_correction")) c.kernel_correction = true;
    for (const Section& f : top.node_is_table("fluid") ? std::vector<Section>{} : top.sections("fluid")) {
        BlockSpec b;
        b.key = f.path();
        b.shape = read_shape(f, dim, dx, false);
        b.material = table.resolve(f, "material", f.text_or("material", "water"));
        b.velocity = f.vector_or("velocity", dim, "[m/s]", std::vector<double>(static_cast<std::size_t>(dim), 0.0));
        b.hydrostatic = f.flag_or("hydrostatic", false);
        f.has("solver");  // read by read_fluid_solver: a known key here
        c.fluids.push_back(std::move(b));
    }
    for (const Section& s : top.sections("inlet")) {
        InletSpec in;
        in.key = s.path();
        in.position = s.vector("position", dim, "[m]");
        in.direction = s.vector("direction", dim, "[-]");
        double n2 = 0.0;
        for (double v : in.direction) n2 += v * v;
        if (n2 <= 0.0) s.fail("direction", "must not be the zero vector");
        for (double& v : in.direction) v /= std::sqrt(n2);
        in.diameter = s.number("diameter", positive("[m]"));
        if (in.diameter < dx)
            s.fail("diameter", fmt::format("is less than numerics.particle_spacing = {} m (lengths are in metres: "
                                           "0.1 mm is 1e-4)", dx));
        in.velocity = s.number("velocity", positive("[m/s]"));
        in.material = table.resolve(s, "material", s.text_or("material", "water"));
        in.start = s.number_or("start", 0.0, non_negative("[s]"));
        in.stop = s.number_or("stop", 1e300, non_negative("[s]"));
        c.inlets.push_back(std::move(in));
    }
    for (const Section& f : top.sections("solid")) {
        BlockSpec b;
        b.key = f.path();
        b.shape = read_shape(f, dim, dx, false);
        b.material = table.resolve(f, "material", f.text("material"), Phase::solid);
        b.velocity = f.vector_or("velocity", dim, "[m/s]", std::vector<double>(static_cast<std::size_t>(dim), 0.0));
        b.velocity_profile =
            f.choice("velocity_profile", "uniform", {"uniform", "cantilever_mode", "longitudinal_wave"});
        if (b.velocity_profile == "cantilever_mode") {
            b.mode_origin = f.number("mode_origin");
            b.mode_length = f.number("mode_length", positive("[m]"));
            b.mode_tip_velocity = f.number("mode_tip_velocity");
        } else if (b.velocity_profile == "longitudinal_wave") {
            const std::string axis = f.choice("wave_axis", "x", dim == 2 ? std::vector<std::string>{"x", "y"}
                                                                          : std::vector<std::string>{"x", "y", "z"});
            b.wave_axis = axis[0] - 'x';
            b.wave_length = f.number("wave_length", positive("[m]"));
            b.wave_amplitude = f.number("wave_amplitude");
        }
        c.solids.push_back(std::move(b));
    }
    for (const Section& s : top.sections("clamp")) {
        OutletSpec o = read_box(s, dim);
        o.velocity = s.vector_or("velocity", dim, "[m/s]", std::vector<double>(static_cast<std::size_t>(dim), 0.0));
        c.clamps.push_back(std::move(o));
    }
    if (!c.clamps.empty() && c.solids.empty()) throw InputError("key 'clamp': clamps hold solids, and the case has no [[solid]]");
    const int default_material = !c.fluids.empty() ? c.fluids.front().material
                                 : !c.inlets.empty() ? c.inlets.front().material
                                                     : -1;
    for (const Section& w : top.sections("wall")) {
        BlockSpec b;
        b.key = w.path();
        b.shape = read_shape(w, dim, dx, true, c.source.parent_path());
        if (!w.has("material") && default_material < 0)
            w.fail("material", "is required: walls take the EOS of a fluid, and the case has none");
        b.material = w.has("material") ? table.resolve(w, "material", w.text("material")) : default_material;
        c.walls.push_back(std::move(b));
    }
    for (const Section& s : top.sections("outlet")) {
        OutletSpec o = read_box(s, dim);
        c.outlets.push_back(std::move(o));
    }
    if (top.has("jet")) read_jet(top.section("jet"), c, table);

    const Section grain_materials = top.section("grain_materials");
    GrainMaterialTable grain_table(grain_materials, c.grain_materials);
    for (const Section& g : top.sections("grains")) {
        GrainBlockSpec b;
        b.key = g.path();
        b.material = grain_table.resolve(g, "material", g.text_or("material", "garnet"));
        b.size = read_grain_size(g, c.grain_materials[static_cast<std::size_t>(b.material)]);
        b.arrangement = g.choice("arrangement", "single", {"single", "lattice", "random"});
        if (b.arrangement == "single") {
            b.position = g.vector("position", dim, "[m]");
        } else {
            b.min = g.vector("min", dim, "[m]");
            b.max = g.vector("max", dim, "[m]");
            for (int k = 0; k < dim; ++k)
                if (b.max[k] <= b.min[k]) g.fail("max", "must exceed min in every direction");
            if (b.arrangement == "lattice") {
                b.spacing = g.number("spacing", positive("[m]"));
                b.jitter = g.number_or("jitter", 0.0, non_negative("[m]"));
            } else {
                b.count = g.integer_or("count", 0, 1, 100000000);
                if (b.count == 0) g.fail("count", "is required for arrangement = \"random\"");
            }
        }
        b.seed = static_cast<std::uint64_t>(g.integer_or("seed", 1, 0, 2147483647));
        b.velocity = g.vector_or("velocity", dim, "[m/s]", std::vector<double>(static_cast<std::size_t>(dim), 0.0));
        b.fixed = g.flag_or("fixed", false);
        if (b.fixed)
            for (double v : b.velocity)
                if (v != 0.0)
                    g.fail("velocity", fmt::format("= {}: fixed grains (fixed = true) do not move; remove the velocity "
                                                   "or the fixed flag",
                                                   fmt::join(b.velocity, ", ")));
        c.grains.push_back(std::move(b));
    }
    if (top.has("abrasive")) read_abrasive(top.section("abrasive"), c, grain_table);
    for (const Section& f : top.sections("grain_feed")) {
        GrainFeedSpec feed;
        feed.key = f.path();
        feed.material = grain_table.resolve(f, "material", f.text_or("material", "garnet"));
        feed.size = read_grain_size(f, c.grain_materials[static_cast<std::size_t>(feed.material)]);
        feed.min = f.vector("min", dim, "[m]");
        feed.max = f.vector("max", dim, "[m]");
        for (int k = 0; k < dim; ++k)
            if (!(feed.max[static_cast<std::size_t>(k)] > feed.min[static_cast<std::size_t>(k)]))
                f.fail("max", "must exceed min along every axis");
        feed.velocity = f.vector_or("velocity", dim, "[m/s]", std::vector<double>(static_cast<std::size_t>(dim), 0.0));
        feed.mass_flow_rate = f.number("mass_flow_rate", positive("[kg/s]"));
        feed.interval = f.number("interval", positive("[s]"));
        feed.start = f.number_or("start", 0.0, non_negative("[s]"));
        feed.stop = f.number_or("stop", 1e300, positive("[s]"));
        feed.count = f.integer_or("count", 0, 0, 100'000'000);
        feed.seed = static_cast<std::uint64_t>(f.integer_or("seed", 1, 0, 2'000'000'000));
        c.grain_feeds.push_back(std::move(feed));
    }
    for (const Section& w : top.sections("grain_wall")) {
        if (!c.has_grains()) throw InputError("key 'grain_wall': grain walls need [[grains]] or [abrasive]");
        GrainWallSpec gw;
        gw.key = w.path();
        gw.name = w.text_or("name", fmt::format("plane{}", c.grain_walls.size()));
        if (gw.name.empty() || gw.name.find_first_of(", \t\"") != std::string::npos)
            w.fail("name", "must be a non-empty name without commas, spaces or quotes");
        gw.point = w.vector("point", dim, "[m]");
        gw.normal = w.vector("normal", dim, "[-]");
        double n2 = 0.0;
        for (double v : gw.normal) n2 += v * v;
        if (n2 <= 0.0) w.fail("normal", "must not be the zero vector");
        for (double& v : gw.normal) v /= std::sqrt(n2);
        gw.material = w.has("material") ? grain_table.resolve(w, "material", w.text("material")) : c.first_grain_material();
        c.grain_walls.push_back(std::move(gw));
    }
    read_meshes(top, c, grain_table);
    std::optional<std::vector<bool>> dem_periodic;
    if (top.has("dem")) {
        const Section d = top.section("dem");
        c.dem.contact_law = d.choice("contact_law", c.dem.contact_law, {"linear", "hertz"});
        c.dem.skin = d.number_or("skin", c.dem.skin, positive("[m]"));
        if (d.has("periodic")) dem_periodic = read_axes(d, "periodic", dim);
        c.dem.overlap_coefficient = d.number_or("overlap_coefficient", 0.0, in_range(0.0, 0.999));
        c.dem.solid_friction = d.number_or("solid_friction", -1.0, non_negative("[-]"));
        c.dem.wall_particle_contact = d.flag_or("wall_particle_contact", true);
        c.dem.grain_grain_contact = d.flag_or("grain_grain_contact", true);
    }
    if (top.has("coupling")) {
        const Section k = top.section("coupling");
        c.coupling.enabled = k.flag_or("enabled", true);
        // Up to 200 d: fine sand in coarse water (0.1 mm grains, 5 mm spacing) needs R_c = 2 h = 125 d.
        c.coupling.radius = k.number_or("radius", c.coupling.radius, in_range(0.5, 200.0));
        c.coupling.drag = k.choice("drag", c.coupling.drag, {"gidaspow", "di_felice", "single_particle", "single_particle_as_printed"});
        c.coupling.min_porosity = k.number_or("min_porosity", c.coupling.min_porosity, in_range(0.01, 0.9));
    }
    for (const auto& name : grain_materials.keys()) {
        bool in_use = false;
        for (const auto& m : c.grain_materials) in_use |= m.name == name;
        if (!in_use) read_grain_material(grain_materials.section(name), name);
    }

    const Section domain = top.section("domain");
    c.jet.derive_domain = c.has_jet && !top.has("domain");
    if (!c.jet.derive_domain) {
        c.domain_min = domain.vector("min", dim, "[m]");
        c.domain_max = domain.vector("max", dim, "[m]");
        for (int k = 0; k < dim; ++k)
            if (c.domain_max[k] <= c.domain_min[k]) domain.fail("max", "must exceed domain.min in every direction");
        c.remove_leaving = domain.choice("on_exit", "error", {"error", "remove"}) == "remove";
    }
    if (c.has_jet) build_jet(c);
    read_periodic(c, domain, dem_periodic);
    read_symmetry(c, domain);

    // Materials are read on first use; a defined but unused material is still checked and reported.
    for (const auto& name : materials.keys()) {
        bool in_use = false;
        for (const auto& m : c.materials) in_use |= m.name == name;
        if (!in_use) read_material(materials.section(name), name);
    }

    if (c.fluids.empty() && c.inlets.empty() && c.solids.empty() && !c.has_grains())
        throw InputError(
            "the case has nothing that moves: add a [[fluid]], [[solid]], [[inlet]], [jet], [[grains]] or [[grain_feed]]");
    // The tables modules read themselves (case_tables.hpp), after the reader's own, then their cross rules.
    for (const CaseTable& t : case_tables()) {
        if (keys.asked.count(t.key))
            throw std::logic_error("the case reader already reads the table '" + t.key + "' a module registered");
        if (top.has(t.key)) c.module_specs[t.key] = t.read(top, c);
    }
    for (const CaseTable& t : case_tables())
        if (t.check) t.check(c);
    check_fluid_solver(c);
    if (c.shepard_interval > 0 && c.has_grains() && c.coupling.enabled && !c.fluids.empty())
        throw InputError(fmt::format("key 'numerics.shepard_interval' = {}: the Shepard filter acts on the particle "
                                     "density, which with grains coupled to the fluid is the porosity-weighted one; "
                                     "set it to 0 or coupling.enabled = false", c.shepard_interval));
    report_unknown(root, "", keys);
    // Last, once everything else is valid: refuse a case its spacing cannot resolve, or too big to allocate.
    check_resolution(c);
    check_particle_budget(c);
    return c;
}

/// The TOML of a case's text; `what` names it in the message of a syntax error ("case file", "case text").
toml::table parse_case(const std::string& text, const std::filesystem::path& file, const char* what) {
    try {
        return toml::parse(text, file.string());
    } catch (const toml::parse_error& e) {
        throw InputError(fmt::format("{} '{}' line {}: malformed TOML: {}", what, file.string(), e.source().begin.line,
                                     e.description()));
    }
}

}  // namespace

CaseSpec read_case(const std::filesystem::path& file, const std::vector<std::string>& overrides) {
    if (!std::filesystem::exists(file)) throw InputError(fmt::format("case file '{}': no such file", file.string()));
    std::ifstream in(file, std::ios::binary);
    std::string text(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>{});
    if (!in.eof() && in.fail()) throw InputError(fmt::format("case file '{}': cannot be read", file.string()));
    toml::table root = parse_case(text, file, "case file");
    return read_case_table(std::move(root), file, std::move(text), overrides);
}

CaseSpec read_case_text(const std::string& text, const std::filesystem::path& file,
                        const std::vector<std::string>& overrides) {
    return read_case_table(parse_case(text, file, "case text"), file, text, overrides);
}

}  // namespace grit::io
