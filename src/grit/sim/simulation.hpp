// A run of one case: the run state, the modules the case needs, the step pipeline they install, the run
// loop with its outputs, the health check and the last-good backup, and checkpoints (each part in its own
// simulation_*.cpp).
#pragma once

#include <filesystem>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "grit/core/timer.hpp"
#include "grit/io/case_spec.hpp"
#include "grit/io/pvd_writer.hpp"
#include "grit/io/series_writer.hpp"
#include "grit/sim/module.hpp"
#include "grit/sim/pipeline.hpp"
#include "grit/sim/run_estimate.hpp"
#include "grit/sim/state.hpp"
#include "grit/sph/kernels.hpp"

namespace grit::modules {
template <int Dim>
class ProbesModule;
}

namespace grit::sim {

class RunLog;

struct RunOptions {
    std::filesystem::path output_dir;
    bool quiet = false;
    bool write_files = true;  ///< false: run in memory only (tests, benchmarks)
    /// Continue from this checkpoint file, or from the latest checkpoint in this run folder; empty: a
    /// fresh run.
    std::filesystem::path restart;
    /// From this step on (> 0), the SPH particles are written after every step to
    /// dump/<case>_step_<N>.vtu: what starts a blow-up, which happens between two outputs.
    long dump_from_step = 0;
    /// Use fewer threads while another process holds a core, and take them back when it is free
    /// (parallel::ThreadGovernor; the CLI's runs). Results do not depend on the thread count.
    bool adapt_threads = false;
    /// A plain progress line (step, t, rate, ETA) this often [s of wall time] in run.log, and on standard
    /// error when it is not a terminal (0: none; a terminal's live line is kept up to date regardless).
    double progress_every_s = 30.0;
    /// Stop with a checkpoint after this much wall time [s] (--max-wall-time; 0: no limit).
    double max_wall_time_s = 0.0;
    /// Called after each output is written, with the time and step (the Python module's progress callback).
    /// What it throws ends the run there, without a checkpoint.
    std::function<void(double time, long step)> on_output;
};

/// What a finished run reports (also written to summary.json).
struct RunSummary {
    std::string status;  ///< "completed", "interrupted" or "blow_up"
    Index particles = 0;
    long steps = 0;
    double end_time = 0.0;
    double wall_time_s = 0.0;          ///< over every segment of the run (a restart adds its own)
    double segment_wall_time_s = 0.0;  ///< of this process's segment alone
    std::int64_t segments = 1;         ///< 1 for a run that never stopped, +1 for each restart
    double particle_steps_per_second = 0.0;
    double pair_interactions_per_second = 0.0;
    std::vector<OutputValue> values;  ///< every output value (series and summary) at the end
    std::vector<double> momentum;
    std::vector<core::TimerEntry> stages;
    std::string restarted_from;  ///< the checkpoint a restarted run continued, or empty
    std::string message;         ///< a note for the user (a restart already at time.end), or empty

    /// The value named `name` (throws std::out_of_range if there is none).
    double value(const std::string& name) const;
};

/// Thrown when the run stopped before time.end after writing its checkpoint: on SIGINT, SIGTERM or SIGUSR1
/// (the CLI exits with 128 + signal: 130 for Ctrl-C, 143 for SIGTERM, 138 for SIGUSR1) or at the wall-time
/// limit (signal 0; exit 0, as a batch job's planned stop).
class Interrupted : public std::runtime_error {
public:
    Interrupted(int signal, const std::string& what) : std::runtime_error(what), signal_(signal) {}
    int signal() const noexcept { return signal_; }

private:
    int signal_;
};

template <int Dim>
class Simulation {
public:
    using Vec = core::Vec<Dim>;

    /// Builds the state and modules of `spec`. Throws core::InputError for an impossible case.
    Simulation(io::CaseSpec spec, RunOptions options);
    ~Simulation();
    Simulation(const Simulation&) = delete;
    Simulation& operator=(const Simulation&) = delete;

    /// Runs to the case's end time (from the checkpoint of options.restart if given). Throws
    /// core::BlowUpError (after writing the last good snapshot), Interrupted on SIGINT/SIGTERM (after
    /// writing a checkpoint), core::InputError for a checkpoint that does not fit the case.
    RunSummary run();

    /// Advances one time step (public for tests and benchmarks).
    void step();
    /// Steps until time() reaches `target` exactly (primes the rates first if needed).
    void advance_to(double target, const std::function<void()>& after_each_step = {});
    /// Computes the rates of the current state (before the first step).
    void prime();
    /// The cost of running to time.end from the current state (primes it if needed).
    RunEstimate estimate();

    /// Writes the run state and every module's own state to `file` (atomically: a temporary file, then
    /// a rename). Continuing from it is bit-identical to not stopping, and writing it does not change the
    /// run: the log files are flushed, then write_checkpoint_file, which is const, writes it.
    void save_checkpoint(const std::filesystem::path& file);
    /// Reads a checkpoint written by a run of this case. Throws core::InputError naming what does not fit
    /// (another case, another spacing, dimension or materials, another format version, an unreadable file).
    void load_checkpoint(const std::filesystem::path& file);

