// The SPH module: integrator, neighbour lists, fluid pressure and sums, CFL time step.
#include "grit/modules/sph_fluid.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>
#include <type_traits>

#include "grit/boundary/wall_pressure.hpp"
#include "grit/modules/coupling.hpp"
#include "grit/parallel/parallel.hpp"
#include "grit/sph/pressure.hpp"
#include "grit/sph/shepard_filter.hpp"

namespace grit::modules {

template <int Dim>
SphModule<Dim>::SphModule(sim::State<Dim>& state, const sim::RunSetup<Dim>& setup) : state_(state), setup_(setup) {
    const auto& spec = setup.spec;
    fluid_.gravity = core::to_vec<Dim>(spec.gravity);
    // Along a periodic axis the pressure is periodic too: the body force there is not balanced by a
    // hydrostatic pressure gradient, so the hydrostatic parts of the density diffusion and of the wall
    // pressure take only the components along open axes (all of g without periodic axes).
    fluid_.hydrostatic_gravity = fluid_.gravity;
    for (int k = 0; k < Dim; ++k)
        if (setup.periodic_box.periodic[k]) fluid_.hydrostatic_gravity[k] = 0.0;
    fluid_.periodic_box = setup.periodic_box;
    fluid_.density_diffusion = spec.density_diffusion;
    for (const auto& m : spec.materials) {
        fluid_.materials.push_back({m.sound_speed(), m.reference_density(), m.artificial_viscosity_alpha,
                                    m.artificial_viscosity_beta, m.dynamic_viscosity / m.reference_density()});
        // The time step of a solid follows its longitudinal wave, not the bulk c0: with c0, the free
        // edges of a sandstone bar in tension rang and blew up at C_F = 0.2 (docs/theory.md).
        signal_speed_.push_back(m.signal_speed());
    }
}

template <int Dim>
void SphModule<Dim>::install(sim::Pipeline& pipeline) {
    using sim::Hook;
    auto& ps = state_.particles;
    pipeline.add(Hook::begin_step, "integrate_predict", [this] { integrate_predict(); });
    pipeline.add(Hook::neighbors, "neighbors", [this] { update_neighbors(false); });
    if (setup_.spec.shepard_interval > 0) pipeline.add(Hook::neighbors, "shepard_filter", [this] { shepard_filter(); });
    pipeline.add(Hook::pressure, "equation_of_state", [this, &ps] {
        sph::update_pressure(ps, setup_.spec.materials, Phase::fluid, nullptr, porosity());
    }, true);
    pipeline.add(Hook::pre_force, "wall_pressure", [this, &ps] {
        boundary::update_wall_pressure(ps, state_.neighbors.list(), setup_.kernel, fluid_.hydrostatic_gravity,
                                       setup_.spec.materials, setup_.periodic_box);
    }, true);
    pipeline.add(Hook::pre_force, "sph_prepare", [this, &ps] {
        sph::prepare_sph_workspace(ps, workspace_);
        if (setup_.spec.kernel_correction)
            sph::compute_gradient_correction(ps, state_.neighbors.list(), setup_.kernel, setup_.periodic_box,
                                             Phase::fluid, sph::phase_bit(Phase::fluid) | sph::phase_bit(Phase::wall) |
                                                               sph::phase_bit(Phase::solid),
                                             correction_);
        workspace_generation_ = ps.generation();
    }, true);
    pipeline.add(Hook::force, "sph_fluid", [this, &ps] {
        sph::compute_fluid_rates(ps, state_.neighbors.list(), setup_.kernel, fluid_, workspace(), pairs_, porosity(),
                                 correction_.empty() ? nullptr : correction_.data());
    }, true);
    pipeline.add(Hook::integrate, "integrate_update", [this] { integrate_update(); });
}

template <int Dim>
const double* SphModule<Dim>::porosity() const {
    return CouplingModule<Dim>::porosity(state_.particles);
}

template <int Dim>
void SphModule<Dim>::prime() {
    update_neighbors(true);
}

template <int Dim>
const sph::SphWorkspace& SphModule<Dim>::workspace() const {
    // Scratch outside the registry: valid only while no particle was added, removed or reordered.
    if (workspace_generation_ != state_.particles.generation())
        throw std::logic_error("SPH workspace read after the particle set changed");
    return workspace_;
}

template <int Dim>
void SphModule<Dim>::update_neighbors(bool force) {
    const double skin = setup_.spec.neighbor_skin * setup_.smoothing_length;
    const double support = std::visit([](const auto& k) { return k.support(); }, setup_.kernel);
    state_.neighbors.update(state_.particles, support + skin, skin, force, setup_.periodic_box);
}

template <int Dim>
void SphModule<Dim>::shepard_filter() {
    if (state_.clock.step == 0 || state_.clock.step % setup_.spec.shepard_interval != 0) return;
    auto& ps = state_.particles;
    sph::shepard_density(ps, state_.neighbors.list(), setup_.kernel, setup_.periodic_box, shepard_);
    double* rho = ps.density();
    double* rho_half = ps.density_half();
    const std::int32_t* ph = ps.phase();
    const auto fluid = static_cast<std::int32_t>(Phase::fluid);
    const double* filtered = shepard_.data();
    parallel::for_each(ps.size(), [&](Index i) {
        if (ph[i] != fluid) return;
        rho_half[i] += filtered[i] - rho[i];
        rho[i] = filtered[i];
    });
}

// Leap-frog (Liu & Liu 2003, the scheme of the first seed paper): positions at whole steps, velocity
// and density at half steps. The sums read velocity and density predicted to the whole step,
//   v^n = v^(n-1/2) + dt/2 a^(n-1),  rho^n = rho^(n-1/2) + dt/2 drho^(n-1),
// then  v^(n+1/2) = v^(n-1/2) + dt a^n,  rho^(n+1/2) = rho^(n-1/2) + dt drho^n,  x^(n+1) = x^n + dt v^(n+1/2).
// The first step starts the half-step values with dt/2. Density and position are thus evaluated at the
// same instant; a kick-drift-kick update that reads rho^(n+1/2) at x^(n+1) grows free-surface
// oscillations at C_F = 0.2 (measured: docs/theory.md).
template <int Dim>
void SphModule<Dim>::integrate_predict() {
    if (state_.clock.step == 0) return;
    auto& ps = state_.particles;
    const double half = 0.5 * state_.clock.dt;
    auto* v = ps.velocity();
    double* rho = ps.density();
    const auto* v_half = ps.velocity_half();
    const double* rho_half = ps.density_half();
    const auto* a = ps.acceleration();
    const double* drho = ps.density_rate();
    const std::int32_t* ph = ps.phase();
    const std::int32_t* fixed = ps.fields().has("fixed") ? ps.fields().template get<std::int32_t>("fixed").data() : nullptr;
    const auto fluid = static_cast<std::int32_t>(Phase::fluid), solid = static_cast<std::int32_t>(Phase::solid);
    parallel::for_each(ps.size(), [&](Index i) {
        if (ph[i] != fluid && ph[i] != solid) return;
        rho[i] = rho_half[i] + drho[i] * half;
        if (fixed && fixed[i]) return;  // clamped solids keep their prescribed velocity
        v[i] = v_half[i] + a[i] * half;
    });
}

template <int Dim>
void SphModule<Dim>::integrate_update() {
    auto& ps = state_.particles;
    const double dt = state_.clock.dt;
    const double kick = state_.clock.step == 0 ? 0.5 * dt : dt;
    auto* x = ps.position();
    auto* v = ps.velocity();
    double* rho = ps.density();
    auto* v_half = ps.velocity_half();
    double* rho_half = ps.density_half();
    const auto* a = ps.acceleration();
    const double* drho = ps.density_rate();
    const std::int32_t* ph = ps.phase();
    const std::int32_t* fixed = ps.fields().has("fixed") ? ps.fields().template get<std::int32_t>("fixed").data() : nullptr;
    const auto fluid = static_cast<std::int32_t>(Phase::fluid), solid = static_cast<std::int32_t>(Phase::solid);
    // Along periodic axes a particle leaving through a face comes back through the opposite one. The
    // loop is compiled twice: the one without periodic axes is the loop as it was before them (a run-time
    // test in it changed how the compiler fused x + v dt, and with it the last bits of every result).
    const auto& box = setup_.periodic_box;
    auto update = [&](auto periodic) {
        parallel::for_each(ps.size(), [&](Index i) {
            if (ph[i] != fluid && ph[i] != solid) return;
            rho_half[i] += drho[i] * kick;
            // Between steps, velocity and density show the half-step state (outputs, diagnostics).
            rho[i] = rho_half[i];
            if (fixed && fixed[i]) {  // clamped: moves at its prescribed velocity
                x[i] += v_half[i] * dt;
                if constexpr (decltype(periodic)::value) x[i] = box.wrap(x[i]);
                return;
            }
            v_half[i] += a[i] * kick;
            x[i] += v_half[i] * dt;
            if constexpr (decltype(periodic)::value) x[i] = box.wrap(x[i]);
            v[i] = v_half[i];
        });
    };
    if (box.any())
        update(std::true_type{});
    else
        update(std::false_type{});
}

template <int Dim>
double SphModule<Dim>::stable_time_step() const {
    // Eq. (51): dt = C_F min_a h / (c_a + |v_a|), with Monaghan's force condition 0.25 sqrt(h/|a|) and
    // the viscous condition 0.125 h^2 / nu.
    const auto& ps = state_.particles;
    const double h = setup_.smoothing_length;
    const auto* v = ps.velocity();
    const auto* a = ps.fields().template get<core::Vec<Dim>>("acceleration").data();
    const std::int32_t* ph = ps.phase();
    const std::int32_t* mat = ps.material();
    const auto fluid = static_cast<std::int32_t>(Phase::fluid), solid = static_cast<std::int32_t>(Phase::solid);
    const double* signal = signal_speed_.data();
    const double huge = std::numeric_limits<double>::max();
    struct Limits {
        double cfl, accel2;
    };
    const Limits lim = parallel::reduce(
        ps.size(), Limits{huge, 0.0},
        [&](Index i) {
            if (ph[i] != fluid && ph[i] != solid) return Limits{huge, 0.0};
            return Limits{h / (signal[mat[i]] + core::norm(v[i])), core::norm2(a[i])};
        },
        [](Limits x, Limits y) { return Limits{std::min(x.cfl, y.cfl), std::max(x.accel2, y.accel2)}; });
    const auto& spec = setup_.spec;
    if (lim.cfl >= huge) {
        // No fluid yet (an inlet that has not started): step by the fastest speed in the case.
        return spec.inlets.empty() ? std::numeric_limits<double>::infinity() : spec.cfl * h / setup_.max_speed;
    }
    double dt = spec.cfl * lim.cfl;
    if (lim.accel2 > 0.0) dt = std::min(dt, 0.25 * std::sqrt(h / std::sqrt(lim.accel2)));
    for (const auto& c : fluid_.materials)
        if (c.kinematic_viscosity > 0.0) dt = std::min(dt, 0.125 * h * h / c.kinematic_viscosity);
    return dt;
}

template class SphModule<2>;
template class SphModule<3>;

}  // namespace grit::modules
