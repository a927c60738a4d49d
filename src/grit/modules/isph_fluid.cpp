// The incompressible SPH module: predict, project, correct (Cummins & Rudman
// 1999).
#include "grit/modules/isph_fluid.hpp"

#include <cmath>
#include <limits>

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include "grit/domain/particle_id.hpp"
#include "grit/io/hdf5_file.hpp"
#include "grit/modules/coupling.hpp"
#include "grit/parallel/parallel.hpp"

namespace grit::modules {

namespace {
constexpr double force_coefficient = 0.25;  ///< of the force condition dt <= C sqrt(h / |a|)
}  // namespace

template <int Dim>
IsphModule<Dim>::IsphModule(sim::State<Dim>& state, const sim::RunSetup<Dim>& setup) : state_(state), setup_(setup) {
    const auto& spec = setup.spec;
    viscous_.gravity = core::to_vec<Dim>(spec.gravity);
    viscous_.hydrostatic_gravity = viscous_.gravity;
    viscous_.periodic_box = setup.periodic_box;
    viscous_.density_diffusion = 0.0;  // delta-SPH damps the acoustic noise of WCSPH: ISPH has none
    const double h = setup.smoothing_length;
    for (const auto& m : spec.materials) {
        viscous_.materials.push_back({m.sound_speed(), m.reference_density(), m.artificial_viscosity_alpha,
                                      m.artificial_viscosity_beta, m.dynamic_viscosity / m.reference_density()});
        // Monaghan's artificial viscosity acts as nu = alpha c0 h / (2 (D + 2));
        // its explicit limit 0.125 h^2 / nu bounds the step too (c0 is then only
        // the viscosity's velocity scale).
        const double nu = m.artificial_viscosity_alpha * m.sound_speed() * h / (2.0 * (Dim + 2));
        av_limit_.push_back(nu > 0.0 ? 0.125 * h * h / nu : std::numeric_limits<double>::infinity());
        projection_settings_.reference_density.push_back(m.reference_density());
    }
    projection_settings_.gravity = viscous_.gravity;
    projection_settings_.tolerance = spec.isph.tolerance;
    projection_settings_.max_iterations = spec.isph.max_iterations;
    projection_settings_.free_surface_divergence = spec.isph.free_surface_divergence;
    projection_settings_.density_relaxation = spec.isph.density_relaxation;
    projection_settings_.periodic_box = setup.periodic_box;
    projection_settings_.surface_offset = 0.5 * setup.spacing;
    shifting_.coefficient = spec.isph.shifting;
    shifting_.spacing = setup.spacing;
    shifting_.periodic_box = setup.periodic_box;
    spdlog::warn(
        "fluid.solver = \"isph\" is validated on the 2D and 3D tanks, the 2D dam break and a packed bed of "
        "grains; a grain settling in it overshoots its terminal velocity by 7 % (docs/validation.md, "
        "incompressible SPH)");
    // 1 on the particles the projection treats as free surface (p = 0 there), for ParaView.
    state_.particles.fields().template add<std::int32_t>("free_surface", 0, true, false);
}

template <int Dim>
void IsphModule<Dim>::initialise() {
    // Incompressible: every fluid and wall particle starts at its material's
    // reference density (the hydrostatic start of a block keeps its pressure, the
    // first guess of the first solve).
    auto& ps = state_.particles;
    double* rho = ps.density();
    double* rho_half = ps.density_half();
    const std::int32_t* ph = ps.phase();
    const std::int32_t* mat = ps.material();
    for (Index i = 0; i < ps.size(); ++i) {
        if (ph[i] != fluid_phase && ph[i] != wall_phase) continue;
        rho[i] = rho_half[i] = projection_settings_.reference_density[static_cast<std::size_t>(mat[i])];
    }
}

template <int Dim>
void IsphModule<Dim>::install(sim::Pipeline& pipeline) {
    using sim::Hook;
    pipeline.add(Hook::neighbors, "neighbors", [this] { update_neighbors(false); });
    pipeline.add(Hook::pre_force, "isph_prepare", [this] { prepare(); });
    pipeline.add(Hook::force, "isph_predict", [this] { predict(); });
    // After the forces between particle sets (post_force): the grains' reaction on the fluid (eq. 50)
    // is then in v* and the projection removes the divergence it drives within the step. Added
    // after the projection, the next one removed it only over the allowed step (0.4 ms against the
    // grain's 2.7 us steps in cases/sedimentation_3d), and the grain fell 20 % slower at first.
    pipeline.add(Hook::integrate, "pressure_solve", [this] { project(); });
    pipeline.add(Hook::integrate, "integrate_update", [this] { integrate(); });
}

template <int Dim>
void IsphModule<Dim>::prime() {
    update_neighbors(true);
}

template <int Dim>
void IsphModule<Dim>::update_neighbors(bool force) {
    const double skin = setup_.spec.neighbor_skin * setup_.smoothing_length;
    const double support = std::visit([](const auto& k) { return k.support(); }, setup_.kernel);
    state_.neighbors.update(state_.particles, support + skin, skin, force, setup_.periodic_box);
}

template <int Dim>
const double* IsphModule<Dim>::porosity() const {
    return CouplingModule<Dim>::porosity(state_.particles);
}

template <int Dim>
void IsphModule<Dim>::prepare() {
    auto& ps = state_.particles;
    if (const double* eps = porosity()) {
        // Grains coupled to the fluid: a particle carries the fluid mass of its mixture volume and
        // its density is the locally averaged one, rho_bar = eps rho0 (eq. 21), at this step's
        // porosity (the coupling's stage at the neighbours hook). The sums then read rho_bar as
        // WCSPH's do, and a grain moving in takes volume from the fluid around it.
        double* rho = ps.density();
        double* rho_half = ps.density_half();
        const std::int32_t* ph = ps.phase();
        const std::int32_t* mat = ps.material();
        const auto& rho0 = projection_settings_.reference_density;
        parallel::for_each(ps.size(), [&](Index i) {
            if (ph[i] != fluid_phase) return;
            rho[i] = rho_half[i] = eps[i] * rho0[static_cast<std::size_t>(mat[i])];
        });
    }
    sph::prepare_sph_workspace(ps, workspace_);
    // The predictor's sums carry no pressure: it comes from the projection.
    std::fill(workspace_.pressure_term.begin(), workspace_.pressure_term.end(), 0.0);
    if (setup_.spec.kernel_correction)
        sph::compute_gradient_correction(ps, state_.neighbors.list(), setup_.kernel, setup_.periodic_box, Phase::fluid,
                                         sph::phase_bit(Phase::fluid) | sph::phase_bit(Phase::wall), correction_);
}

template <int Dim>
void IsphModule<Dim>::predict() {
    // The predictor's acceleration: g + viscous terms (no pressure).
    sph::compute_fluid_rates(state_.particles, state_.neighbors.list(), setup_.kernel, viscous_, workspace_, pairs_,
                             nullptr, correction_.empty() ? nullptr : correction_.data());
}

template <int Dim>
void IsphModule<Dim>::project() {
    // v* = v^n + dt a, a the predictor's acceleration and what the stages since added to it (the
    // grains' reaction).
    auto& ps = state_.particles;
    {
        const Index n = ps.size();
        const double dt = state_.clock.dt;
        const auto* v = ps.velocity();
        const auto* a = ps.acceleration();
        const std::int32_t* ph = ps.phase();
        v_star_.resize(static_cast<std::size_t>(n));
        // The walls take g dt too: their pressure (Adami et al. 2012) carries rho g . x_wf, which
        // holds the fluid against gravity; a wall at v in the divergence asked for that support a
        // second time, and the tank's bottom row rose 1.8 mm off the wall in the first 0.05 s.
        const auto g_dt = viscous_.gravity * dt;
        parallel::for_each(n, [&](Index i) {
            auto& vs = v_star_[static_cast<std::size_t>(i)];
            vs = ph[i] == fluid_phase ? v[i] + a[i] * dt : ph[i] == wall_phase ? v[i] + g_dt : v[i];
        });
        // A mirror image's v* is its source's, mirrored (its own sums end in the images).
        state_.ghosts.forward(v_star_.data());
    }
    const auto& nl = state_.neighbors.list();
    const auto* L = correction_.empty() ? nullptr : correction_.data();
    auto& surface = ps.fields().template get<std::int32_t>("free_surface");
    // The carried divergence and the density invariance go over ISPH's own step, not a shorter one
    // the grains impose: removing the carried divergence at each DEM step (80 per fluid step in the
    // sloshing tank) blew the tank up within 7 ms, the invariance (~ 1/tau^2) on it within 5 ms
    // (docs/theory.md).
    last_ = projection_.solve(ps, nl, setup_.kernel, projection_settings_, v_star_.data(), L, state_.clock.dt,
                              std::max(state_.clock.dt, relaxation_dt_), surface.data(), porosity(), &state_.ghosts);
    ++solves_;
    iterations_total_ += last_.iterations;
    if (last_.restarted) ++restarts_;
    if (last_.bad_row >= 0) {
        const Index a = last_.bad_row;
        failure_ = fmt::format(
            "the pressure Poisson system has a non-finite entry in the row of the {} particle with id {} ({}; "
            "density {:g}, position ({}))",
            ps.phase()[a] == fluid_phase ? "fluid" : "wall", ps.id()[a], domain::describe_id(ps.id()[a]), ps.density()[a],
            fmt::join(ps.position()[a].c, ps.position()[a].c + Dim, ", "));
        return;
    }
    if (!last_.converged) {
        failure_ = fmt::format(
            "the pressure Poisson solve did not converge: relative residual {:.3g} "
            "after {} "
            "iterations (isph.tolerance = {:g}, isph.max_iterations = {})",
            last_.residual, last_.iterations, setup_.spec.isph.tolerance, setup_.spec.isph.max_iterations);
        return;
    }
    // A surface particle whose neighbours fill less than a quarter of the kernel's moments (det L_a
    // > 4: the tip of the dam break's surge) keeps the plain gradient: its L_a amplified the
    // pressure jump across the surge front into accelerations of 1e4 m/s^2.
    if (L)
        parallel::for_each(ps.size(), [&](Index i) {
            auto& c = correction_[static_cast<std::size_t>(i)];
            const bool surface_particle = surface[static_cast<std::size_t>(i)] != 0;
            if (surface_particle && c.determinant() > projection_settings_.max_surface_correction)
                c = sph::GradientCorrection<Dim>::identity();
        });
    // Kept apart from the particles' acceleration, which holds the predictor's (gravity and
    // viscosity) for the time step: the pressure acceleration of a projection is not a force the
    // step must resolve. It removes whatever divergence the step starts with, so it grows as the
    // step shrinks, and a force-limited step (C sqrt(h/|a|)) fed on it collapsed to 1e-5 s and
    // ran away in the dam break.
    sph::pressure_acceleration(ps, nl, setup_.kernel, setup_.periodic_box, L, pressure_acc_);
}

template <int Dim>
void IsphModule<Dim>::integrate() {
    // v^(n+1) = v* - dt grad p / rho; x^(n+1) = x^n + dt v^(n+1) (symplectic Euler). Not the
    // trapezoidal x^n + dt (v^n + v^(n+1)) / 2 used before: with the pressure taken at x^n it
    // amplifies an oscillation (a surface wave, a wall layer) by about 1 + (omega dt)^2 / 4 a step,
    // which held the step to 0.08 sqrt(h/g); this one is neutral up to omega dt = 2. The density
    // invariance then acts within the step it is asked for, as Asai et al. (2012) move the particles.
    // The density stays rho0: the particles carry no compression (a continuity
    // density drifted to 0.7 rho0 at the dam break's front, whose invariance term
    // then drove the pressure to oscillate; docs/theory.md).
    if (!failure_.empty()) return;  // the health check reports it with the last good state
    auto& ps = state_.particles;
    const Index n = ps.size();
    const double dt = state_.clock.dt;
    auto* x = ps.position();
    auto* v = ps.velocity();
    auto* v_half = ps.velocity_half();
    const std::int32_t* ph = ps.phase();
    const auto& box = setup_.periodic_box;
    parallel::for_each(n, [&](Index i) {
        if (ph[i] != fluid_phase) return;
        const auto k = static_cast<std::size_t>(i);
        const auto v_new = v_star_[k] + pressure_acc_[k] * dt;
        x[i] += v_new * dt;
        if (box.any()) x[i] = box.wrap(x[i]);
        v[i] = v_half[i] = v_new;
    });
    // The shift reads the moved positions of its neighbours, mirror images too.
    state_.ghosts.forward_positions(x);
    state_.ghosts.forward(v);
    state_.ghosts.forward(v_half);
    if (shifting_.coefficient > 0.0)
        sph::shift_particles(ps, state_.neighbors.list(), setup_.kernel, shifting_, dt,
                             ps.fields().template get<std::int32_t>("free_surface").data(), shift_);
}

template <int Dim>
double IsphModule<Dim>::stable_time_step() const {
    // No sound speed: the velocity CFL C_F h / |v|max, the force condition 0.25 sqrt(h / |a|max)
    // on the predictor's acceleration (gravity and viscosity, at least |g|; not the projection's),
    // and the viscous limits 0.125 h^2 / nu (laminar and artificial).
    const auto& ps = state_.particles;
    const double h = setup_.smoothing_length;
    const auto* v = ps.velocity();
    const auto* a = ps.fields().template get<core::Vec<Dim>>("acceleration").data();
    const std::int32_t* ph = ps.phase();
    struct Extremes {
        double v2, a2;
    };
    const Extremes e = parallel::reduce(
        ps.size(), Extremes{0.0, 0.0},
        [&](Index i) {
            if (ph[i] != fluid_phase) return Extremes{0.0, 0.0};
            return Extremes{core::norm2(v[i]), core::norm2(a[i])};
        },
        [](Extremes l, Extremes r) {
            return Extremes{std::max(l.v2, r.v2), std::max(l.a2, r.a2)};
        });
    const double inf = std::numeric_limits<double>::infinity();
    double dt = e.v2 > 0.0 ? setup_.spec.cfl * h / std::sqrt(e.v2) : inf;
    const double accel = std::max(std::sqrt(e.a2), core::norm(viscous_.gravity));
    // 0.25, WCSPH's: the hydrostatic tank (dx 1 cm) holds at rest for 10 s. With the trapezoidal
    // position update it held with 0.084 and blew up from the wall layers with 0.14 and 0.25
    // (docs/validation.md).
    if (accel > 0.0) dt = std::min(dt, force_coefficient * std::sqrt(h / accel));
    for (std::size_t m = 0; m < viscous_.materials.size(); ++m) {
        const double nu = viscous_.materials[m].kinematic_viscosity;
        if (nu > 0.0) dt = std::min(dt, 0.125 * h * h / nu);
        dt = std::min(dt, av_limit_[m]);
    }
    if (dt == inf) {  // at rest without gravity: the fastest wave of the materials
                      // sets the scale
        double c = 0.0;
        for (const auto& m : viscous_.materials)
            c = std::max(c, m.sound_speed);
        dt = setup_.spec.cfl * h / c;
    }
    // The carried divergence and the density invariance go over this step, also when a shorter one is
    // imposed (the grains', an output time). At rest the invariance's source is not zero under the
    // surface (it balances the Laplacian's error in the cut kernel there), so a tau that followed a
    // step cut for an output time moved that balance: the 3D tank's top rows sank at 10 mm/s in each
    // such step and its probes read 100 Pa low. Capped at 0.08 sqrt(h/|a|) before, for a settling
    // grain that stalled at 0.25 v_t; that stall was the walls' doubled support (IsphModule::project).
    relaxation_dt_ = dt;
    return dt;
}

template <int Dim>
void IsphModule<Dim>::save(io::Hdf5Group& group) const {
    group.write("solves", static_cast<std::int64_t>(solves_));
    group.write("restarts", static_cast<std::int64_t>(restarts_));
    group.write("iterations_total", iterations_total_);
    group.write("last_iterations", static_cast<std::int64_t>(last_.iterations));
    group.write("last_residual", last_.residual);
    group.write("last_surface_particles", static_cast<std::int64_t>(last_.surface_particles));
    group.write("relaxation_dt", relaxation_dt_);
}

template <int Dim>
void IsphModule<Dim>::load(const io::Hdf5Group& group) {
    if (!group.has_attribute("solves")) return;  // written before grit saved them: the means start afresh
    solves_ = static_cast<long>(group.read_int("solves"));
    restarts_ = static_cast<long>(group.read_int("restarts"));
    iterations_total_ = group.read_double("iterations_total");
    last_.iterations = static_cast<int>(group.read_int("last_iterations"));
    last_.residual = group.read_double("last_residual");
    last_.surface_particles = static_cast<Index>(group.read_int("last_surface_particles"));
    relaxation_dt_ = group.read_double("relaxation_dt");
}

template <int Dim>
std::string IsphModule<Dim>::check_health() const {
    return failure_;
}

template <int Dim>
void IsphModule<Dim>::output_values(std::vector<sim::OutputValue>& out) const {
    out.push_back(sim::OutputValue::count("pressure_iterations", last_.iterations, domain::Combine::same));
    out.push_back(sim::OutputValue::real("pressure_residual", last_.residual, domain::Combine::same));
    out.push_back(sim::OutputValue::count("free_surface_particles", static_cast<double>(last_.surface_particles), domain::Combine::sum));
    out.push_back(sim::OutputValue::count("pressure_restarts", static_cast<double>(restarts_), domain::Combine::same).summary_only());
    out.push_back(sim::OutputValue::real("pressure_iterations_mean",
                                         solves_ > 0 ? iterations_total_ / static_cast<double>(solves_) : 0.0, domain::Combine::same)
                      .summary_only());
}

template class IsphModule<2>;
template class IsphModule<3>;

}  // namespace grit::modules
