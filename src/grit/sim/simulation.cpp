// A run of one case: the modules over one state, the run loop, outputs and the health check (checkpoints:
// simulation_checkpoint.cpp; the summary: simulation_summary.cpp).
#include "grit/sim/simulation.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "grit/analysis/diagnostics.hpp"
#include "grit/core/error.hpp"
#include "grit/io/run_folder.hpp"
#include "grit/io/vtu_writer.hpp"
#include "grit/modules/abrasive_feed.hpp"
#include "grit/modules/analyses.hpp"
#include "grit/modules/grain_contact.hpp"
#include "grit/modules/coupling.hpp"
#include "grit/modules/grain_feed.hpp"
#include "grit/modules/grains.hpp"
#include "grit/modules/mesh_wear.hpp"
#include "grit/modules/open_boundaries.hpp"
#include "grit/modules/isph_fluid.hpp"
#include "grit/modules/sph_fluid.hpp"
#include "grit/modules/thin_walls.hpp"
#include "grit/modules/sph_solid.hpp"
#include "grit/modules/symmetry_plane.hpp"
#include "grit/parallel/parallel.hpp"
#include "grit/parallel/thread_governor.hpp"
#include "grit/sim/checkpoint_files.hpp"
#include "grit/sim/geometry.hpp"
#include "grit/sim/particle_blocks.hpp"
#include "grit/sim/progress.hpp"
#include "grit/sim/run_control.hpp"
#include "grit/sim/run_estimate.hpp"
#include "grit/sim/output_times.hpp"
#include "grit/sim/output_units.hpp"
#include "grit/sim/run_log.hpp"
#include "grit/sim/step_to_target.hpp"
#include "grit/sim/version.hpp"