    State<Dim>& state() { return state_; }
    particles::SphParticles<Dim>& particles() { return state_.particles; }
    double time() const { return state_.clock.time; }
    double time_step() const { return state_.clock.dt; }
    long steps() const { return state_.clock.step; }
    double mass_in() const { return state_.ledger.in; }
    double mass_out() const { return state_.ledger.out; }
    double eroded_mass() const { return state_.ledger.eroded; }
    const Pipeline& pipeline() const { return pipeline_; }
    std::size_t pair_count() const { return state_.neighbors.list().pair_count(); }
    /// Value of probe k (case order) now.
    double probe(std::size_t k) const;
    /// Value of the probe named `name` now (throws std::out_of_range if there is none).
    double probe(const std::string& name) const;
    const io::CaseSpec& spec() const { return spec_; }
    /// The grains, or null when the case has none.
    dem::DemSystem<Dim>* grains() { return state_.grains.get(); }
    const wear::ImpactLog& impacts() const { return state_.impacts; }
    /// The run's module of type M (e.g. modules::MeshWearModule<Dim>, for its wear map), or null.
    template <class M>
    const M* module() const {
        for (const auto& m : modules_)
            if (const auto* found = dynamic_cast<const M*>(m.get())) return found;
        return nullptr;
    }
    /// Every output value at the current state, in column order.
    std::vector<OutputValue> output_values() const;

private:
    void write_checkpoint_file(const std::filesystem::path& file) const;
    void check_health();
    /// The first particle, grain or module state that is not healthy, described; empty when all are.
    std::string find_unhealthy() const;
    /// Throws core::BlowUpError naming the step, `what` and the last good snapshot (written first).
    [[noreturn]] void report_blow_up(const std::string& what);
    /// Prints and logs the run's estimate; throws core::InputError when it cannot fit this machine's memory,
    /// warns when it may not fit the free memory or disk.
    void check_plan(RunLog* log);
    void compute_time_step();
    void open_output(bool restart);
    /// The run log (null when no files are written), with what a restart changed.
    std::unique_ptr<RunLog> open_run_log(bool restart);
    /// Writes a checkpoint, the state now as a snapshot and the summary, then throws Interrupted.
    [[noreturn]] void stop_cleanly(const std::string& reason, int signal, RunLog* log);
    void write_output();
    /// The SPH particles of this step to dump/<case>_step_<N>.vtu (RunOptions::dump_from_step).
    void write_dump();
    void write_checkpoint();
    void write_summary(const RunSummary& summary, const std::string& message) const;
    RunSummary summarize(double wall_time, const std::string& status) const;

    io::CaseSpec spec_;
    RunOptions options_;
    sph::Kernel<Dim> kernel_;
    domain::SerialComm comm_;
    RunSetup<Dim> setup_;
    State<Dim> state_;
    std::vector<std::unique_ptr<Module<Dim>>> modules_;
    const modules::ProbesModule<Dim>* probes_ = nullptr;
    Pipeline pipeline_;
    bool has_sph_ = true;  ///< false for a grains-only case: no SPH module
    bool primed_ = false;
    double particle_steps_ = 0.0, pair_steps_ = 0.0;  ///< of this session (for the rates)
    core::Stopwatch segment_clock_;  ///< wall time of this segment (this process's part of the run)
    /// The segments of the run before the checkpoint this one continues (summary.json sums them all).
    struct EarlierSegments {
        std::int64_t count = 0;
        double wall_time_s = 0.0, particle_steps = 0.0, pair_steps = 0.0;
    } earlier_;
    int run_threads_ = 0;     ///< the threads run() started with (the governor's ceiling)
    int thread_changes_ = 0;  ///< how often the governor changed the count
    double thread_steps_ = 0.0;   ///< threads summed over this segment's steps (summary.json's threads_used_mean)
    long thread_step_count_ = 0;

    particles::SphParticles<Dim> last_good_;
    double last_good_time_ = 0.0;
    long last_good_step_ = 0;
    bool blow_up_reported_ = false;  ///< set once report_blow_up has thrown, so step() passes it on as it is

    OutputPlace place_;
    long snapshot_index_ = 0;
    std::unique_ptr<io::PvdWriter> pvd_;
    std::unique_ptr<io::SeriesWriter> series_;
    std::vector<io::PvdWriter::Entry> restored_pvd_;
    long restored_series_rows_ = 0;
    std::vector<std::string> restart_notes_;  ///< what a restart from an older grit's checkpoint changed
    std::filesystem::path restarted_from_;
};

extern template class Simulation<2>;
extern template class Simulation<3>;

/// Runs `spec` in its dimension; returns the summary. Used by the CLI and tests.
RunSummary run_case(const io::CaseSpec& spec, const RunOptions& options);

/// The checkpoint a restart from `path` continues: `path` itself if it is a file, else the latest
/// (highest step) `checkpoints/*.h5` in the run folder `path`. Throws core::InputError if there is none.
std::filesystem::path resolve_checkpoint(const std::filesystem::path& path);

/// The --set overrides the checkpointed run of case `case_name` was started with, in order (none for a
/// checkpoint of another case, one written before they were kept, or a file that is not a checkpoint).
std::vector<std::string> checkpoint_overrides(const std::filesystem::path& checkpoint, const std::string& case_name);

}  // namespace grit::sim
