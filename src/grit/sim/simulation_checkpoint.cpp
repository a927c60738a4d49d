// A run's checkpoints: writing the run state whole (a temporary, fsync, rename), reading it back with
// every key it depends on checked, and finding the checkpoint a restart continues.
#include <fmt/format.h>

#include <algorithm>
#include <system_error>

#include "grit/core/error.hpp"
#include "grit/io/durable_file.hpp"
#include "grit/io/hdf5_file.hpp"
#include "grit/sim/checkpoint_files.hpp"
#include "grit/sim/output_times.hpp"
#include "grit/sim/simulation.hpp"
#include "grit/sim/version.hpp"

namespace grit::sim {

namespace {

// 2: grain-grain contact histories are held by the grain of lower index (was: lower id), one entry per
// pair of the cut lists (dem::ContactHistory). 3: grains carry `collisions` and `grain_contact`, the grains
// module the collisions of the grains that left.
constexpr std::int64_t checkpoint_format_version = 4;  // 4: 64-bit ids by origin, the inlets' layer counts

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

}  // namespace

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
        h5.write("case_text", spec_.text);
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
            throw core::InputError(fmt::format(
                "{}: format version {}, written by grit {}; this grit ({}) reads format version {} only. Restart "
                "it with the grit that wrote it, or run the case again from its start",
                where, version_found, h5.read_string("grit_version"), version, checkpoint_format_version));
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

template void Simulation<2>::save_checkpoint(const std::filesystem::path&);
template void Simulation<3>::save_checkpoint(const std::filesystem::path&);
template void Simulation<2>::write_checkpoint_file(const std::filesystem::path&) const;
template void Simulation<3>::write_checkpoint_file(const std::filesystem::path&) const;
template void Simulation<2>::load_checkpoint(const std::filesystem::path&);
template void Simulation<3>::load_checkpoint(const std::filesystem::path&);
template void Simulation<2>::write_checkpoint();
template void Simulation<3>::write_checkpoint();

}  // namespace grit::sim