namespace grit::sim {

namespace {

/// True when the case has a fluid material (the coupling needs one).
bool has_fluid(const io::CaseSpec& spec) {
    return std::any_of(spec.materials.begin(), spec.materials.end(),
                       [](const material::Material& m) { return m.phase == Phase::fluid; });
}

using core::to_vec;


const char* phase_name(std::int32_t p) {
    switch (static_cast<Phase>(p)) {
        case Phase::fluid: return "fluid";
        case Phase::solid: return "solid";
        case Phase::wall: return "wall";
        case Phase::grain: return "grain";
    }
    return "unknown";
}

/// A snapshot of `particles` with the names behind its integer codes: `material_names` (the case's
/// materials, by the `material` index) and `phase_names` (by the `phase` code).
template <int Dim>
io::PointCloud named_snapshot(const particles::SphParticles<Dim>& particles, const io::CaseSpec& spec) {
    io::PointCloud cloud = particles.snapshot();
    io::NameList materials{"material_names", {}};
    for (const auto& m : spec.materials) materials.values.push_back(m.name);
    io::NameList phases{"phase_names", {}};
    for (const auto p : {Phase::fluid, Phase::solid, Phase::wall}) phases.values.push_back(phase_name(static_cast<std::int32_t>(p)));
    cloud.names.push_back(std::move(materials));
    cloud.names.push_back(std::move(phases));
    return cloud;
}

}  // namespace

template <int Dim>
Simulation<Dim>::Simulation(io::CaseSpec spec, RunOptions options)
    : spec_(std::move(spec)),
      options_(std::move(options)),
      kernel_(sph::CubicSpline<Dim>(1.0)),
      setup_{spec_,   spec_.particle_spacing, spec_.smoothing_ratio * spec_.particle_spacing, kernel_, 0.0,
             periodic_box_of<Dim>(spec_)} {
    if (spec_.dimension != Dim) throw std::logic_error("case dimension does not match the simulation");
    sph::make_kernel<Dim>(spec_.kernel, setup_.smoothing_length, kernel_);
    double fastest = 0.0;
    for (const auto& m : spec_.materials) fastest = std::max(fastest, m.signal_speed());
    for (const auto& in : spec_.inlets) fastest = std::max(fastest, in.velocity);
    setup_.max_speed = spec_.max_speed > 0.0 ? spec_.max_speed : 2.0 * fastest;

    has_sph_ = spec_.has_sph();
    if (has_sph_) check_periodic_lengths();

    // The modules the case needs. Their order is the order of their stages within a hook point and of
    // their output columns; fields are registered (in this order) before any particle exists.
    modules::SphModule<Dim>* sph = nullptr;
    if (has_sph_ && spec_.fluid_solver == "isph") {
        // The incompressible solver takes the fluid and the walls (the case reader refuses what it cannot).
        modules_.push_back(std::make_unique<modules::IsphModule<Dim>>(state_, setup_));
    } else if (has_sph_) {
        auto m = std::make_unique<modules::SphModule<Dim>>(state_, setup_);
        sph = m.get();
        modules_.push_back(std::move(m));
    }
    const bool solids = !spec_.solids.empty();
    if (solids) {
        modules_.push_back(std::make_unique<modules::SolidModule<Dim>>(state_, setup_, *sph));
        if (spec_.has_crater) modules_.push_back(std::make_unique<modules::CraterModule<Dim>>(state_, setup_));
        if (spec_.has_cracks) modules_.push_back(std::make_unique<modules::CracksModule<Dim>>(state_, setup_));
        if (has_fluid(spec_)) modules_.push_back(std::make_unique<modules::FluidInSolidModule<Dim>>(state_, setup_));
    }
    if (has_sph_) modules_.push_back(std::make_unique<modules::OpenBoundariesModule<Dim>>(state_, setup_));
    if (spec_.has_thin_walls()) modules_.push_back(std::make_unique<modules::ThinWallsModule<Dim>>(state_, setup_));

    add_particle_blocks<Dim>(spec_, setup_.spacing, state_.particles);
    for (auto& m : modules_) m->initialise();
    const auto* x = state_.particles.position();
    for (Index i = 0; i < state_.particles.size(); ++i)
        if (!inside<Dim>(x[i], spec_.domain_min, spec_.domain_max))
            throw core::InputError(fmt::format(
                "key 'domain.min'/'domain.max': a {} particle at ({}) lies outside the domain; enlarge the domain",
                phase_name(state_.particles.phase()[i]), fmt::join(std::vector<double>(x[i].c, x[i].c + Dim), ", ")));
    if (setup_.periodic_box.any()) {
        // Inside the closed box; along the periodic axes into [min, max) (a point on max is the one on min).
        Vec* xw = state_.particles.position();
        for (Index i = 0; i < state_.particles.size(); ++i) xw[i] = setup_.periodic_box.wrap(xw[i]);
    }

    if (spec_.has_grains()) {
        // The grains module builds the grains the others register fields on; its step runs after
        // theirs (contact and coupling forces first, then the grains' kick).
        auto grains = std::make_unique<modules::GrainsModule<Dim>>(state_, setup_);
        if (has_sph_) modules_.push_back(std::make_unique<modules::GrainContactModule<Dim>>(state_, setup_));
        if (has_sph_ && spec_.coupling.enabled && has_fluid(spec_))
            modules_.push_back(std::make_unique<modules::CouplingModule<Dim>>(state_, setup_));
        modules_.push_back(std::move(grains));
        if (!spec_.meshes.empty()) modules_.push_back(std::make_unique<modules::MeshWearModule<Dim>>(state_, setup_));
        if (!spec_.grain_feeds.empty()) modules_.push_back(std::make_unique<modules::GrainFeedModule<Dim>>(state_, setup_));
        if (spec_.abrasive.enabled) modules_.push_back(std::make_unique<modules::AbrasiveFeedModule<Dim>>(state_, setup_));
    }
    // After the modules whose forces and porosity act on the particles: its stages close each hook.
    if (has_sph_ && spec_.symmetry_plane)
        modules_.push_back(std::make_unique<modules::SymmetryPlaneModule<Dim>>(state_, setup_));
    if (!spec_.probes.empty()) {
        auto m = std::make_unique<modules::ProbesModule<Dim>>(state_, setup_);
        probes_ = m.get();
        modules_.push_back(std::move(m));
    }

    for (auto& m : modules_) m->install(pipeline_);
    pipeline_.add(Hook::check, "health_check", [this] { check_health(); });
    pipeline_.add(Hook::check, "time_step", [this] { compute_time_step(); }, true);
}

template <int Dim>
Simulation<Dim>::~Simulation() = default;

template <int Dim>
void Simulation<Dim>::check_periodic_lengths() const {
    // The neighbour grid divides a periodic axis into whole cells of at least the list radius and scans
    // one cell either side: three cells at least, so that no pair is met twice.
    const double skin = spec_.neighbor_skin * setup_.smoothing_length;
    const double radius = std::visit([](const auto& k) { return k.support(); }, kernel_) + skin;
    const char* axis = "xyz";
    for (int k = 0; k < Dim; ++k) {
        if (!setup_.periodic_box.periodic[k]) continue;
        const double length = setup_.periodic_box.length(k);
        if (std::floor(length / radius) < 3.0)
            throw core::InputError(fmt::format(
                "key '{}': the domain is {:.6g} m long along the periodic axis {}, less than three neighbour-list "
                "radii (3 x {:.6g} m = {:.6g} m: kernel support + numerics.neighbor_skin); lengthen the domain "
                "along {} or refine numerics.particle_spacing",
                spec_.periodic_key, length, axis[k], radius, 3.0 * radius, axis[k]));
    }
}

template <int Dim>
void Simulation<Dim>::compute_time_step() {
    // Eq. (51): the smallest of the modules' stable steps (SPH CFL, DEM), capped by time.max_step.
    double dt = std::numeric_limits<double>::max();
    for (const auto& m : modules_) dt = std::min(dt, m->stable_time_step());
    auto& clock = state_.clock;
    clock.dt = std::min(dt, spec_.max_time_step);
    clock.dt_stable = clock.dt;
    if (!(clock.dt < std::numeric_limits<double>::max()))
        throw core::InputError("nothing sets a time step: the case has no particles that move");
}

template <int Dim>
std::string Simulation<Dim>::find_unhealthy() const {
    const auto& ps = state_.particles;
    const Vec* x = ps.position();
    const Vec* v = ps.velocity();
    const double* rho = ps.density();
    const double* p = ps.pressure();
    const std::int32_t* ph = ps.phase();
    const auto wall = static_cast<std::int32_t>(Phase::wall);
    const double vmax2 = setup_.max_speed * setup_.max_speed;
    const bool check_domain = !spec_.remove_leaving;
    const Index bad = parallel::first_index(ps.size(), [&](Index i) {
        if (ph[i] == wall || ps.is_image(i)) return false;  // an image is checked as its source
        return !core::all_finite(x[i]) || !core::all_finite(v[i]) || !(rho[i] > 0.0) || !std::isfinite(rho[i]) ||
               !std::isfinite(p[i]) || core::norm2(v[i]) > vmax2 ||
               (check_domain && !inside<Dim>(x[i], spec_.domain_min, spec_.domain_max));
    });
    std::string what;
    if (bad >= 0) {
        if (!core::all_finite(x[bad]))
            what = "position is not finite";
        else if (!core::all_finite(v[bad]))
            what = "velocity is not finite";
        else if (!(rho[bad] > 0.0) || !std::isfinite(rho[bad]))
            what = fmt::format("density = {:.6g} kg/m^3 is not positive and finite", rho[bad]);
        else if (!std::isfinite(p[bad]))
            what = "pressure is not finite";
        else if (core::norm2(v[bad]) > vmax2)
            what = fmt::format("speed = {:.6g} m/s exceeds numerics.max_speed = {:.6g} m/s (runaway)",
                               core::norm(v[bad]), setup_.max_speed);
        else
            what = "escaped the domain (domain.min/domain.max)";
        what = fmt::format("{} particle {} at ({:.6g}): {}", phase_name(ph[bad]), bad,
                           fmt::join(std::vector<double>(x[bad].c, x[bad].c + Dim), ", "), what);
    }
    for (auto it = modules_.begin(); what.empty() && it != modules_.end(); ++it) what = (*it)->check_health();
    return what;
}

template <int Dim>
void Simulation<Dim>::check_health() {
    const std::string what = find_unhealthy();
    if (!what.empty()) report_blow_up(what);
    const auto& clock = state_.clock;
    if (clock.step % spec_.check_interval == 0) {
        last_good_ = state_.particles;
        last_good_time_ = clock.time;
        last_good_step_ = clock.step;
    }
}

template <int Dim>
void Simulation<Dim>::report_blow_up(const std::string& what) {
    const auto& clock = state_.clock;
    std::string message = fmt::format("numerical blow-up at step {} (t = {:.9g} s): {}", clock.step, clock.time, what);
    if (options_.write_files && has_sph_) {
        const auto file = fmt::format("snapshots/{}_last_good_{:06}.vtu", spec_.name, last_good_step_);
        io::write_vtu(options_.output_dir / file, named_snapshot(last_good_, spec_));
        pvd_->add(last_good_time_, file);
        message += fmt::format("; last good state (step {}, t = {:.9g} s) written to {}", last_good_step_,
                               last_good_time_, (options_.output_dir / file).string());
    }
    blow_up_reported_ = true;
    throw core::BlowUpError(message);
}

template <int Dim>
void Simulation<Dim>::prime() {
    primed_ = true;
    for (auto& m : modules_) m->prime();
    // The first step recomputes these rates at the same state; prime only sizes the first dt.
    pipeline_.run_prime();
    last_good_ = state_.particles;
}

template <int Dim>
RunEstimate Simulation<Dim>::estimate() {
    if (!primed_) prime();
    return estimate_run(spec_, state_);
}

template <int Dim>
void Simulation<Dim>::step() {
    const double dt = state_.clock.dt;  // the time_step stage replaces clock.dt with the next step's value
    try {
        pipeline_.run();
    } catch (const core::BlowUpError& e) {
        if (blow_up_reported_) throw;
        // Found inside a stage (a neighbour grid over a NaN position): name the step, the culprit where
        // the health check finds one, and write the last good snapshot, as the health check does.
        const std::string found = find_unhealthy();
        report_blow_up(found.empty() ? std::string(e.what()) : found + " (" + e.what() + ")");
    }
    state_.clock.time += dt;
    ++state_.clock.step;
    particle_steps_ += static_cast<double>(state_.particles.size());
    pair_steps_ += static_cast<double>(state_.neighbors.list().pair_count());
}

template <int Dim>
void Simulation<Dim>::advance_to(double target, const std::function<void()>& after_each_step) {
    if (!primed_) prime();
    auto& clock = state_.clock;
    while (clock.time < target * (1.0 - 1e-12)) {
        clock.dt = step_toward(clock.time, target, clock.dt);  // land exactly on the target time, in equal steps
        step();
        if (after_each_step) after_each_step();
    }
}

template <int Dim>
double Simulation<Dim>::probe(std::size_t k) const {
    return probes_->value(k);
}

template <int Dim>
double Simulation<Dim>::probe(const std::string& name) const {
    for (std::size_t k = 0; k < spec_.probes.size(); ++k)
        if (spec_.probes[k].name == name) return probes_->value(k);
    throw std::out_of_range("no probe named '" + name + "'");
}

template <int Dim>
std::vector<OutputValue> Simulation<Dim>::output_values() const {
    const auto& clock = state_.clock;
    const auto d = analysis::compute_diagnostics(state_.particles);
    // time, step and particles have their own summary keys.
    std::vector<OutputValue> out = {
        OutputValue::real("time", clock.time).series_only(),
        OutputValue::count("step", static_cast<double>(clock.step)).series_only(),
        OutputValue::real("dt", clock.dt).series_only(),
        OutputValue::real("kinetic_energy", d.kinetic_energy),
        OutputValue::real("mass_total", d.mass),
        OutputValue::real("mass_in", state_.ledger.in),
        OutputValue::real("mass_out", state_.ledger.out),
        OutputValue::real("max_velocity", d.max_velocity),
        OutputValue::count("particles", static_cast<double>(state_.particles.size() - state_.particles.image_count()))
            .series_only(),
    };
    for (const auto& m : modules_) m->output_values(out);
    for (auto& v : out)
        if (v.unit.empty()) v.unit = output_unit(v.name, Dim);
    return out;
}

template <int Dim>
void Simulation<Dim>::open_output(bool restart) {
    namespace fs = std::filesystem;
    place_ = {options_.output_dir, spec_.name, spec_.write_snapshots};
    const fs::path dir = options_.output_dir;
    // A fresh run replaces what an earlier run left here (the CLI asks for --overwrite first), derived
    // files (plots) included, so that nothing stale sits beside the new data.
    if (!restart) io::clear_run_folder(dir);
    fs::create_directories(dir / "snapshots");
    fs::create_directories(dir / "checkpoints");
    if (restart) {
        // Checkpoints after the one continued belong to a future this run replaces.
        for (const auto& c : checkpoints_in(dir / "checkpoints"))
            if (checkpoint_step(c) > state_.clock.step) fs::remove(c);
    }
    if (!has_sph_) fs::remove(dir / "snapshots");
    pvd_ = std::make_unique<io::PvdWriter>(dir / (spec_.name + ".pvd"));
    if (restart) pvd_->restore(restored_pvd_);
    std::vector<std::string> columns;
    for (const auto& v : output_values())
        if (v.in_series) columns.push_back(v.name);
    series_ = restart ? std::make_unique<io::SeriesWriter>(dir / "series.csv", columns, restored_series_rows_)
                      : std::make_unique<io::SeriesWriter>(dir / "series.csv", columns);
    for (auto& m : modules_) m->open_output(place_, restart);
}

template <int Dim>
void Simulation<Dim>::write_output() {
    if (!options_.write_files) return;
    if (spec_.write_snapshots && has_sph_) {
        const auto file = fmt::format("snapshots/{}_{:06}.vtu", spec_.name, snapshot_index_++);
        io::write_vtu(options_.output_dir / file, named_snapshot(state_.particles, spec_));
        pvd_->add(state_.clock.time, file);
    }
    for (auto& m : modules_) m->write_output(place_);
    std::vector<double> row;
    for (const auto& v : output_values())
        if (v.in_series) row.push_back(v.value);
    series_->write_row(row);
}

template <int Dim>
void Simulation<Dim>::write_dump() {
    if (!options_.write_files || !has_sph_) return;
    const auto file = options_.output_dir / "dump" / fmt::format("{}_step_{:09}.vtu", spec_.name, state_.clock.step);
    std::filesystem::create_directories(file.parent_path());
    io::write_vtu(file, named_snapshot(state_.particles, spec_));
}

template <int Dim>
RunSummary Simulation<Dim>::run() {
    const bool restart = !options_.restart.empty();
    if (restart) load_checkpoint(resolve_checkpoint(options_.restart));
    // Output k at k x output.interval, and an end on an output time within round-off is that time:
    // a run that ends at T and one that passes T take the same steps (output_times.hpp).
    const Cadence outputs{spec_.output_interval};
    const double end = outputs.snap(spec_.end_time);
    auto& c = state_.clock;
    if (restart && c.time >= end * (1.0 - same_time_tolerance)) {
        // Nothing to run: the run's files, summary.json's totals and its checkpoints stay as they are.
        RunSummary done = summarize(0.0, "completed");
        done.segments = earlier_.count;
        done.message = fmt::format("already at time.end: the checkpoint is at t = {:.9g} s (step {}), time.end = "
                                   "{:.9g} s; nothing to run (extend the run with --set time.end=...)",
                                   c.time, c.step, spec_.end_time);
        return done;
    }
    if (options_.write_files) open_output(restart);
    std::unique_ptr<RunLog> log;
    if (options_.write_files) {
        log = std::make_unique<RunLog>(options_.output_dir, restart);
        log->start(spec_, state_.particles.size(), state_.grains ? state_.grains->grains().size() : Index{0},
                   restart ? restarted_from_.string() : std::string(), state_.clock.step, state_.clock.time);
        std::vector<std::string> notes = restart_notes_;
        if (series_ && !series_->added_columns().empty())
            notes.push_back(fmt::format("series.csv gains column(s) {} (nan in the rows before this restart)",
                                        fmt::join(series_->added_columns(), ", ")));
        for (const std::string& note : notes) {
            if (!options_.quiet) fmt::print(stderr, "{}\n", note);
            log->warn(note);
        }
    }
    segment_clock_.restart();
    run_threads_ = parallel::max_threads();
    std::optional<parallel::ThreadGovernor> governor;
    if (options_.adapt_threads) {
        governor.emplace(run_threads_);
        if (log && governor->active() && run_threads_ > 1)
            log->info(fmt::format("threads: {}, fewer while another process holds a core (--fixed-threads keeps them)",
                                  run_threads_));
    }
    // The run leaves the thread count as it found it, however it ends.
    struct RestoreThreads {
        int n;
        ~RestoreThreads() { parallel::set_threads(n); }
    } restore_threads{run_threads_};
    Progress progress(!options_.quiet, options_.progress_every_s,
                      log ? std::function<void(const std::string&)>([&log](const std::string& line) { log->info(line); })
                          : std::function<void(const std::string&)>());
    RunControl control(options_.max_wall_time_s, options_.write_files ? spec_.checkpoint_wall_interval : 0.0);
    auto show_progress = [&](bool force) {
        progress.update(c.time, spec_.end_time, c.step, state_.particles.size(),
                        state_.grains ? state_.grains->grains().size() : Index{0}, force);
    };
    try {
        if (!restart) prime();
        const RunEstimate plan = estimate();
        if (!options_.quiet) fmt::print(stderr, "estimate: {}\n", plan.text());
        if (log) log->info("estimate: " + plan.text());
        std::error_code no_space;
        const double free_bytes =
            options_.write_files ? static_cast<double>(std::filesystem::space(options_.output_dir, no_space).available)
                                 : -1.0;
        const MachineMemory memory = machine_memory();
        // A run that cannot fit this machine stops here, not hours in with the kernel's out-of-memory kill.
        if (const std::string why = plan.does_not_fit(spec_, memory.total); !why.empty()) throw core::InputError(why);
        for (const std::string& warning : plan.warnings(spec_, no_space ? -1.0 : free_bytes, memory.available)) {
            if (!options_.quiet) fmt::print(stderr, "{}\n", warning);
            if (log) log->warn(warning);
        }
        if (!restart) write_output();
        const Cadence checkpoints{spec_.checkpoint_interval};
        const bool timed_checkpoints = spec_.checkpoint_interval > 0.0;
        long next_output = outputs.next_after(c.time);
        long next_checkpoint = timed_checkpoints ? checkpoints.next_after(c.time) : 0;
        while (c.time < end * (1.0 - same_time_tolerance)) {
            const double target = std::min(end, outputs.at(next_output));
            c.dt = step_toward(c.time, target, c.dt);  // land exactly on the output time, in equal steps
            step();
            if (governor) {
                if (const std::string change = governor->after_step(); !change.empty()) {
                    ++thread_changes_;
                    if (log) log->info(fmt::format("step {} (t = {:.9g} s): {}", c.step, c.time, change));
                }
            }
            thread_steps_ += parallel::max_threads();
            ++thread_step_count_;
            if (options_.dump_from_step > 0 && c.step >= options_.dump_from_step) write_dump();
            show_progress(false);
            if (c.time >= target * (1.0 - same_time_tolerance)) {
                write_output();
                next_output = std::max(next_output + 1, outputs.next_after(c.time));
            }
            if (timed_checkpoints && c.time >= checkpoints.at(next_checkpoint) * (1.0 - same_time_tolerance)) {
                write_checkpoint();
                next_checkpoint = std::max(next_checkpoint + 1, checkpoints.next_after(c.time));
            } else if (control.wall_checkpoint_due()) {
                write_checkpoint();
            }
            if (const auto stop = control.stop_requested()) {
                // Stop cleanly: a checkpoint to continue from, and the state now as a snapshot.
                progress.finish();
                std::string message = fmt::format("{} at step {} (t = {:.9g} s)", stop->reason, c.step, c.time);
                const int signal = stop->signal;
                if (options_.write_files) {
                    write_checkpoint();
                    if (has_sph_) {
                        const auto file = fmt::format("snapshots/{}_interrupted_{:06}.vtu", spec_.name, c.step);
                        io::write_vtu(options_.output_dir / file, named_snapshot(state_.particles, spec_));
                        message += "; state written to " + (options_.output_dir / file).string();
                    }
                    message += "; continue with --restart " + options_.output_dir.string();
                }
                write_summary(summarize(segment_clock_.seconds(), "interrupted"), message);
                if (log) log->warn(message);
                throw Interrupted(signal, message);
            }
        }
        show_progress(true);
        progress.finish();
    } catch (const core::BlowUpError& e) {
        progress.finish();
        write_summary(summarize(segment_clock_.seconds(), "blow_up"), e.what());
        if (log) log->error(e.what());
        throw;
    }
    write_checkpoint();  // a finished run can be extended: --restart DIR --set time.end=...
    RunSummary summary = summarize(segment_clock_.seconds(), "completed");
    write_summary(summary, "");
    if (log)
        log->info(fmt::format("completed: {} steps to t = {:.6g} s, {} particles, {:.3g} s wall, {:.3g} particle-steps/s",
                              summary.steps, summary.end_time, summary.particles, summary.wall_time_s,
                              summary.particle_steps_per_second));
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
