// A run of one case: the particle set, the models chosen by the case, the step pipeline and outputs.
#pragma once

#include <filesystem>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "grit/analysis/cracks.hpp"
#include "grit/analysis/crater.hpp"
#include "grit/analysis/diagnostics.hpp"
#include "grit/boundary/jet_inlet.hpp"
#include "grit/core/timer.hpp"
#include "grit/io/case_spec.hpp"
#include "grit/io/pvd_writer.hpp"
#include "grit/io/series_writer.hpp"
#include "grit/neighbors/cell_grid.hpp"
#include "grit/neighbors/neighbor_list.hpp"
#include "grit/particles/sph_particles.hpp"
#include "grit/sim/grain_phase.hpp"
#include "grit/sim/pipeline.hpp"
#include "grit/sph/fluid_rates.hpp"
#include "grit/sph/kernels.hpp"
#include "grit/sph/solid_rates.hpp"

namespace grit::sim {

struct RunOptions {
    std::filesystem::path output_dir;
    bool quiet = false;
    bool write_files = true;  ///< false: run in memory only (tests, benchmarks)
};

/// What a finished run reports (also written to summary.json).
struct RunSummary {
    Index particles = 0;
    long steps = 0;
    double end_time = 0.0;
    double wall_time_s = 0.0;
    double particle_steps_per_second = 0.0;
    double pair_interactions_per_second = 0.0;
    double kinetic_energy = 0.0, mass_total = 0.0, mass_in = 0.0, mass_out = 0.0, max_velocity = 0.0;
    bool has_solids = false, has_crater = false;
    double eroded_mass = 0.0, max_plastic_strain = 0.0, internal_energy = 0.0;
    double crater_depth = 0.0, crater_width = 0.0;
    bool has_cracks = false;
    double damaged_area = 0.0;  ///< [m^2 per metre of thickness in 2D; m^3 in 3D]
    Index crack_count = 0;
    bool has_grains = false;
    Index grains = 0;
    double grain_kinetic_energy = 0.0;
    std::size_t impacts = 0;
    std::vector<double> momentum;
    std::vector<std::string> probe_names;
    std::vector<double> probe_values;
    std::vector<core::TimerEntry> stages;
};

template <int Dim>
class Simulation {
public:
    using Vec = core::Vec<Dim>;

    /// Builds the particles and models of `spec`. Throws core::InputError for an impossible case.
    Simulation(io::CaseSpec spec, RunOptions options);

    /// Runs to the case's end time. Throws core::BlowUpError (after writing the last good snapshot).
    RunSummary run();

    /// Advances one time step (public for tests and benchmarks).
    void step();
    /// Steps until time() reaches `target` exactly (primes the rates first if needed).
    void advance_to(double target, const std::function<void()>& after_each_step = {});
    /// Computes the rates of the current state (before the first step).
    void prime();

    particles::SphParticles<Dim>& particles() { return particles_; }
    double time() const { return time_; }
    double time_step() const { return dt_; }
    long steps() const { return step_; }
    double mass_in() const { return mass_in_; }
    double mass_out() const { return mass_out_; }
    double eroded_mass() const { return eroded_mass_; }
    const Pipeline& pipeline() const { return pipeline_; }
    std::size_t pair_count() const { return neighbors_.pair_count(); }
    double probe(std::size_t k) const;
    /// Value of the probe named `name` now (throws std::out_of_range if there is none).
    double probe(const std::string& name) const;
    const io::CaseSpec& spec() const { return spec_; }
    /// The grains, or null when the case has none.
    GrainPhase<Dim>* grains() { return grains_.get(); }

private:
    void build_particles();
    void build_pipeline();

    void integrate_predict();
    void integrate_update();
    void apply_boundaries();
    void update_neighbors(bool force);
    void compute_time_step();
    void register_solid_fields();
    struct SolidMeasures {
        double max_plastic_strain = 0.0;
        double internal_energy = 0.0;  ///< sum of m e over solids [J]
        analysis::CraterProfile crater;
        analysis::CrackMeasures cracks;
    };
    SolidMeasures solid_measures() const;
    void update_solid_stress();
    void apply_brittle_pressure();
    void remove_failed_solids();
    /// True for particles the integrator moves: fluid, and solids that are not clamped.
    bool moves(Index i) const;
    void check_health();

    void write_output();
    void write_summary(const RunSummary& summary, const std::string& status, const std::string& message) const;
    RunSummary summarize(double wall_time) const;

    io::CaseSpec spec_;
    RunOptions options_;
    particles::SphParticles<Dim> particles_;
    sph::Kernel<Dim> kernel_;
    double spacing_, smoothing_length_;
    sph::FluidRateParameters<Dim> fluid_parameters_;
    std::vector<double> signal_speed_;  ///< per material: the wave speed of the CFL condition [m/s]
    sph::SphWorkspace sph_workspace_;
    bool has_solids_ = false;
    bool has_sph_ = true;  ///< false for a grains-only case: the SPH stages are left out
    sph::SolidRateParameters<Dim> solid_parameters_;
    sph::SolidWorkspace solid_workspace_;
    double eroded_mass_ = 0.0;
    std::vector<bool> brittle_;  ///< per material: a JH-2 solid (fractured particles stay until detached)
    std::unique_ptr<GrainPhase<Dim>> grains_;
    double dt_stable_ = 0.0;  ///< the last stable step, before any shortening to land on an output time
    std::vector<boundary::JetInlet<Dim>> inlets_;
    Vec domain_min_, domain_max_;
    double max_speed_;

    neighbors::CellGrid<Dim> grid_;
    neighbors::NeighborList<Dim> neighbors_;
    std::vector<Index> order_, cell_start_;
    bool neighbors_stale_ = true;
    bool primed_ = false;
    long neighbor_builds_ = 0;

    Pipeline pipeline_;
    double time_ = 0.0, dt_ = 0.0;
    long step_ = 0;
    double particle_steps_ = 0.0, pair_steps_ = 0.0;
    double mass_in_ = 0.0, mass_out_ = 0.0;

    particles::SphParticles<Dim> last_good_;
    double last_good_time_ = 0.0;
    long last_good_step_ = 0;

    double next_output_ = 0.0;
    long snapshot_index_ = 0;
    std::unique_ptr<io::PvdWriter> pvd_;
    std::unique_ptr<io::SeriesWriter> series_;
};

extern template class Simulation<2>;
extern template class Simulation<3>;

/// Reads nothing, runs `spec` in its dimension; returns the summary. Used by the CLI and tests.
RunSummary run_case(const io::CaseSpec& spec, const RunOptions& options);

}  // namespace grit::sim
