// A module owns one piece of physics end to end (DESIGN.md section 2): it registers its fields, installs
// its stages at the pipeline's hook points, gives its stable time step, supplies its output values
// (name and value in one place, for series.csv and summary.json), checks its own health, writes its own
// output files and saves and loads what it holds beyond the State.
#pragma once

#include <nlohmann/json_fwd.hpp>

#include <filesystem>
#include <limits>
#include <string>
#include <vector>

#include "grit/domain/comm.hpp"
#include "grit/io/case_spec.hpp"
#include "grit/io/hdf5_file.hpp"
#include "grit/neighbors/periodic_box.hpp"
#include "grit/sim/pipeline.hpp"
#include "grit/sim/state.hpp"
#include "grit/sph/kernels.hpp"

namespace grit::sim {

/// One output value: a column of series.csv and/or a key of summary.json, with how the values of several
/// sub-domains combine into it, e.g. `OutputValue::real("eroded_mass", m, Combine::sum)`,
/// `OutputValue::count("grains", n, Combine::sum).summary_only()`.
struct OutputValue {
    std::string name;
    double value = 0.0;
    domain::Combine combine = domain::Combine::whole_set;
    bool integer = false;    ///< written to summary.json as a whole number
    bool in_series = true;   ///< a series.csv column
    bool in_summary = true;  ///< a summary.json key
    std::string group;       ///< summary.json: under this object (e.g. "probes"); empty: top level
    std::string unit;        ///< summary.json's "units"; empty: sim/output_units.cpp's table names it

    static OutputValue real(std::string name, double value, domain::Combine combine) {
        return {std::move(name), value, combine, false, true, true, {}, {}};
    }
    static OutputValue count(std::string name, double value, domain::Combine combine) {
        return {std::move(name), value, combine, true, true, true, {}, {}};
    }
    OutputValue series_only() && {
        in_summary = false;
        return std::move(*this);
    }
    OutputValue summary_only() && {
        in_series = false;
        return std::move(*this);
    }
    OutputValue in_group(std::string g) && {
        group = std::move(g);
        return std::move(*this);
    }
    OutputValue in_unit(std::string u) && {
        unit = std::move(u);
        return std::move(*this);
    }
};

/// The periodic box of a case: the axes of domain.periodic between domain.min and domain.max.
template <int Dim>
neighbors::PeriodicBox<Dim> periodic_box_of(const io::CaseSpec& spec) {
    std::array<bool, Dim> axes{};
    for (int k = 0; k < Dim; ++k)
        axes[k] = static_cast<std::size_t>(k) < spec.periodic.size() && spec.periodic[static_cast<std::size_t>(k)];
    const bool bounds = spec.domain_min.size() == Dim && spec.domain_max.size() == Dim;
    return neighbors::PeriodicBox<Dim>::make(axes, bounds ? core::to_vec<Dim>(spec.domain_min) : core::Vec<Dim>::zero(),
                                             bounds ? core::to_vec<Dim>(spec.domain_max) : core::Vec<Dim>::zero());
}

/// Set-up shared by the modules of a run, fixed for the run.
template <int Dim>
struct RunSetup {
    const io::CaseSpec& spec;
    double spacing;           ///< dx [m]
    double smoothing_length;  ///< h [m]
    const sph::Kernel<Dim>& kernel;
    double max_speed;         ///< faster is a blow-up [m/s]
    /// The periodic axes of the SPH particles and the grains (domain.periodic); none: any() is false.
    /// Every loop that forms x_a - x_b of two points takes its nearest image along them.
    neighbors::PeriodicBox<Dim> periodic_box;
    /// The run's reductions across sub-domains (one process: domain::SerialComm).
    const domain::Comm& comm;
};

/// Where output files go (only when files are written).
struct OutputPlace {
    std::filesystem::path dir;
    std::string name;        ///< the case's base name
    bool snapshots = true;   ///< output.snapshots
};

template <int Dim>
class Module {
public:
    virtual ~Module() = default;
    /// A short name (checkpoint group, messages).
    virtual std::string name() const = 0;

    /// Adds the module's stages to the pipeline (called once, in module order).
    virtual void install(Pipeline& pipeline) = 0;
    /// After the initial particles are built (start values of its fields, checks of its set-up).
    virtual void initialise() {}
    /// Before the first step's prime stages: what the first state needs (lists, first forces).
    virtual void prime() {}
    /// Largest stable step of this module's physics [s]; infinity when it sets none.
    virtual double stable_time_step() const { return std::numeric_limits<double>::infinity(); }
    /// Empty, or what went wrong with which particle (the Simulation adds the step and writes the last
    /// good state).
    virtual std::string check_health() const { return {}; }
    /// Output values at the current state, in column order.
    virtual void output_values(std::vector<OutputValue>& /*out*/) const {}
    /// What summary.json should say of the module's set-up, beyond its output values (the crater's
    /// region, which `grit plot` and `grit crater` read back).
    virtual void describe(nlohmann::ordered_json& /*summary*/) const {}

    /// Output files of its own: `open` before the first output (`restart`: continue the files of the
    /// run a checkpoint came from), `write` at each output time.
    virtual void open_output(const OutputPlace& /*place*/, bool /*restart*/) {}
    virtual void write_output(const OutputPlace& /*place*/) {}

    /// Writes the records its log files (eroded.csv, ...) still buffer: called before a checkpoint
    /// records how many rows they hold. Touches the files only, never the run.
    virtual void flush_logs() {}
    /// What the module holds beyond the State (inlet progress, output counters), for a checkpoint.
    /// const: writing a checkpoint cannot change the run it is taken from.
    virtual void save(io::Hdf5Group& /*group*/) const {}
    virtual void load(const io::Hdf5Group& /*group*/) {}
    /// Whether a checkpoint without this module's group (written by a grit before the module ran in such
    /// a case) can be continued, the module starting afresh; if not, such a checkpoint is refused.
    virtual bool continues_without_saved_state() const { return false; }
};

}  // namespace grit::sim
