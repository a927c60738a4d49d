// A run of one case: modules over one state, the run loop, outputs, health check, checkpoints.
#include "grit/sim/simulation.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <optional>
#include <nlohmann/json.hpp>
#include <sstream>
#include <system_error>

#include "grit/analysis/diagnostics.hpp"
#include "grit/core/error.hpp"
#include "grit/io/durable_file.hpp"
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

// 2: grain-grain contact histories are held by the grain of lower index (was: lower id), one entry per
// pair of the cut lists (dem::ContactHistory). 3: grains carry `collisions` and `grain_contact`, the grains
// module the collisions of the grains that left.
constexpr std::int64_t checkpoint_format_version = 3;

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

std::string read_text(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

constexpr const char* periodic_state_key = "domain.periodic";
constexpr const char* symmetry_state_key = "domain.symmetry";

std::string periodic_axes(const io::CaseSpec& spec) {
    std::string axes;
    for (std::size_t k = 0; k < spec.periodic.size(); ++k)
        if (spec.periodic[k]) axes += static_cast<char>('x' + k);
    return axes;
}

// The keys a checkpoint's state depends on: a restart with other values is refused.
std::vector<std::pair<std::string, std::string>> state_keys(const io::CaseSpec& spec) {
    std::string materials, grain_materials;
    for (const auto& m : spec.materials) materials += (materials.empty() ? "" : ", ") + m.name;
    for (const auto& m : spec.grain_materials) grain_materials += (grain_materials.empty() ? "" : ", ") + m.name;
    std::vector<std::pair<std::string, std::string>> keys = {
        {"simulation.dimension", std::to_string(spec.dimension)},
        {"numerics.particle_spacing", fmt::format("{:.17g}", spec.particle_spacing)},
        {"numerics.smoothing_ratio", fmt::format("{:.17g}", spec.smoothing_ratio)},
        {"numerics.kernel", spec.kernel},
        {"materials", materials},
        {"grain materials", grain_materials}};
    // Only where some axis is periodic, so that the checkpoints of other cases stay as they were.
    if (spec.any_periodic()) keys.emplace_back(periodic_state_key, periodic_axes(spec));
    if (spec.symmetry_plane) keys.emplace_back(symmetry_state_key, "x");  // the particles are a half
    return keys;
}

// The step number of checkpoints/checkpoint_<step>.h5, or -1 for another name.
long checkpoint_step(const std::filesystem::path& file) {
    const std::string stem = file.stem().string();
    if (file.extension() != ".h5" || stem.rfind("checkpoint_", 0) != 0) return -1;
    try {
        return std::stol(stem.substr(11));
    } catch (const std::exception&) {
        return -1;
    }
}

std::vector<std::filesystem::path> checkpoints_in(const std::filesystem::path& dir) {
    std::vector<std::filesystem::path> out;
    if (!std::filesystem::is_directory(dir)) return out;
    for (const auto& e : std::filesystem::directory_iterator(dir))
        if (checkpoint_step(e.path()) >= 0) out.push_back(e.path());
    std::sort(out.begin(), out.end(),
              [](const auto& a, const auto& b) { return checkpoint_step(a) < checkpoint_step(b); });
    return out;
}

nlohmann::ordered_json json_number(const OutputValue& v) {
    if (!std::isfinite(v.value)) return nullptr;
    if (v.integer) return static_cast<long long>(v.value);
    return v.value;
}

}  // namespace

double RunSummary::value(const std::string& name) const {
    for (const auto& v : values)
        if (v.name == name) return v.value;
    throw std::out_of_range("no output value named '" + name + "'");
}

std::filesystem::path resolve_checkpoint(const std::filesystem::path& path) {
    if (std::filesystem::is_regular_file(path)) return path;
    if (!std::filesystem::is_directory(path))
        throw core::InputError(fmt::format("--restart {}: no such checkpoint file or run folder", path.string()));
    const auto found = checkpoints_in(path / "checkpoints");
    if (found.empty())
        throw core::InputError(fmt::format("--restart {}: the folder has no checkpoints/checkpoint_*.h5", path.string()));
    return found.back();
}

