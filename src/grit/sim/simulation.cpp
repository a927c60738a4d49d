// A run of one case: set-up from the case spec, the step pipeline, outputs and blow-up handling.
#include "grit/sim/simulation.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>

#include "grit/analysis/crater.hpp"
#include "grit/analysis/probes.hpp"
#include "grit/boundary/wall_pressure.hpp"
#include "grit/core/error.hpp"
#include "grit/io/vtu_writer.hpp"
#include "grit/parallel/parallel.hpp"
#include "grit/sim/geometry.hpp"
#include "grit/sim/progress.hpp"
#include "grit/sph/pressure.hpp"

namespace grit::sim {

namespace {

using core::to_vec;

template <int Dim>
bool inside(const core::Vec<Dim>& x, const std::vector<double>& lo, const std::vector<double>& hi) {
    for (int k = 0; k < Dim; ++k)
        if (x[k] < lo[static_cast<std::size_t>(k)] || x[k] > hi[static_cast<std::size_t>(k)]) return false;
    return true;
}

const char* phase_name(std::int32_t p) {
    switch (static_cast<Phase>(p)) {
        case Phase::fluid: return "fluid";
        case Phase::solid: return "solid";
        case Phase::wall: return "wall";
        case Phase::grain: return "grain";
    }
    return "unknown";
}

}  // namespace

template <int Dim>
Simulation<Dim>::Simulation(io::CaseSpec spec, RunOptions options)
    : spec_(std::move(spec)),
      options_(std::move(options)),
      kernel_(sph::CubicSpline<Dim>(1.0)),
      spacing_(spec_.particle_spacing),
      smoothing_length_(spec_.smoothing_ratio * spec_.particle_spacing) {
    if (spec_.dimension != Dim) throw std::logic_error("case dimension does not match the simulation");
    sph::make_kernel<Dim>(spec_.kernel, smoothing_length_, kernel_);

    fluid_parameters_.gravity = to_vec<Dim>(spec_.gravity);
    fluid_parameters_.density_diffusion = spec_.density_diffusion;
    double fastest = 0.0;
    for (const auto& m : spec_.materials) {
        fluid_parameters_.materials.push_back({m.sound_speed(), m.reference_density(), m.artificial_viscosity_alpha,
                                               m.artificial_viscosity_beta,
                                               m.dynamic_viscosity / m.reference_density()});
        // The time step of a solid follows its fastest wave, the longitudinal one,
        // c_L = sqrt(c0^2 + 4G / (3 rho0)), not the bulk c0 (up to 1.4x slower for rock): with c0, the
        // free edges of a sandstone bar in tension rang and blew up at C_F = 0.2 (docs/theory.md).
        const double c_l = m.phase == Phase::solid
                               ? std::sqrt(m.sound_speed() * m.sound_speed() +
                                           4.0 * m.solid.shear_modulus / (3.0 * m.reference_density()))
                               : m.sound_speed();
        signal_speed_.push_back(c_l);
        fastest = std::max(fastest, c_l);
    }
    for (const auto& in : spec_.inlets) fastest = std::max(fastest, in.velocity);
    max_speed_ = spec_.max_speed > 0.0 ? spec_.max_speed : 2.0 * fastest;
    domain_min_ = to_vec<Dim>(spec_.domain_min);
    domain_max_ = to_vec<Dim>(spec_.domain_max);

    has_solids_ = !spec_.solids.empty();
    for (const auto& m : spec_.materials) brittle_.push_back(std::holds_alternative<material::JH2>(m.solid_model));
    solid_parameters_.gravity = fluid_parameters_.gravity;
    solid_parameters_.artificial_stress = spec_.artificial_stress;
    solid_parameters_.spacing = spacing_;
    solid_parameters_.materials = fluid_parameters_.materials;
    if (has_solids_) register_solid_fields();

    build_particles();
    if (!spec_.grains.empty()) grains_ = std::make_unique<GrainPhase<Dim>>(spec_);
    for (const auto& in : spec_.inlets) {
        const auto& m = spec_.materials[static_cast<std::size_t>(in.material)];
        inlets_.emplace_back(in, spacing_, m.reference_density(), m.reference_density() * std::pow(spacing_, Dim));
    }
    has_sph_ = particles_.size() > 0 || !inlets_.empty();
    build_pipeline();
}

template <int Dim>
void Simulation<Dim>::build_particles() {
    const double dx = spacing_;
    const double cell_volume = std::pow(dx, Dim);
    const Vec g = to_vec<Dim>(spec_.gravity);
    const double g_norm = core::norm(g);

    auto add_block = [&](const io::BlockSpec& b, Phase phase) {
        const auto points = lattice_points<Dim>(b.shape, dx);
        if (points.empty())
            throw core::InputError(fmt::format("{}: the shape holds no particle at numerics.particle_spacing = {} m",
                                               b.key, dx));
        const auto& mat = spec_.materials[static_cast<std::size_t>(b.material)];
        const double rho0 = mat.reference_density();
        // Hydrostatic start: p = rho0 |g| depth below the block's free surface (its highest point).
        double top = 0.0;
        if (b.hydrostatic && g_norm > 0.0) {
            top = -1e300;
            for (const auto& x : points) top = std::max(top, -core::dot(g, x) / g_norm);
            top += 0.5 * dx;
        }
        const Index first = particles_.append(static_cast<Index>(points.size()));
        Vec* x = particles_.position();
        Vec* v = particles_.velocity();
        double* rho = particles_.density();
        double* p = particles_.pressure();
        double* m = particles_.mass();
        std::int32_t* ph = particles_.phase();
        std::int32_t* mi = particles_.material();
        Vec* v_half = particles_.velocity_half();
        double* rho_half = particles_.density_half();
        for (std::size_t k = 0; k < points.size(); ++k) {
            const Index i = first + static_cast<Index>(k);
            x[i] = points[k];
            v[i] = phase != Phase::wall ? to_vec<Dim>(b.velocity) : Vec::zero();
            if (b.velocity_profile == "cantilever_mode") {
                // First bending mode of a clamped-free beam, k L = 1.875 (Gray, Monaghan & Swift 2001):
                // W(s) = cosh ks - cos ks - sigma (sinh ks - sin ks), sigma = (cosh kL + cos kL) /
                // (sinh kL + sin kL), s = x - x0; v_y = V W(s) / W(L).
                const double kl = 1.87510407, wavenumber = kl / b.mode_length;
                const double sigma = (std::cosh(kl) + std::cos(kl)) / (std::sinh(kl) + std::sin(kl));
                auto mode = [&](double s) {
                    const double ks = wavenumber * std::clamp(s, 0.0, b.mode_length);
                    return std::cosh(ks) - std::cos(ks) - sigma * (std::sinh(ks) - std::sin(ks));
                };
                v[i][1] += b.mode_tip_velocity * mode(points[k][0] - b.mode_origin) / mode(b.mode_length);
            }
            v_half[i] = v[i];
            p[i] = 0.0;
            if (b.hydrostatic && g_norm > 0.0) p[i] = rho0 * g_norm * (top - (-core::dot(g, points[k]) / g_norm));
            rho[i] = material::density_from_pressure(mat.eos, p[i]);
            rho_half[i] = rho[i];
            m[i] = rho0 * cell_volume;
            ph[i] = static_cast<std::int32_t>(phase);
            mi[i] = b.material;
        }
    };
    for (const auto& f : spec_.fluids) add_block(f, Phase::fluid);
    const Index first_solid = particles_.size();
    for (const auto& s : spec_.solids) add_block(s, Phase::solid);
    for (const auto& w : spec_.walls) add_block(w, Phase::wall);
    if (has_solids_) {
        // Solids start at their room temperature; clamp boxes hold the solid particles inside them.
        auto& temperature = particles_.fields().template get<double>("temperature");
        auto& fixed = particles_.fields().template get<std::int32_t>("fixed");
        const Vec* xs = particles_.position();
        for (Index i = first_solid; i < particles_.size(); ++i) {
            if (particles_.phase()[i] != static_cast<std::int32_t>(Phase::solid)) continue;
            temperature[i] = spec_.materials[static_cast<std::size_t>(particles_.material()[i])].solid.room_temperature;
            for (const auto& c : spec_.clamps)
                if (inside<Dim>(xs[i], c.min, c.max)) {
                    fixed[i] = 1;
                    particles_.velocity()[i] = to_vec<Dim>(c.velocity);
                    particles_.velocity_half()[i] = to_vec<Dim>(c.velocity);
                }
        }
        for (const auto& c : spec_.clamps) {
            bool any = false;
            for (Index i = first_solid; i < particles_.size() && !any; ++i) any = fixed[i] && inside<Dim>(xs[i], c.min, c.max);
            if (!any) throw core::InputError(fmt::format("{}: the clamp box holds no solid particle", c.key));
        }
    }

    const Vec* x = particles_.position();
    for (Index i = 0; i < particles_.size(); ++i)
        if (!inside<Dim>(x[i], spec_.domain_min, spec_.domain_max))
            throw core::InputError(fmt::format(
                "key 'domain.min'/'domain.max': a {} particle at ({}) lies outside the domain; enlarge the domain",
                phase_name(particles_.phase()[i]),
                fmt::join(std::vector<double>(x[i].c, x[i].c + Dim), ", ")));
}

template <int Dim>
void Simulation<Dim>::build_pipeline() {
    if (!has_sph_) {
        // Grains only: the DEM step, checks and the time step.
        pipeline_.add("grain_motion", [this] { grains_->advance(time_, dt_, step_ == 0); });
        pipeline_.add("health_check", [this] { check_health(); });
        pipeline_.add("time_step", [this] { compute_time_step(); });
        return;
    }
    pipeline_.add("integrate_predict", [this] { integrate_predict(); });
    pipeline_.add("boundaries", [this] { apply_boundaries(); });
    pipeline_.add("neighbors", [this] { update_neighbors(false); });
    pipeline_.add("equation_of_state", [this] {
        sph::update_pressure(particles_, spec_.materials, Phase::fluid);
        if (has_solids_) {
            sph::update_pressure(particles_, spec_.materials, Phase::solid,
                                 particles_.fields().template get<double>("specific_energy").data());
            apply_brittle_pressure();
        }
    });
    pipeline_.add("wall_pressure", [this] {
        boundary::update_wall_pressure(particles_, neighbors_, kernel_, fluid_parameters_.gravity, spec_.materials);
    });
    pipeline_.add("sph_prepare", [this] { sph::prepare_sph_workspace(particles_, sph_workspace_); });
    pipeline_.add("sph_fluid", [this] { sph::compute_fluid_rates(particles_, neighbors_, kernel_, fluid_parameters_, sph_workspace_); });
    if (has_solids_) {
        pipeline_.add("sph_solid", [this] {
            sph::compute_solid_rates(particles_, neighbors_, kernel_, solid_parameters_, sph_workspace_,
                                     solid_workspace_);
        });
    }
    if (grains_) {
        // Grains and SPH solids/walls push each other at the state the SPH sums saw (eqs. 12-14); then
        // the grains take their step with the same dt.
        pipeline_.add("grain_contact", [this] {
            const std::int32_t* fixed =
                has_solids_ ? particles_.fields().template get<std::int32_t>("fixed").data() : nullptr;
            grains_->couple(time_, particles_, fixed, dt_stable_, spec_.materials);
        });
        pipeline_.add("grain_motion", [this] { grains_->advance(time_, dt_, step_ == 0); });
    }
    pipeline_.add("integrate_update", [this] { integrate_update(); });
    if (has_solids_) {
        pipeline_.add("solid_stress", [this] { update_solid_stress(); });
        pipeline_.add("erosion", [this] { remove_failed_solids(); });
    }
    pipeline_.add("health_check", [this] { check_health(); });
    pipeline_.add("time_step", [this] { compute_time_step(); });
}

// Leap-frog (Liu & Liu 2003, the scheme of the first seed paper): positions at whole steps, velocity
// and density at half steps. The sums read velocity and density predicted to the whole step,
//   v^n = v^(n-1/2) + dt/2 a^(n-1),  rho^n = rho^(n-1/2) + dt/2 drho^(n-1),
// then  v^(n+1/2) = v^(n-1/2) + dt a^n,  rho^(n+1/2) = rho^(n-1/2) + dt drho^n,  x^(n+1) = x^n + dt v^(n+1/2).
// The first step starts the half-step values with dt/2. Density and position are thus evaluated at the
// same instant; a kick-drift-kick update that reads rho^(n+1/2) at x^(n+1) grows free-surface
// oscillations at C_F = 0.2 (measured: docs/theory.md).
template <int Dim>
void Simulation<Dim>::integrate_predict() {
    if (step_ == 0) return;
    const double half = 0.5 * dt_;
    Vec* v = particles_.velocity();
    double* rho = particles_.density();
    const Vec* v_half = particles_.velocity_half();
    const double* rho_half = particles_.density_half();
    const Vec* a = particles_.acceleration();
    const double* drho = particles_.density_rate();
    const std::int32_t* ph = particles_.phase();
    const std::int32_t* fixed = has_solids_ ? particles_.fields().template get<std::int32_t>("fixed").data() : nullptr;
    const auto fluid = static_cast<std::int32_t>(Phase::fluid), solid = static_cast<std::int32_t>(Phase::solid);
    parallel::for_each(particles_.size(), [&](Index i) {
        if (ph[i] != fluid && ph[i] != solid) return;
        rho[i] = rho_half[i] + drho[i] * half;
        if (fixed && fixed[i]) return;  // clamped solids keep their prescribed velocity
        v[i] = v_half[i] + a[i] * half;
    });
}

template <int Dim>
void Simulation<Dim>::integrate_update() {
    const double kick = step_ == 0 ? 0.5 * dt_ : dt_;
    const double dt = dt_;
    Vec* x = particles_.position();
    Vec* v = particles_.velocity();
    double* rho = particles_.density();
    Vec* v_half = particles_.velocity_half();
    double* rho_half = particles_.density_half();
    const Vec* a = particles_.acceleration();
    const double* drho = particles_.density_rate();
    const std::int32_t* ph = particles_.phase();
    const std::int32_t* fixed = has_solids_ ? particles_.fields().template get<std::int32_t>("fixed").data() : nullptr;
    const auto fluid = static_cast<std::int32_t>(Phase::fluid), solid = static_cast<std::int32_t>(Phase::solid);
    parallel::for_each(particles_.size(), [&](Index i) {
        if (ph[i] != fluid && ph[i] != solid) return;
        rho_half[i] += drho[i] * kick;
        // Between steps, velocity and density show the half-step state (outputs, diagnostics).
        rho[i] = rho_half[i];
        if (fixed && fixed[i]) {  // clamped: moves at its prescribed velocity
            x[i] += v_half[i] * dt;
            return;
        }
        v_half[i] += a[i] * kick;
        x[i] += v_half[i] * dt;
        v[i] = v_half[i];
    });
}

template <int Dim>
void Simulation<Dim>::register_solid_fields() {
    particles::FieldRegistry& f = particles_.fields();
    f.add<core::SymTensor3>("deviatoric_stress", core::SymTensor3::zero(), true);
    f.add<double>("plastic_strain", 0.0, true);
    f.add<double>("damage", 0.0, true);
    f.add<double>("von_mises", 0.0, true);
    f.add<double>("temperature", 0.0, true);
    f.add<double>("specific_energy", 0.0, false);
    f.add<double>("bulking_pressure", 0.0, true);
    f.add<std::int32_t>("fixed", 0, true);
}

template <int Dim>
void Simulation<Dim>::apply_brittle_pressure() {
    // JH-2 (eqs. 40-41): the polynomial EOS value plus the bulking increment in compression, and tension
    // limited to -T (1 - D).
    const auto& f = particles_.fields();
    const double* damage = f.template get<double>("damage").data();
    const double* bulking = f.template get<double>("bulking_pressure").data();
    const double* rho = particles_.density();
    double* p = particles_.pressure();
    const std::int32_t* ph = particles_.phase();
    const std::int32_t* mat = particles_.material();
    const auto solid = static_cast<std::int32_t>(Phase::solid);
    for (std::size_t m = 0; m < spec_.materials.size(); ++m) {
        const auto* jh2 = std::get_if<material::JH2>(&spec_.materials[m].solid_model);
        if (!jh2 || spec_.materials[m].phase != Phase::solid) continue;
        const auto id = static_cast<std::int32_t>(m);
        const double rho0 = jh2->reference_density, tension = jh2->strength.tensile_pressure();
        parallel::for_each(particles_.size(), [&](Index i) {
            if (ph[i] != solid || mat[i] != id) return;
            p[i] = material::jh2_pressure(p[i], rho[i] / rho0 - 1.0, bulking[i], damage[i], tension);
        });
    }
}

template <int Dim>
void Simulation<Dim>::update_solid_stress() {
    // Material update of every solid particle (first seed paper Fig. 6): Jaumann rate, radial return,
    // plastic strain, damage, temperature; and the specific internal energy. One loop per material,
    // dispatched once on its constitutive model.
    auto& f = particles_.fields();
    core::SymTensor3* tau = f.template get<core::SymTensor3>("deviatoric_stress").data();
    double* eps_p = f.template get<double>("plastic_strain").data();
    double* damage = f.template get<double>("damage").data();
    double* vm = f.template get<double>("von_mises").data();
    double* temperature = f.template get<double>("temperature").data();
    double* energy = f.template get<double>("specific_energy").data();
    double* bulking = f.template get<double>("bulking_pressure").data();
    const double* p = particles_.pressure();
    const double* rho = particles_.density();
    const std::int32_t* ph = particles_.phase();
    const std::int32_t* mat = particles_.material();
    const core::SymTensor3* rate = solid_workspace_.strain_rate.data();
    const material::Spin* spin = solid_workspace_.spin.data();
    const double* de = solid_workspace_.energy_rate.data();
    const double dt = dt_;
    const auto solid = static_cast<std::int32_t>(Phase::solid);
    for (std::size_t m = 0; m < spec_.materials.size(); ++m) {
        const auto& material = spec_.materials[m];
        if (material.phase != Phase::solid) continue;
        const auto id = static_cast<std::int32_t>(m);
        std::visit(
            [&](const auto& model) {
                parallel::for_each(particles_.size(), [&](Index i) {
                    if (ph[i] != solid || mat[i] != id) return;
                    material::SolidPointState s{tau[i], eps_p[i], 0.0, damage[i], temperature[i], bulking[i]};
                    s = material::update_solid_point(model, material.solid, s, rate[i], spin[i], p[i], rho[i], dt);
                    tau[i] = s.deviatoric_stress;
                    eps_p[i] = s.plastic_strain;
                    damage[i] = s.damage;
                    temperature[i] = s.temperature;
                    bulking[i] = s.bulking_pressure;
                    vm[i] = s.deviatoric_stress.von_mises();
                    energy[i] += de[i] * dt;
                });
            },
            material.solid_model);
    }
}

template <int Dim>
void Simulation<Dim>::remove_failed_solids() {
    // Ductile (eq. 36): a particle with D >= 1 is removed and its mass booked as eroded.
    // Brittle (JH-2): a fractured particle still carries pressure, so it stays while it touches intact
    // rock (a crack); it is removed once it is detached, when no solid particle within 1.5 spacings
    // (its nearest and diagonal neighbours) has D < 1: loose fragments and comminuted rubble.
    const double* damage = particles_.fields().template get<double>("damage").data();
    const std::int32_t* ph = particles_.phase();
    const std::int32_t* mat = particles_.material();
    const Vec* x = particles_.position();
    const auto solid = static_cast<std::int32_t>(Phase::solid);
    const Index n = particles_.size();
    const double reach2 = 2.25 * spacing_ * spacing_;
    const Index* nb = neighbors_.indices();
    std::vector<std::uint8_t> gone(static_cast<std::size_t>(n), 0);
    parallel::for_each(n, [&](Index i) {
        if (ph[i] != solid || damage[i] < 1.0) return;
        if (brittle_[static_cast<std::size_t>(mat[i])]) {
            for (Index k = neighbors_.begin(i); k < neighbors_.end(i); ++k) {
                const Index j = nb[k];
                if (ph[j] == solid && damage[j] < 1.0 && core::norm2(x[j] - x[i]) <= reach2) return;
            }
        }
        gone[static_cast<std::size_t>(i)] = 1;
    });
    const Index failed = parallel::sum(n, Index{0}, [&](Index i) { return Index{gone[static_cast<std::size_t>(i)]}; });
    if (failed == 0) return;
    const double* m = particles_.mass();
    std::vector<Index> keep;
    keep.reserve(static_cast<std::size_t>(n - failed));
    for (Index i = 0; i < n; ++i) {
        if (gone[static_cast<std::size_t>(i)])
            eroded_mass_ += m[i];
        else
            keep.push_back(i);
    }
    particles_.gather(keep);
    neighbors_stale_ = true;
}

template <int Dim>
void Simulation<Dim>::apply_boundaries() {
    // Outlets and (with domain.on_exit = "remove") the domain's faces remove fluid and loose solid
    // particles (debris). Fluid mass is booked as mass_out, solid mass as eroded mass.
    if (!spec_.outlets.empty() || spec_.remove_leaving) {
        const Vec* x = particles_.position();
        const double* m = particles_.mass();
        const std::int32_t* ph = particles_.phase();
        const std::int32_t* fixed =
            has_solids_ ? particles_.fields().template get<std::int32_t>("fixed").data() : nullptr;
        const auto fluid = static_cast<std::int32_t>(Phase::fluid), solid = static_cast<std::int32_t>(Phase::solid);
        const Index n = particles_.size();
        std::vector<std::uint8_t> gone(static_cast<std::size_t>(n), 0);
        parallel::for_each(n, [&](Index i) {
            if (ph[i] != fluid && (ph[i] != solid || (fixed && fixed[i]))) return;
            bool out = spec_.remove_leaving && !inside<Dim>(x[i], spec_.domain_min, spec_.domain_max);
            for (const auto& o : spec_.outlets) out = out || inside<Dim>(x[i], o.min, o.max);
            gone[static_cast<std::size_t>(i)] = out;
        });
        const Index removed = parallel::sum(n, Index{0}, [&](Index i) { return Index{gone[static_cast<std::size_t>(i)]}; });
        if (removed > 0) {
            std::vector<Index> keep;
            keep.reserve(static_cast<std::size_t>(n - removed));
            for (Index i = 0; i < n; ++i) {
                if (!gone[static_cast<std::size_t>(i)])
                    keep.push_back(i);
                else if (ph[i] == solid)
                    eroded_mass_ += m[i];
                else
                    mass_out_ += m[i];
            }
            particles_.gather(keep);
            neighbors_stale_ = true;
        }
    }
    for (auto& inlet : inlets_) {
        const double emitted = inlet.emit(particles_, time_, dt_);
        if (emitted > 0.0) {
            mass_in_ += emitted;
            neighbors_stale_ = true;
        }
    }
}

template <int Dim>
void Simulation<Dim>::update_neighbors(bool force) {
    const double skin = spec_.neighbor_skin * smoothing_length_;
    const double support = std::visit([](const auto& k) { return k.support(); }, kernel_);
    const Index n = particles_.size();
    if (!force && !neighbors_stale_ && neighbors_.max_displacement2(particles_.position(), n) < 0.25 * skin * skin)
        return;
    // Sort every field by cell, then list neighbours; sorting keeps neighbours close in memory.
    const double radius = support + skin;
    grid_ = neighbors::CellGrid<Dim>::covering(particles_.position(), n, radius);
    neighbors::sort_by_cell(grid_, particles_.position(), n, order_, cell_start_);
    particles_.gather(order_);
    neighbors_.build(grid_, cell_start_, particles_.position(), n, radius, particles_.phase());
    neighbors_stale_ = false;
    ++neighbor_builds_;
}

template <int Dim>
void Simulation<Dim>::compute_time_step() {
    // Eq. (51): dt = C_F min_a h / (c_a + |v_a|), with Monaghan's force condition 0.25 sqrt(h/|a|) and
    // the viscous condition 0.125 h^2 / nu.
    const double h = smoothing_length_;
    const Vec* v = particles_.velocity();
    const Vec* a = particles_.acceleration();
    const std::int32_t* ph = particles_.phase();
    const std::int32_t* mat = particles_.material();
    const auto fluid = static_cast<std::int32_t>(Phase::fluid), solid = static_cast<std::int32_t>(Phase::solid);
    const double* signal = signal_speed_.data();
    const double huge = std::numeric_limits<double>::max();
    struct Limits {
        double cfl, accel2;
    };
    const Limits lim = parallel::reduce(
        particles_.size(), Limits{huge, 0.0},
        [&](Index i) {
            if (ph[i] != fluid && ph[i] != solid) return Limits{huge, 0.0};
            return Limits{h / (signal[mat[i]] + core::norm(v[i])), core::norm2(a[i])};
        },
        [](Limits x, Limits y) { return Limits{std::min(x.cfl, y.cfl), std::max(x.accel2, y.accel2)}; });
    const double cfl = lim.cfl, amax2 = lim.accel2;
    double dt = huge;
    if (cfl >= huge) {
        // No fluid yet (an inlet that has not started): step by the fastest speed in the case.
        if (!inlets_.empty()) dt = spec_.cfl * h / max_speed_;
    } else {
        dt = spec_.cfl * cfl;
        if (amax2 > 0.0) dt = std::min(dt, 0.25 * std::sqrt(h / std::sqrt(amax2)));
        for (const auto& c : fluid_parameters_.materials)
            if (c.kinematic_viscosity > 0.0) dt = std::min(dt, 0.125 * h * h / c.kinematic_viscosity);
    }
    // Eq. (51): the smaller of the SPH and DEM limits.
    if (grains_) dt = std::min(dt, grains_->stable_time_step());
    dt_ = std::min(dt, spec_.max_time_step);
    dt_stable_ = dt_;
    if (!(dt_ < huge)) throw core::InputError("nothing sets a time step: the case has no particles that move");
}

template <int Dim>
void Simulation<Dim>::check_health() {
    const Vec* x = particles_.position();
    const Vec* v = particles_.velocity();
    const double* rho = particles_.density();
    const double* p = particles_.pressure();
    const std::int32_t* ph = particles_.phase();
    const auto wall = static_cast<std::int32_t>(Phase::wall);
    const double vmax2 = max_speed_ * max_speed_;
    const bool check_domain = !spec_.remove_leaving;
    const Index bad = parallel::first_index(particles_.size(), [&](Index i) {
        if (ph[i] == wall) return false;
        return !core::all_finite(x[i]) || !core::all_finite(v[i]) || !(rho[i] > 0.0) || !std::isfinite(rho[i]) ||
               !std::isfinite(p[i]) || core::norm2(v[i]) > vmax2 ||
               (check_domain && !inside<Dim>(x[i], spec_.domain_min, spec_.domain_max));
    });
    if (grains_ && bad < 0) {
        const std::string grain = grains_->check(spec_.domain_min, spec_.domain_max);
        if (!grain.empty())
            throw core::BlowUpError(fmt::format("numerical blow-up at step {} (t = {:.9g} s): {}", step_, time_, grain));
    }
    if (bad < 0) {
        if (step_ % spec_.check_interval == 0) {
            last_good_ = particles_;
            last_good_time_ = time_;
            last_good_step_ = step_;
        }
        return;
    }
    std::string what;
    if (!core::all_finite(x[bad]))
        what = "position is not finite";
    else if (!core::all_finite(v[bad]))
        what = "velocity is not finite";
    else if (!(rho[bad] > 0.0) || !std::isfinite(rho[bad]))
        what = fmt::format("density = {:.6g} kg/m^3 is not positive and finite", rho[bad]);
    else if (!std::isfinite(p[bad]))
        what = "pressure is not finite";
    else if (core::norm2(v[bad]) > vmax2)
        what = fmt::format("speed = {:.6g} m/s exceeds numerics.max_speed = {:.6g} m/s (runaway)", core::norm(v[bad]),
                           max_speed_);
    else
        what = "escaped the domain (domain.min/domain.max)";
    std::string message =
        fmt::format("numerical blow-up at step {} (t = {:.9g} s): {} particle {} at ({:.6g}): {}", step_, time_,
                    phase_name(ph[bad]), bad, fmt::join(std::vector<double>(x[bad].c, x[bad].c + Dim), ", "), what);
    if (options_.write_files) {
        const auto file = fmt::format("snapshots/{}_last_good_{:06}.vtu", spec_.name, last_good_step_);
        io::write_vtu(options_.output_dir / file, last_good_.snapshot());
        pvd_->add(last_good_time_, file);
        message += fmt::format("; last good state (step {}, t = {:.9g} s) written to {}", last_good_step_,
                               last_good_time_, (options_.output_dir / file).string());
    }
    throw core::BlowUpError(message);
}

template <int Dim>
void Simulation<Dim>::prime() {
    primed_ = true;
    if (grains_) grains_->prime();
    update_neighbors(true);
    pipeline_.run_only({"equation_of_state", "wall_pressure", "sph_prepare", "sph_fluid", "sph_solid", "time_step"});
    // The first step recomputes these rates at the same state; prime only sizes the first dt.
    last_good_ = particles_;
}

template <int Dim>
void Simulation<Dim>::step() {
    const double dt = dt_;  // the time_step stage replaces dt_ with the next step's value
    pipeline_.run();
    time_ += dt;
    ++step_;
    particle_steps_ += particles_.size();
    pair_steps_ += static_cast<double>(neighbors_.pair_count());
}

template <int Dim>
void Simulation<Dim>::advance_to(double target, const std::function<void()>& after_each_step) {
    if (!primed_) prime();
    while (time_ < target * (1.0 - 1e-12)) {
        if (time_ + dt_ > target) dt_ = target - time_;  // land exactly on the target time
        step();
        if (after_each_step) after_each_step();
    }
}

template <int Dim>
double Simulation<Dim>::probe(std::size_t k) const {
    return analysis::evaluate_probe(spec_.probes[k], particles_, kernel_, spacing_);
}

template <int Dim>
double Simulation<Dim>::probe(const std::string& name) const {
    for (std::size_t k = 0; k < spec_.probes.size(); ++k)
        if (spec_.probes[k].name == name) return probe(k);
    throw std::out_of_range("no probe named '" + name + "'");
}

template <int Dim>
void Simulation<Dim>::write_output() {
    if (!options_.write_files) return;
    if (spec_.write_snapshots && has_sph_) {
        const auto file = fmt::format("snapshots/{}_{:06}.vtu", spec_.name, snapshot_index_++);
        io::write_vtu(options_.output_dir / file, particles_.snapshot());
        pvd_->add(time_, file);
    }
    const auto d = analysis::compute_diagnostics(particles_);
    std::vector<double> row = {time_, static_cast<double>(step_), dt_, d.kinetic_energy, d.mass, mass_in_, mass_out_,
                               d.max_velocity, static_cast<double>(particles_.size())};
    if (has_solids_) {
        const SolidMeasures s = solid_measures();
        row.insert(row.end(), {eroded_mass_, s.max_plastic_strain, s.internal_energy});
        if (spec_.has_crater) {
            row.insert(row.end(), {s.crater.depth, s.crater.width});
            std::ofstream out(options_.output_dir / "crater.csv");
            out << "# surface profile at t = " << fmt::format("{:.9g}", time_) << " s\nx,surface\n";
            for (std::size_t b = 0; b < s.crater.x.size(); ++b)
                out << fmt::format("{:.9g},{:.9g}\n", s.crater.x[b], s.crater.surface[b]);
        }
        if (spec_.has_cracks)
            row.insert(row.end(), {s.cracks.damaged_area, static_cast<double>(s.cracks.crack_count)});
    }
    if (grains_) {
        if (spec_.write_snapshots) grains_->write_snapshot(options_.output_dir, spec_.name, time_);
        row.insert(row.end(), {static_cast<double>(grains_->size()), grains_->kinetic_energy()});
        grains_->flush_impacts();
    }
    for (std::size_t k = 0; k < spec_.probes.size(); ++k) row.push_back(probe(k));
    series_->write_row(row);
}

template <int Dim>
typename Simulation<Dim>::SolidMeasures Simulation<Dim>::solid_measures() const {
    SolidMeasures out;
    if (!has_solids_) return out;
    const auto& f = particles_.fields();
    const double* eps_p = f.template get<double>("plastic_strain").data();
    const double* e = f.template get<double>("specific_energy").data();
    const double* m = particles_.mass();
    const std::int32_t* ph = particles_.phase();
    const auto solid = static_cast<std::int32_t>(Phase::solid);
    out.max_plastic_strain =
        parallel::max(particles_.size(), 0.0, [&](Index i) { return ph[i] == solid ? eps_p[i] : 0.0; });
    out.internal_energy = parallel::sum(particles_.size(), 0.0, [&](Index i) { return ph[i] == solid ? m[i] * e[i] : 0.0; });
    if (spec_.has_cracks)
        out.cracks = analysis::analyse_cracks(
            particles_, f.template get<double>("damage").data(),
            {spec_.crack_damage_threshold, spec_.crack_link_distance, spec_.crack_min_particles});
    if constexpr (Dim == 2) {
        if (spec_.has_crater)
            out.crater = analysis::analyse_crater(
                particles_, {spec_.crater_surface, spec_.crater_x_min, spec_.crater_x_max}, spacing_);
    }
    return out;
}

template <int Dim>
RunSummary Simulation<Dim>::summarize(double wall_time) const {
    RunSummary s;
    s.particles = particles_.size();
    s.steps = step_;
    s.end_time = time_;
    s.wall_time_s = wall_time;
    s.particle_steps_per_second = wall_time > 0.0 ? particle_steps_ / wall_time : 0.0;
    s.pair_interactions_per_second = wall_time > 0.0 ? pair_steps_ / wall_time : 0.0;
    const auto d = analysis::compute_diagnostics(particles_);
    s.kinetic_energy = d.kinetic_energy;
    s.mass_total = d.mass;
    s.mass_in = mass_in_;
    s.mass_out = mass_out_;
    s.max_velocity = d.max_velocity;
    s.momentum.assign(d.momentum.c, d.momentum.c + Dim);
    for (std::size_t k = 0; k < spec_.probes.size(); ++k) {
        s.probe_names.push_back(spec_.probes[k].name);
        s.probe_values.push_back(probe(k));
    }
    s.stages = pipeline_.timers();
    if (grains_) {
        s.has_grains = true;
        s.grains = grains_->size();
        s.grain_kinetic_energy = grains_->kinetic_energy();
        s.impacts = grains_->impacts().size();
    }
    s.has_solids = has_solids_;
    if (has_solids_) {
        const SolidMeasures m = solid_measures();
        s.eroded_mass = eroded_mass_;
        s.max_plastic_strain = m.max_plastic_strain;
        s.internal_energy = m.internal_energy;
        s.has_crater = spec_.has_crater;
        s.crater_depth = m.crater.depth;
        s.crater_width = m.crater.width;
        s.has_cracks = spec_.has_cracks;
        s.damaged_area = m.cracks.damaged_area;
        s.crack_count = m.cracks.crack_count;
    }
    return s;
}

template <int Dim>
void Simulation<Dim>::write_summary(const RunSummary& s, const std::string& status, const std::string& message) const {
    if (!options_.write_files) return;
    nlohmann::ordered_json j;
    j["case"] = spec_.name;
    j["title"] = spec_.title;
    j["status"] = status;
    if (!message.empty()) j["message"] = message;
    j["dimension"] = Dim;
    j["threads"] = parallel::max_threads();
    j["particles"] = s.particles;
    j["steps"] = s.steps;
    j["end_time"] = s.end_time;
    j["wall_time_s"] = s.wall_time_s;
    j["particle_steps_per_second"] = s.particle_steps_per_second;
    j["pair_interactions_per_second"] = s.pair_interactions_per_second;
    j["neighbor_list_builds"] = neighbor_builds_;
    j["kinetic_energy"] = s.kinetic_energy;
    j["mass_total"] = s.mass_total;
    j["mass_in"] = s.mass_in;
    j["mass_out"] = s.mass_out;
    j["max_velocity"] = s.max_velocity;
    if (s.has_solids) {
        j["eroded_mass"] = s.eroded_mass;
        j["max_plastic_strain"] = s.max_plastic_strain;
        j["internal_energy"] = s.internal_energy;
        if (s.has_crater) {
            j["crater_depth"] = s.crater_depth;
            j["crater_width"] = s.crater_width;
        }
        if (s.has_cracks) {
            j["damaged_area"] = s.damaged_area;
            j["crack_count"] = s.crack_count;
        }
    }
    if (s.has_grains) {
        j["grains"] = s.grains;
        j["grain_kinetic_energy"] = s.grain_kinetic_energy;
        j["impacts"] = s.impacts;
    }
    j["momentum"] = s.momentum;
    for (std::size_t k = 0; k < s.probe_names.size(); ++k) {
        const double v = s.probe_values[k];
        j["probes"][s.probe_names[k]] = std::isfinite(v) ? nlohmann::ordered_json(v) : nlohmann::ordered_json(nullptr);
    }
    for (const auto& t : s.stages) j["stage_seconds"][t.name] = t.seconds;
    std::ofstream out(options_.output_dir / "summary.json");
    out << j.dump(2) << '\n';
}

template <int Dim>
RunSummary Simulation<Dim>::run() {
    namespace fs = std::filesystem;
    if (options_.write_files) {
        fs::create_directories(options_.output_dir / "snapshots");
        for (const auto& e : fs::directory_iterator(options_.output_dir / "snapshots"))
            if (e.path().extension() == ".vtu") fs::remove(e.path());
        if (!has_sph_) fs::remove(options_.output_dir / "snapshots");
        pvd_ = std::make_unique<io::PvdWriter>(options_.output_dir / (spec_.name + ".pvd"));
        std::vector<std::string> columns = {"time",     "step",     "dt",           "kinetic_energy", "mass_total",
                                            "mass_in",  "mass_out", "max_velocity", "particles"};
        if (has_solids_) {
            columns.insert(columns.end(), {"eroded_mass", "max_plastic_strain", "internal_energy"});
            if (spec_.has_crater) columns.insert(columns.end(), {"crater_depth", "crater_width"});
            if (spec_.has_cracks) columns.insert(columns.end(), {"damaged_area", "crack_count"});
        }
        if (grains_) {
            columns.insert(columns.end(), {"grains", "grain_kinetic_energy"});
            grains_->open_output(options_.output_dir, spec_.name);
        }
        for (const auto& p : spec_.probes) columns.push_back(p.name);
        series_ = std::make_unique<io::SeriesWriter>(options_.output_dir / "series.csv", columns);
    }
    core::Stopwatch clock;
    Progress progress(!options_.quiet);
    try {
        prime();
        write_output();
        next_output_ = spec_.output_interval;
        const double end = spec_.end_time;
        while (time_ < end * (1.0 - 1e-12)) {
            advance_to(std::min(end, next_output_), [&] { progress.update(time_, end, step_); });
            write_output();
            while (next_output_ <= time_ * (1.0 + 1e-12)) next_output_ += spec_.output_interval;
        }
        progress.update(time_, end, step_, true);
        progress.finish();
    } catch (const core::BlowUpError& e) {
        progress.finish();
        write_summary(summarize(clock.seconds()), "blow_up", e.what());
        throw;
    }
    RunSummary summary = summarize(clock.seconds());
    write_summary(summary, "completed", "");
    return summary;
}

template class Simulation<2>;
template class Simulation<3>;

RunSummary run_case(const io::CaseSpec& spec, const RunOptions& options) {
    if (spec.dimension == 2) {
        Simulation<2> s(spec, options);
        return s.run();
    }
    Simulation<3> s(spec, options);
    return s.run();
}

}  // namespace grit::sim
