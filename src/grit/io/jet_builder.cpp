// The jet builder.
#include "grit/io/jet_builder.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "grit/core/error.hpp"

namespace grit::io {

double jet_velocity_from_pressure(double pressure, double volume_efficiency, double density) {
    return volume_efficiency * std::sqrt(2.0 * pressure / density);
}

double abrasive_volume(int dimension, double diameter, double jet_diameter) {
    const double r = 0.5 * diameter;
    return dimension == 2 ? std::numbers::pi * r * r * jet_diameter : 4.0 / 3.0 * std::numbers::pi * r * r * r;
}

double abrasive_mass_flow_rate(double grain_density, double jet_velocity, double volume, double spacing) {
    return grain_density * jet_velocity * volume / spacing;
}

namespace {

[[noreturn]] void fail(const std::string& key, double value, const std::string& reason) {
    throw core::InputError(fmt::format("key '{}' = {}: {}", key, value, reason));
}

std::string point_text(const std::vector<double>& x) { return fmt::format("({:.4g})", fmt::join(x, ", ")); }

/// The mean diameter of a size distribution [m] (eq. 55 takes one grain volume).
double mean_diameter(const dem::SizeDistribution& size) {
    return std::visit(
        [](const auto& d) -> double {
            using T = std::decay_t<decltype(d)>;
            if constexpr (std::is_same_v<T, dem::FixedSize>) return d.diameter;
            else if constexpr (std::is_same_v<T, dem::UniformSize>) return 0.5 * (d.min + d.max);
            else if constexpr (std::is_same_v<T, dem::DiscreteSize>) return d.mean();
            else return d.mean;
        },
        size);
}

/// How far upstream of the nozzle a grain joins the run: beyond the coupling's reach (R_c of the
/// largest grain) of the water already emitted, plus two spacings [m].
double abrasive_lead(const CaseSpec& c) {
    const double largest = std::visit([](const auto& d) { return d.largest(); }, c.abrasive.size);
    return c.coupling.radius * largest + 2.0 * c.particle_spacing;
}

/// The feed of [abrasive] on the jet's inlet `jet`; `diameter` is the whole jet's (the inlet's is half of
/// it on a symmetry plane).
void build_abrasive(CaseSpec& c, const InletSpec& jet, double diameter) {
    AbrasiveSpec& a = c.abrasive;
    const auto& grain = c.grain_materials[static_cast<std::size_t>(a.material)];
    const double largest = std::visit([](const auto& d) { return d.largest(); }, a.size);
    if (largest > diameter)
        fail("abrasive.diameter", largest,
             fmt::format("a grain is wider than the jet (jet.diameter = {} m); it cannot ride inside it", diameter));
    const double volume = abrasive_volume(c.dimension, mean_diameter(a.size), diameter);
    const double densest = grain.density * jet.velocity * volume / largest;  // M at y_dis = the largest diameter
    if (a.rate_key == "abrasive.mass_flow_rate") {
        if (a.mass_flow_rate > densest)
            fail(a.rate_key, a.mass_flow_rate,
                 fmt::format("packs the grains closer than their diameter: y_dis would be {:.3g} m, below the largest "
                             "grain's {:.3g} m (at most {:.3g} kg/s for this jet and grain, eq. 55)",
                             grain.density * jet.velocity * volume / a.mass_flow_rate, largest, densest));
        a.spacing = grain.density * jet.velocity * volume / a.mass_flow_rate;
    } else {
        if (a.spacing < largest)
            fail(a.rate_key, a.spacing,
                 fmt::format("packs the grains closer than their diameter ({:.3g} m): a liquid column must hold its "
                             "grain whole",
                             largest));
        a.mass_flow_rate = abrasive_mass_flow_rate(grain.density, jet.velocity, volume, a.spacing);
    }
    // Eq. (54): the grain's share of its column, pi d^2 / 4 over y_dis d_jet in 2D, the sphere over the
    // cylinder y_dis pi d_jet^2 / 4 in 3D.
    const double column = c.dimension == 2 ? a.spacing * diameter * diameter
                                           : a.spacing * std::numbers::pi * 0.25 * diameter * diameter;
    a.volume_fraction = volume / column;
    // Half the jet holds half its grains: one per two columns, each with its twin across the plane.
    a.feed_spacing = c.jet.symmetric ? 2.0 * a.spacing : a.spacing;
    a.half_jet = c.jet.symmetric;
    a.inlet = static_cast<int>(c.inlets.size()) - 1;
    a.lead = abrasive_lead(c);
    // The grains join the run upstream of the nozzle: that point must lie in the domain.
    for (std::size_t k = 0; k < jet.position.size(); ++k) {
        const double x = jet.position[k] - jet.direction[k] * (a.lead + 0.5 * largest);
        if (x < c.domain_min[k] - 1e-12 || x > c.domain_max[k] + 1e-12)
            throw core::InputError(fmt::format(
                "key 'domain.{}' = [{}]: the abrasive joins the jet {:.3g} m upstream of the nozzle, at {} = {:.4g} m, "
                "outside the domain; extend it (or leave [domain] out: the jet builder sizes it)",
                x < c.domain_min[k] ? "min" : "max", fmt::join(x < c.domain_min[k] ? c.domain_min : c.domain_max, ", "),
                a.lead, "xyz"[k], x));
    }
}

/// jet.symmetric: a jet whose axis x = 0 is a plane of symmetry of the whole set-up.
void check_symmetric(const CaseSpec& c, const std::vector<double>& lo, const std::vector<double>& hi) {
    const JetSpec& j = c.jet;
    const double dx = c.particle_spacing;
    const std::string why = "with jet.symmetric the plane x = 0 must be a plane of symmetry of the set-up";
    if (c.dimension != 2)
        throw core::InputError("key 'jet.symmetric': the half jet is 2D only (a 3D jet's half disc is not laid yet)");
    if (j.angle != 90.0) fail("jet.angle", j.angle, why + " (normal incidence, 90)");
    if (j.traverse_speed != 0.0) fail("jet.traverse_speed", j.traverse_speed, why + " (no traverse)");
    if (!j.target.empty() && j.target[0] != 0.0) fail("jet.target", j.target[0], why + " (the jet aimed at x = 0)");
    if (std::abs(lo[0] + hi[0]) > 1e-9 * (hi[0] - lo[0]))
        throw core::InputError(fmt::format("key '{}.min' = [{}]: {} (the specimen from x = -a to a; its max is [{}])",
                                           c.solids.front().key, fmt::join(lo, ", "), why, fmt::join(hi, ", ")));
    const long columns = std::lround(std::floor(j.diameter / dx + 1e-6));
    if (columns % 2 != 0)
        fail("jet.diameter", j.diameter,
             fmt::format("holds {} particle columns (numerics.particle_spacing = {} m), an odd number: the plane x = 0 "
                         "would cut the middle one; {}",
                         columns, dx, "use a diameter of an even number of spacings"));
    if (c.solids.size() > 1 || !c.inlets.empty() || !c.fluids.empty() || !c.walls.empty())
        throw core::InputError(
            "key 'jet.symmetric': the builder halves the jet and the specimen only; other [[solid]], [[inlet]], "
            "[[fluid]] or [[wall]] blocks would need halving by hand (use domain.symmetry for such set-ups)");
}

}  // namespace

void build_jet(CaseSpec& c) {
    JetSpec& j = c.jet;
    const int dim = c.dimension;
    const auto V = static_cast<std::size_t>(dim - 1);  // the vertical axis
    const double dx = c.particle_spacing;
    if (c.solids.empty() || c.solids.front().shape.kind != "box")
        throw core::InputError(
            "key 'jet': the jet is aimed at the specimen, the first [[solid]], which must be a box (shape = \"box\"); "
            "use [[inlet]] for other set-ups");
    auto& specimen = c.solids.front();
    std::vector<double> lo = specimen.shape.min, hi = specimen.shape.max;
    const double surface = hi[V];
    if (j.symmetric) check_symmetric(c, lo, hi);
    const double width = hi[0] - lo[0];  // the whole specimen's, also on a symmetry plane

    if (j.target.empty()) {
        j.target.assign(static_cast<std::size_t>(dim), 0.0);
        for (std::size_t k = 0; k < V; ++k) j.target[k] = 0.5 * (lo[k] + hi[k]);
        j.target[V] = surface;
    }
    const double angle = j.angle * std::numbers::pi / 180.0;
    std::vector<double> direction(static_cast<std::size_t>(dim), 0.0);
    direction[0] = std::cos(angle);
    direction[V] = -std::sin(angle);
    if (j.angle == 90.0) direction[0] = 0.0;  // exactly normal, not cos(pi/2) = 6e-17
    std::vector<double> nozzle(static_cast<std::size_t>(dim));
    for (std::size_t k = 0; k < nozzle.size(); ++k) nozzle[k] = j.target[k] - direction[k] * j.standoff;

    // The nozzle section must clear the specimen's top by a particle spacing.
    const double lowest = nozzle[V] - 0.5 * j.diameter * std::abs(direction[0]);
    if (lowest < surface + dx)
        fail("jet.standoff", j.standoff,
             fmt::format("puts the nozzle at {} with its section down to {} = {:.4g} m, inside or within a particle "
                         "spacing of the specimen's top surface ({} = {:.4g} m); use a larger standoff or a higher "
                         "jet.target",
                         point_text(nozzle), "xyz"[V], lowest, "xyz"[V], surface));
    if (j.diameter < dx)
        fail("jet.diameter", j.diameter,
             fmt::format("is less than numerics.particle_spacing = {} m (lengths are in metres: 0.1 mm is 1e-4)", dx));

    InletSpec in;
    in.key = "jet";
    in.position = nozzle;
    in.direction = direction;
    in.diameter = j.diameter;
    if (j.symmetric) {  // the x >= 0 half: the specimen, the jet section and the columns of particles in it
        c.symmetry_plane = true;
        c.symmetry_key = "jet.symmetric";
        lo[0] = 0.0;
        specimen.shape.min[0] = 0.0;
        in.diameter = 0.5 * j.diameter;
        in.position[0] = 0.25 * j.diameter;
    }
    in.velocity = j.velocity;
    in.material = j.material;
    in.start = j.start;
    in.stop = j.stop;
    in.motion.assign(static_cast<std::size_t>(dim), 0.0);
    in.motion[0] = j.traverse_speed;
    c.inlets.push_back(in);

    // Side zones: outlets above the specimen's edges and clamps along them (Fig. 9).
    j.side_width = std::max(4.0 * dx, 0.08 * width);
    const double w = j.side_width;
    if (j.derive_domain) {
        c.domain_min.assign(static_cast<std::size_t>(dim), 0.0);
        c.domain_max.assign(static_cast<std::size_t>(dim), 0.0);
        for (std::size_t k = 0; k < V; ++k) {
            c.domain_min[k] = lo[k] - w - 2.0 * dx;
            c.domain_max[k] = hi[k] + w + 2.0 * dx;
        }
        // On the plane: a particle that drifted across is reflected, not lost.
        if (j.symmetric) c.domain_min[0] = -2.0 * dx;
        c.domain_min[V] = lo[V] - 2.0 * dx;
        double above = std::max(w, 4.0 * dx);
        if (c.abrasive.enabled)
            above = std::max(above, abrasive_lead(c) + std::visit([](const auto& d) { return d.largest(); }, c.abrasive.size));
        c.domain_max[V] = std::max(nozzle[V], surface) + above;
        c.remove_leaving = true;
    }
    // The nozzle must stay inside the domain while it traverses.
    const double x_end = nozzle[0] + j.traverse_speed * std::min(c.end_time, j.stop);
    for (std::size_t k = 0; k < nozzle.size(); ++k)
        if (nozzle[k] < c.domain_min[k] || nozzle[k] > c.domain_max[k])
            fail("jet.standoff", j.standoff,
                 fmt::format("puts the nozzle at {}, outside the domain (domain.min/domain.max)", point_text(nozzle)));
    if (x_end > c.domain_max[0])
        fail("jet.traverse_speed", j.traverse_speed,
             fmt::format("moves the nozzle to x = {:.4g} m by the end, outside the domain (x up to {:.4g} m)", x_end,
                         c.domain_max[0]));

    const double top = c.domain_max[V];
    if (j.side_outlets && c.outlets.empty() && top > surface) {
        for (std::size_t a = 0; a < V; ++a)
            for (const double edge : {lo[a], hi[a]}) {
                if (j.symmetric && a == 0 && edge == lo[a]) continue;  // the plane, not an edge
                OutletSpec o;
                o.key = fmt::format("jet (side outlet at {} = {:.4g} m)", "xyz"[a], edge);
                o.min = c.domain_min;
                o.max = c.domain_max;
                // Across the edge, a spacing beyond it on the outer side.
                const bool low = edge == lo[a];
                o.min[a] = edge - w - (low ? dx : 0.0);
                o.max[a] = edge + w + (low ? 0.0 : dx);
                o.min[V] = surface;
                o.max[V] = top;
                c.outlets.push_back(o);
            }
    }
    const bool own_clamps = !c.clamps.empty();
    if (j.clamp_sides && !own_clamps) {
        for (std::size_t a = 0; a < V; ++a)
            for (const double edge : {lo[a], hi[a]}) {
                if (j.symmetric && a == 0 && edge == lo[a]) continue;
                OutletSpec cl;
                cl.key = fmt::format("jet (side clamp at {} = {:.4g} m)", "xyz"[a], edge);
                cl.min = lo;
                cl.max = hi;
                for (std::size_t k = 0; k < cl.min.size(); ++k) cl.min[k] -= dx, cl.max[k] += dx;
                if (edge == lo[a]) cl.max[a] = lo[a] + 0.5 * w;
                else cl.min[a] = hi[a] - 0.5 * w;
                cl.velocity.assign(static_cast<std::size_t>(dim), 0.0);
                c.clamps.push_back(cl);
            }
    }
    if (j.clamp_bottom && !own_clamps) {
        OutletSpec cl;
        cl.key = "jet (bottom clamp)";
        cl.min = lo;
        cl.max = hi;
        for (std::size_t k = 0; k < cl.min.size(); ++k) cl.min[k] -= dx, cl.max[k] += dx;
        cl.max[V] = lo[V] + 0.5 * w;
        cl.velocity.assign(static_cast<std::size_t>(dim), 0.0);
        c.clamps.push_back(cl);
    }
    {
        // Between the outlets, in whole spacings from the specimen's edges: the profile's bins are then
        // centred on the lattice's columns (analysis::analyse_crater). In 3D the map also spans y. (On a
        // symmetry plane the crater analysis mirrors it: modules/crater_table.)
        const double inset = std::round(w / dx) * dx;
        JetSpec::Crater crater;
        crater.surface = surface;
        crater.x_min = lo[0] + inset;
        crater.x_max = hi[0] - inset;
        if (dim == 3) {
            crater.y_min = lo[1] + inset;
            crater.y_max = hi[1] - inset;
        }
        j.crater = crater;
    }
    if (c.abrasive.enabled) build_abrasive(c, c.inlets.back(), j.diameter);
}

}  // namespace grit::io