std::vector<std::string> checkpoint_overrides(const std::filesystem::path& checkpoint, const std::string& case_name) {
    std::vector<std::string> overrides;
    try {
        const auto h5 = io::Hdf5File::open(checkpoint);
        // Another case's checkpoint: its keys may not exist here, and the restart refuses it anyway.
        if (!h5.has_attribute("case_name") || h5.read_string("case_name") != case_name) return overrides;
        if (!h5.has_attribute("override_count")) return overrides;  // written before grit kept them
        const std::int64_t n = h5.read_int("override_count");
        for (std::int64_t k = 0; k < n; ++k) overrides.push_back(h5.read_string(fmt::format("override {}", k)));
    } catch (const std::exception&) {
        return {};  // not a readable checkpoint: the restart itself says so, naming the file
    }
    return overrides;
}

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
void Simulation<Dim>::save_checkpoint(const std::filesystem::path& file) {
    // The logs first: the checkpoint records how many rows each holds, and a restart keeps those.
    state_.impacts.flush();
    for (auto& m : modules_) m->flush_logs();
    write_checkpoint_file(file);
}

template <int Dim>
void Simulation<Dim>::write_checkpoint_file(const std::filesystem::path& file) const {
    namespace fs = std::filesystem;
    // Written whole under a temporary name, then put in place (io/durable_file.hpp): a run killed at any
    // moment, or a disk that fills, leaves the previous checkpoint as it was.
    const fs::path temporary = io::temporary_name(file);
    try {
        auto h5 = io::Hdf5File::create(temporary);
        h5.write("format", "grit checkpoint");
        h5.write("format_version", checkpoint_format_version);
        h5.write("grit_version", std::string(version));
        h5.write("git_revision", std::string(git_revision()));
        h5.write("case_name", spec_.name);
        h5.write("case_file", spec_.source.string());
        h5.write("case_text", read_text(spec_.source));
        // The --set overrides: a restart applies them again before its own (checkpoint_overrides).
        h5.write("override_count", static_cast<std::int64_t>(spec_.overrides.size()));
        for (std::size_t k = 0; k < spec_.overrides.size(); ++k)
            h5.write(fmt::format("override {}", k), spec_.overrides[k]);
        for (const auto& [key, value] : state_keys(spec_)) h5.write("state_key " + key, value);
        const auto& clock = state_.clock;
        h5.write("time", clock.time);
        h5.write("step", static_cast<std::int64_t>(clock.step));

        auto run = h5.create_group("run");
        run.write("time", clock.time);
        run.write("step", static_cast<std::int64_t>(clock.step));
        run.write("dt", clock.dt);
        run.write("dt_stable", clock.dt_stable);
        run.write("mass_in", state_.ledger.in);
        run.write("mass_out", state_.ledger.out);
        run.write("eroded_mass", state_.ledger.eroded);
        // What is due next (a restart derives both from the time: output_times.hpp).
        const Cadence outputs{spec_.output_interval};
        run.write("next_output", outputs.at(outputs.next_after(clock.time)));
        const Cadence checkpoints{spec_.checkpoint_interval};
        run.write("next_checkpoint",
                  spec_.checkpoint_interval > 0.0 ? checkpoints.at(checkpoints.next_after(clock.time)) : 0.0);
        run.write("snapshot_index", static_cast<std::int64_t>(snapshot_index_));
        // The run's totals so far, this segment's included: summary.json sums the segments.
        run.write("segments", earlier_.count + 1);
        run.write("wall_time_s", earlier_.wall_time_s + segment_clock_.seconds());
        run.write("particle_steps", earlier_.particle_steps + particle_steps_);
        run.write("pair_steps", earlier_.pair_steps + pair_steps_);
        run.write("series_rows", static_cast<std::int64_t>(series_ ? series_->rows() : restored_series_rows_));
        io::save_pvd_entries(run, "pvd", pvd_ ? pvd_->entries() : restored_pvd_);

        auto particles = h5.create_group("particles");
        state_.particles.save(particles);
        auto neighbors = h5.create_group("neighbors");
        state_.neighbors.save(neighbors, state_.particles);
        if (state_.grains) {
            auto grains = h5.create_group("dem");
            state_.grains->save(grains);
        }
        auto impacts = h5.create_group("impacts");
        state_.impacts.save(impacts);
        auto modules = h5.create_group("modules");
        for (auto& m : modules_) {
            auto g = modules.create_group(m->name());
            m->save(g);
        }
        h5.close();
    } catch (const io::Hdf5Error& e) {
        std::error_code ignored;
        fs::remove(temporary, ignored);
        throw std::runtime_error(fmt::format("cannot write the checkpoint {} ({}); the checkpoints written before "
                                             "it are intact",
                                             file.string(), e.what()));
    }
    try {
        io::commit_file(temporary, file);
    } catch (const std::system_error& e) {
        throw std::runtime_error(fmt::format("{}; the checkpoints written before it are intact", e.what()));
    }
}

