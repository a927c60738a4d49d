// A run of one case: its modules assembled over one state, and the run loop (prime, step, advance to the
// output times, the time step, the output and checkpoint cadence). Elsewhere: the health check and last good
// state (simulation_health.cpp), outputs (simulation_output.cpp), checkpoints (simulation_checkpoint.cpp),
// the summary (simulation_summary.cpp), the modules themselves (module_catalog.hpp, modules/catalog.cpp).
#include "grit/sim/simulation.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "grit/core/error.hpp"
#include "grit/modules/analyses.hpp"
#include "grit/parallel/parallel.hpp"
#include "grit/parallel/thread_governor.hpp"
#include "grit/sim/module_catalog.hpp"
#include "grit/sim/output_times.hpp"
#include "grit/sim/particle_blocks.hpp"
#include "grit/sim/periodic_lengths.hpp"
#include "grit/sim/progress.hpp"
#include "grit/sim/run_control.hpp"
#include "grit/sim/run_log.hpp"
#include "grit/sim/step_to_target.hpp"

namespace grit::sim {

template <int Dim>
Simulation<Dim>::Simulation(io::CaseSpec spec, RunOptions options)
    : spec_(std::move(spec)),
      options_(std::move(options)),
      kernel_(sph::CubicSpline<Dim>(1.0)),
      setup_{spec_,   spec_.particle_spacing, spec_.smoothing_ratio * spec_.particle_spacing, kernel_, 0.0,
             periodic_box_of<Dim>(spec_), comm_} {
    if (spec_.dimension != Dim) throw std::logic_error("case dimension does not match the simulation");
    sph::make_kernel<Dim>(spec_.kernel, setup_.smoothing_length, kernel_);
    double fastest = 0.0;
    for (const auto& m : spec_.materials) fastest = std::max(fastest, m.signal_speed());
    for (const auto& in : spec_.inlets) fastest = std::max(fastest, in.velocity);
    setup_.max_speed = spec_.max_speed > 0.0 ? spec_.max_speed : 2.0 * fastest;

    has_sph_ = spec_.has_sph();
    if (has_sph_) check_periodic_lengths(setup_);

    // The modules the case wants (modules/catalog.cpp): first those that register SPH fields, then the
    // particles, then those that need them (the grains and what acts on both sets).
    make_modules(BuildTime::before_particles, spec_, state_, setup_, modules_);
    add_particle_blocks<Dim>(spec_, setup_.spacing, state_.particles);
    for (auto& m : modules_) m->initialise();
    check_and_wrap_into_domain(spec_, setup_.periodic_box, state_.particles);
    const std::size_t placed = modules_.size();
    make_modules(BuildTime::after_particles, spec_, state_, setup_, modules_);
    for (std::size_t k = placed; k < modules_.size(); ++k) modules_[k]->initialise();
    order_modules(modules_);
    probes_ = module<modules::ProbesModule<Dim>>();

    for (auto& m : modules_) {
        pipeline_.set_installer(m->name());
        m->install(pipeline_);
    }
    pipeline_.set_installer("simulation");
    pipeline_.add(Hook::check, "health_check", [this] { check_health(); });
    pipeline_.add(Hook::check, "time_step", [this] { compute_time_step(); }, true);
}

template <int Dim>
Simulation<Dim>::~Simulation() = default;

template <int Dim>
void Simulation<Dim>::compute_time_step() {
    // Eq. (51): the smallest of the modules' stable steps (SPH CFL, DEM), capped by time.max_step.
    double dt = std::numeric_limits<double>::max();
    for (const auto& m : modules_) dt = std::min(dt, m->stable_time_step());
    auto& clock = state_.clock;
    clock.dt = std::min(comm_.min(dt), spec_.max_time_step);  // one step for every sub-domain
    clock.dt_stable = clock.dt;
    if (!(clock.dt < std::numeric_limits<double>::max()))
        throw core::InputError("nothing sets a time step: the case has no particles that move");
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
    if (!probes_) throw std::out_of_range("the case has no probes");
    return probes_->value(k);
}

template <int Dim>
double Simulation<Dim>::probe(const std::string& name) const {
    if (!probes_) throw std::out_of_range("no probe named '" + name + "': the case has no probes");
    return probes_->value(name);
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
    std::unique_ptr<RunLog> log = open_run_log(restart);
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
        check_plan(log.get());
        if (!restart) {
            write_output();
            if (options_.on_output) options_.on_output(c.time, c.step);
        }
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
                if (options_.on_output) options_.on_output(c.time, c.step);
            }
            if (timed_checkpoints && c.time >= checkpoints.at(next_checkpoint) * (1.0 - same_time_tolerance)) {
                write_checkpoint();
                next_checkpoint = std::max(next_checkpoint + 1, checkpoints.next_after(c.time));
            } else if (control.wall_checkpoint_due()) {
                write_checkpoint();
            }
            if (const auto stop = control.stop_requested()) {
                progress.finish();
                stop_cleanly(stop->reason, stop->signal, log.get());
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
