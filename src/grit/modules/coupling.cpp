// The fluid-grain coupling module: porosity stage, force exchange stage, outputs.
#include "grit/modules/coupling.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "grit/core/error.hpp"
#include "grit/parallel/parallel.hpp"

namespace grit::modules {

template <int Dim>
CouplingModule<Dim>::CouplingModule(sim::State<Dim>& state, const sim::RunSetup<Dim>& setup)
    : state_(state), setup_(setup), gravity_(core::to_vec<Dim>(setup.spec.gravity)) {
    const auto& spec = setup.spec;
    const material::Material* fluid = nullptr;
    for (const auto& m : spec.materials) {
        if (m.phase != Phase::fluid) continue;
        if (fluid)
            throw core::InputError(fmt::format(
                "[coupling]: the grains are coupled to one fluid material, and the case has two ('{}', '{}')",
                fluid->name, m.name));
        fluid = &m;
    }
    if (!fluid) throw core::InputError("[coupling]: the case has grains and SPH particles but no fluid material");
    if (!(fluid->dynamic_viscosity > 0.0))
        throw core::InputError(fmt::format("key 'materials.{}.dynamic_viscosity' = {}: the drag laws need a fluid "
                                           "viscosity > 0 [Pa s]",
                                           fluid->name, fluid->dynamic_viscosity));
    coupling::CouplingParameters p;
    p.radius_factor = spec.coupling.radius;
    p.drag = coupling::make_drag_law(spec.coupling.drag);
    p.min_porosity = spec.coupling.min_porosity;
    p.fluid_density = fluid->reference_density();
    p.viscosity = fluid->dynamic_viscosity;
    coupling_ = coupling::FluidGrainCoupling<Dim>(p, setup.kernel, setup.periodic_box);

    // A grain whose volume exceeds its kernel's reach drives the porosity at its centre below zero
    // (V_i W(0, h_c) > 1): the floor then hides it and the pressure of eq. (21) runs away. In 2D with the
    // cubic spline V W(0) = 10 / (7 k^2) for R_c = k d, 1.43 at k = 1.
    // The grains of the run: those at the start and the largest an abrasive feed brings.
    const auto& grains = state.grains->grains();
    std::vector<double> radii(grains.radius(), grains.radius() + grains.size());
    if (spec.abrasive.enabled)
        radii.push_back(0.5 * std::visit([](const auto& d) { return d.largest(); }, spec.abrasive.size));
    double worst = 0.0;
    for (const double r : radii) {
        const double h = 0.5 * p.radius_factor * 2.0 * r;
        const double w0 = std::visit([&](const auto& k) { return std::decay_t<decltype(k)>(h).value(0.0); }, setup.kernel);
        worst = std::max(worst, coupling::grain_volume<Dim>(r) * w0);
    }
    if (worst >= 1.0 - p.min_porosity)
        throw core::InputError(fmt::format(
            "key 'coupling.radius' = {}: too small for the grains: a grain's volume times the coupling kernel "
            "at its centre is {:.3g}, so the porosity there would fall below coupling.min_porosity = {} "
            "(use a radius of at least {:.2g} grain diameters)",
            p.radius_factor, worst, p.min_porosity,
            p.radius_factor * std::pow(worst / (1.0 - p.min_porosity), 1.0 / Dim) * 1.01));

    // A particle takes a grain at its nearest image: over a period shorter than two reaches it would
    // be within reach of two images of one grain.
    double largest_reach = 0.0;
    for (const double r : radii) largest_reach = std::max(largest_reach, p.radius_factor * 2.0 * r);
    for (int k = 0; k < Dim; ++k) {
        const double length = setup.periodic_box.length(k);
        if (setup.periodic_box.periodic[k] && !(length > 2.0 * largest_reach * (1.0 + 1e-12)))
            throw core::InputError(fmt::format(
                "key 'coupling.radius' = {}: the coupling reaches {:.3g} m from the largest grain, and the periodic "
                "axis {} is {:.3g} m long, not more than two reaches: a particle would be within reach of two "
                "periodic images of one grain (widen the domain, or use a smaller radius)",
                p.radius_factor, largest_reach, "xyz"[k], length));
    }

    // 0 marks a particle the coupling has not seen yet (update_porosity gives it its porosity).
    state.particles.fields().template add<double>(porosity_field, 0.0, true).set_output_scope(
        [](std::int32_t phase, std::int32_t) { return phase == static_cast<std::int32_t>(Phase::fluid); });
    auto& grain_fields = state.grains->grains().fields();
    grain_fields.template add<core::Vec<Dim>>("fluid_force", core::Vec<Dim>::zero(), true);
    grain_fields.template add<core::Vec<Dim>>("drag_force", core::Vec<Dim>::zero(), true);
}

template <int Dim>
void CouplingModule<Dim>::install(sim::Pipeline& pipeline) {
    // After the SPH lists (the particles are in their final order for the step) and before the
    // equation of state, which reads rho = rho_bar / eps.
    pipeline.add(sim::Hook::neighbors, "porosity", [this] { update_porosity(); }, true);
    // After the SPH sums (theta_a) and before the grains' step, which kicks with these forces.
    pipeline.add(sim::Hook::post_force, "fluid_grain_coupling", [this] { exchange(); });
}

template <int Dim>
void CouplingModule<Dim>::update_porosity() {
    auto& ps = state_.particles;
    coupling_.find_pairs(state_.grains->grains(), ps);
    pairs_generation_ = ps.generation();
    const Index n = ps.size();
    std::vector<double> eps(static_cast<std::size_t>(n));
    coupling_.compute_porosity(state_.grains->grains(), ps, eps.data());

    double* porosity = ps.fields().template get<double>(porosity_field).data();
    double* m = ps.fields().template get<double>("mass").data();
    double* rho = ps.fields().template get<double>("density").data();
    double* rho_half = ps.fields().template get<double>("density_half").data();
    const std::int32_t* phase = ps.phase();
    const auto fluid = static_cast<std::int32_t>(Phase::fluid);
    // A fluid particle new to the coupling holds fluid at its density in all of its volume m / rho; the
    // grains around it take (1 - eps) of that volume, so it keeps the fluid part: m and rho_bar = eps rho
    // (eq. 21). Fluid an inlet emitted into a grain's reach was booked in full as inflow: the part the
    // grain displaces is taken back.
    const double removed = parallel::sum(n, 0.0, [&](Index a) {
        if (phase[a] != fluid) {
            porosity[a] = 1.0;
            return 0.0;
        }
        const double e = eps[static_cast<std::size_t>(a)];
        const bool fresh = porosity[a] == 0.0;
        porosity[a] = e;
        if (!fresh || e == 1.0) return 0.0;
        const double taken = (1.0 - e) * m[a];
        m[a] *= e;
        rho[a] *= e;
        rho_half[a] *= e;
        return taken;
    });
    if (!priming_) state_.ledger.in -= removed;
    priming_ = false;
}

template <int Dim>
void CouplingModule<Dim>::exchange() {
    auto& ps = state_.particles;
    if (pairs_generation_ != ps.generation())
        throw std::logic_error("fluid-grain pairs used after the particle set changed");
    auto& grains = state_.grains->grains();
    auto& fields = grains.fields();
    coupling_.exchange_forces(grains, ps, ps.fields().template get<double>(porosity_field).data(),
                              fields.template get<core::Vec<Dim>>("fluid_force").data(),
                              fields.template get<core::Vec<Dim>>("drag_force").data());
}

template <int Dim>
void CouplingModule<Dim>::output_values(std::vector<sim::OutputValue>& out) const {
    using sim::OutputValue;
    const auto& ps = state_.particles;
    const double* porosity = ps.fields().template get<double>(porosity_field).data();
    const std::int32_t* phase = ps.phase();
    const auto fluid = static_cast<std::int32_t>(Phase::fluid);
    const double min_eps = parallel::reduce(
        ps.size(), 1.0, [&](Index a) { return phase[a] == fluid && porosity[a] > 0.0 ? porosity[a] : 1.0; },
        [](double x, double y) { return std::min(x, y); });
    out.push_back(OutputValue::real("min_porosity", min_eps, domain::Combine::min));

    // The grains' mean porosity (eq. 45) over those with fluid around them, and their mass-weighted
    // velocity along gravity: the settling velocity, whose last value is the terminal velocity of a
    // sedimentation case.
    const auto& grains = state_.grains->grains();
    const auto& gs = coupling_.grain_state();
    // Means are ratios of sums: each sub-domain's sums, added over all of them, then divided (the same on
    // every rank).
    std::vector<double> sums(5, 0.0);  // porosity, grains with fluid around, and the mass-weighted sums below
    double &eps_sum = sums[0], &eps_count = sums[1], &speed = sums[2], &settling = sums[3], &grain_mass = sums[4];
    for (std::size_t i = 0; i < gs.porosity.size(); ++i)
        if (gs.shepard[i] > 0.0) {
            eps_sum += gs.porosity[i];
            eps_count += 1.0;
        }
    const double g = core::norm(gravity_);
    const core::Vec<Dim> down = g > 0.0 ? gravity_ * (1.0 / g) : core::Vec<Dim>::zero();
    for (Index i = 0; i < grains.size(); ++i) {
        const double m = grains.mass()[i];
        speed += m * core::norm(grains.velocity()[i]);
        settling += m * core::dot(grains.velocity()[i], down);
        grain_mass += m;
    }
    setup_.comm.sum_each(sums);
    out.push_back(OutputValue::real("grain_porosity", eps_count > 0.0 ? eps_sum / eps_count
                                                                      : std::numeric_limits<double>::quiet_NaN(), domain::Combine::same));
    out.push_back(OutputValue::real("grain_speed", grain_mass > 0.0 ? speed / grain_mass : 0.0, domain::Combine::same).series_only());
    // A column whether or not grains are there yet (a feed that starts later, grains that all left).
    const double settling_velocity = grain_mass > 0.0 ? settling / grain_mass : std::numeric_limits<double>::quiet_NaN();
    if (g > 0.0) out.push_back(OutputValue::real("settling_velocity", settling_velocity, domain::Combine::same).series_only());
    if (g > 0.0 && grain_mass > 0.0)
        out.push_back(OutputValue::real("terminal_velocity", settling_velocity, domain::Combine::same).summary_only());
    out.push_back(OutputValue::real("contact_velocity", state_.impacts.first_speed(setup_.comm), domain::Combine::same).summary_only());
    out.push_back(OutputValue::count("coupling_pairs", static_cast<double>(coupling_.pair_count()), domain::Combine::sum).series_only());
    bed_values(out);
}

// A packed bed: the fixed grains and the fluid among them, the flow along the body force e = g / |g|.
// The bed is the box the fixed grains span (their centres +- radius) along open axes, the whole period
// along periodic ones. Over the fluid particles inside it, each of mixture volume V_a = m_a / rho_bar_a,
//   superficial velocity  U = sum_a V_a eps_a (v_a . e) / sum_a V_a   (the flow rate per bed section),
//   bed porosity          eps_bed = 1 - sum_i V_i / V_bed,
//   pressure gradient     the fluid force on the bed per unit fluid volume, sum_i F_i . e / (eps_bed V_bed).
// With a body force driving the flow, the steady fluid's balance eps rho g = beta u makes that gradient
// rho_f |g|, the pressure drop an equal bed would need without the body force (docs/validation.md).
template <int Dim>
void CouplingModule<Dim>::bed_values(std::vector<sim::OutputValue>& out) const {
    using sim::OutputValue;
    const auto& grains = state_.grains->grains();
    const std::int32_t* fixed = dem::fixed_flags(grains);
    const double g = core::norm(gravity_);
    if (!fixed || !(g > 0.0)) return;
    const core::Vec<Dim> e = gravity_ * (1.0 / g);
    const auto& box = setup_.periodic_box;
    core::Vec<Dim> lo = core::Vec<Dim>::zero(), hi = core::Vec<Dim>::zero();
    for (int k = 0; k < Dim; ++k) {
        lo[k] = box.periodic[k] ? box.lower[k] : 1e300;
        hi[k] = box.periodic[k] ? box.upper[k] : -1e300;
    }
    std::vector<double> sums(4, 0.0);  // the fixed grains' volume and force along e; the fluid's flux and volume
    double &solid = sums[0], &force = sums[1], &flux = sums[2], &volume = sums[3];
    const auto* fluid_force = grains.fields().template get<core::Vec<Dim>>("fluid_force").data();
    for (Index i = 0; i < grains.size(); ++i) {
        if (!fixed[i]) continue;
        const double r = grains.radius()[i];
        for (int k = 0; k < Dim; ++k)
            if (!box.periodic[k]) {
                lo[k] = std::min(lo[k], grains.position()[i][k] - r);
                hi[k] = std::max(hi[k], grains.position()[i][k] + r);
            }
        solid += coupling::grain_volume<Dim>(r);
        force += core::dot(fluid_force[i], e);
    }
    // The bed's box over every sub-domain's fixed grains: the largest -lo and hi.
    std::vector<double> extent(2 * Dim);
    for (int k = 0; k < Dim; ++k) {
        extent[static_cast<std::size_t>(k)] = -lo[k];
        extent[static_cast<std::size_t>(Dim + k)] = hi[k];
    }
    setup_.comm.max_each(extent);
    for (int k = 0; k < Dim; ++k) {
        lo[k] = -extent[static_cast<std::size_t>(k)];
        hi[k] = extent[static_cast<std::size_t>(Dim + k)];
    }
    double bed_volume = 1.0;
    for (int k = 0; k < Dim; ++k) bed_volume *= hi[k] - lo[k];
    if (!(bed_volume > 0.0)) return;
    const auto& ps = state_.particles;
    const double* porosity = ps.fields().template get<double>(porosity_field).data();
    const std::int32_t* phase = ps.phase();
    const auto fluid = static_cast<std::int32_t>(Phase::fluid);
    for (Index a = 0; a < ps.size(); ++a) {
        if (phase[a] != fluid) continue;
        bool inside = true;
        for (int k = 0; k < Dim; ++k) inside &= ps.position()[a][k] >= lo[k] && ps.position()[a][k] <= hi[k];
        if (!inside) continue;
        const double v = ps.mass()[a] / ps.density()[a];
        flux += v * porosity[a] * core::dot(ps.velocity()[a], e);
        volume += v;
    }
    setup_.comm.sum_each(sums);
    const double eps = 1.0 - solid / bed_volume;
    out.push_back(OutputValue::real("superficial_velocity", volume > 0.0 ? flux / volume : 0.0, domain::Combine::same));
    out.push_back(OutputValue::real("pressure_gradient", force / (eps * bed_volume), domain::Combine::same));
    out.push_back(OutputValue::real("bed_porosity", eps, domain::Combine::same));
}

template class CouplingModule<2>;
template class CouplingModule<3>;

}  // namespace grit::modules