template <int Dim>
void Simulation<Dim>::load_checkpoint(const std::filesystem::path& file) {
    const std::string where = "checkpoint " + file.string();
    try {
        const auto h5 = io::Hdf5File::open(file);
        if (!h5.has_attribute("format") || h5.read_string("format") != "grit checkpoint")
            throw core::InputError(where + ": not a grit checkpoint");
        const auto version_found = h5.read_int("format_version");
        if (version_found != checkpoint_format_version)
            throw core::InputError(fmt::format("{}: format version {}, this grit reads version {} (grit {} wrote it)",
                                               where, version_found, checkpoint_format_version,
                                               h5.read_string("grit_version")));
        const std::string case_name = h5.read_string("case_name");
        if (case_name != spec_.name)
            throw core::InputError(fmt::format("{}: written by case '{}', not '{}'", where, case_name, spec_.name));
        for (const auto& [key, value] : state_keys(spec_)) {
            const bool has = h5.has_attribute("state_key " + key);
            // Before domain.periodic was recorded only grains could be periodic (dem.periodic): a grains-only
            // checkpoint without the key continues in its (periodic) case.
            if (!has && key == periodic_state_key && !has_sph_) continue;
            const std::string saved = has ? h5.read_string("state_key " + key) : std::string("(none)");
            if (saved != value)
                throw core::InputError(fmt::format("{}: {} was {} in the checkpointed run, now {}; the saved state "
                                                   "does not fit (start a fresh run instead)",
                                                   where, key, saved, value));
        }
        // The keys only some runs record: one the checkpoint has and this run has not does not fit either.
        const auto current = state_keys(spec_);
        for (const char* key : {periodic_state_key, symmetry_state_key}) {
            const bool here = std::any_of(current.begin(), current.end(), [&](const auto& k) { return k.first == key; });
            if (!here && h5.has_attribute(std::string("state_key ") + key))
                throw core::InputError(fmt::format("{}: {} was [{}] in the checkpointed run, now none; the saved state "
                                                   "does not fit (start a fresh run instead)",
                                                   where, key, h5.read_string(std::string("state_key ") + key)));
        }
        const auto run = h5.open_group("run");
        auto& clock = state_.clock;
        clock.time = run.read_double("time");
        clock.step = static_cast<long>(run.read_int("step"));
        clock.dt = run.read_double("dt");
        clock.dt_stable = run.read_double("dt_stable");
        state_.ledger.in = run.read_double("mass_in");
        state_.ledger.out = run.read_double("mass_out");
        state_.ledger.eroded = run.read_double("eroded_mass");
        snapshot_index_ = static_cast<long>(run.read_int("snapshot_index"));
        if (run.has_attribute("segments")) {
            earlier_.count = run.read_int("segments");
            earlier_.wall_time_s = run.read_double("wall_time_s");
            earlier_.particle_steps = run.read_double("particle_steps");
            earlier_.pair_steps = run.read_double("pair_steps");
        } else {
            earlier_ = {1, 0.0, 0.0, 0.0};  // written before grit kept the totals: the wall time before is unknown
        }
        restored_series_rows_ = static_cast<long>(run.read_int("series_rows"));
        restored_pvd_ = io::load_pvd_entries(run, "pvd");

        state_.particles.load(h5.open_group("particles"));
        const double skin = spec_.neighbor_skin * setup_.smoothing_length;
        const double support = std::visit([](const auto& k) { return k.support(); }, kernel_);
        state_.neighbors.load(h5.open_group("neighbors"), state_.particles, support + skin, setup_.periodic_box);
        if (state_.grains) state_.grains->load(h5.open_group("dem"));
        state_.impacts.load(h5.open_group("impacts"));
        const auto modules = h5.open_group("modules");
        for (auto& m : modules_) {
            if (!modules.has(m->name()) && m->continues_without_saved_state()) {
                restart_notes_.push_back(fmt::format("{} has no state of module '{}' (the grit that wrote it did "
                                                     "not run it in this case): it starts afresh", where, m->name()));
                continue;
            }
            m->load(modules.open_group(m->name()));
        }
    } catch (const io::Hdf5Error& e) {
        throw core::InputError(fmt::format("{}: unreadable ({})", where, e.what()));
    }
    primed_ = true;  // the rates of the saved state are in its fields: priming would overwrite them
    last_good_ = state_.particles;
    last_good_time_ = state_.clock.time;
    last_good_step_ = state_.clock.step;
    restarted_from_ = file;
}

template <int Dim>
void Simulation<Dim>::write_checkpoint() {
    if (!options_.write_files) return;
    const auto dir = options_.output_dir / "checkpoints";
    save_checkpoint(dir / fmt::format("checkpoint_{:010}.h5", state_.clock.step));
    auto all = checkpoints_in(dir);
    for (std::size_t k = 0; k + static_cast<std::size_t>(spec_.checkpoint_keep) < all.size(); ++k)
        std::filesystem::remove(all[k]);
}

template <int Dim>
RunSummary Simulation<Dim>::summarize(double wall_time, const std::string& status) const {
    RunSummary s;
    s.status = status;
    s.particles = state_.particles.size() - state_.particles.image_count();
    s.steps = state_.clock.step;
    s.end_time = state_.clock.time;
    // Over every segment of the run (a restart continues the totals of the checkpoint it starts from).
    const double wall = earlier_.wall_time_s + wall_time;
    s.wall_time_s = wall;
    s.segment_wall_time_s = wall_time;
    s.segments = earlier_.count + 1;
    s.particle_steps_per_second = wall > 0.0 ? (earlier_.particle_steps + particle_steps_) / wall : 0.0;
    s.pair_interactions_per_second = wall > 0.0 ? (earlier_.pair_steps + pair_steps_) / wall : 0.0;
    s.values = output_values();
    const auto d = analysis::compute_diagnostics(state_.particles);
    s.momentum.assign(d.momentum.c, d.momentum.c + Dim);
    s.stages = pipeline_.timers();
    s.restarted_from = restarted_from_.string();
    return s;
}

template <int Dim>
void Simulation<Dim>::write_summary(const RunSummary& s, const std::string& message) const {
    if (!options_.write_files) return;
    nlohmann::ordered_json j;
    j["case"] = spec_.name;
    j["title"] = spec_.title;
    j["status"] = s.status;
    if (!message.empty()) j["message"] = message;
    j["grit_version"] = version;
    j["git_revision"] = git_revision();
    j["dimension"] = Dim;
    j["case_file"] = spec_.source.string();
    j["case_digest"] = io::case_digest(spec_.source);
    j["overrides"] = spec_.overrides;
    j["particle_spacing"] = spec_.particle_spacing;
    for (const auto& m : modules_) m->describe(j);
    // The x >= 0 half of a symmetric set-up: masses, energies and counts are the half's.
    if (spec_.symmetry_plane) j["symmetry_plane"] = "x";
    j["threads"] = run_threads_ > 0 ? run_threads_ : parallel::max_threads();
    if (options_.adapt_threads) j["thread_changes"] = thread_changes_;
    // The threads the steps of this segment actually ran with, on average (fewer than `threads` where the
    // governor gave a core to another process).
    if (thread_step_count_ > 0) j["threads_used_mean"] = thread_steps_ / static_cast<double>(thread_step_count_);
    j["particles"] = s.particles;
    j["steps"] = s.steps;
    j["end_time"] = s.end_time;
    j["wall_time_s"] = s.wall_time_s;
    j["segments"] = s.segments;
    j["segment_wall_time_s"] = s.segment_wall_time_s;
    j["particle_steps_per_second"] = s.particle_steps_per_second;
    j["pair_interactions_per_second"] = s.pair_interactions_per_second;
    j["neighbor_list_builds"] = state_.neighbors.builds();
    j["neighbor_list_compactions"] = state_.neighbors.compactions();
    for (const auto& v : s.values)
        if (v.in_summary && v.group.empty()) j[v.name] = json_number(v);
    j["momentum"] = s.momentum;
    for (const auto& v : s.values)
        if (v.in_summary && !v.group.empty()) j[v.group][v.name] = json_number(v);
    for (const auto& t : s.stages) j["stage_seconds"][t.name] = t.seconds;
    // The unit of every key above that carries one, and of every series.csv column.
    nlohmann::ordered_json units = {{"end_time", "s"},         {"wall_time_s", "s"},
                                    {"segment_wall_time_s", "s"}, {"particle_spacing", "m"},
                                    {"particle_steps_per_second", "1/s"}, {"pair_interactions_per_second", "1/s"},
                                    {"momentum", Dim == 2 ? "kg m/s per m" : "kg m/s"}};
    for (const auto& v : s.values) units[v.name] = v.unit;
    j["units"] = units;
    j["restarted_from"] = s.restarted_from.empty() ? nlohmann::ordered_json(nullptr) : nlohmann::ordered_json(s.restarted_from);
    // In place whole or not at all (a sweep reads it to tell a finished run).
    const auto file = options_.output_dir / "summary.json";
    const auto temporary = io::temporary_name(file);
    {
        std::ofstream out(temporary);
        out << j.dump(2) << '\n';
        out.flush();
        if (!out) throw std::runtime_error(fmt::format("cannot write {} (disk full or not writable?)", file.string()));
    }
    io::commit_file(temporary, file);
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
