// The grit command-line front end: run, sweep, plot, crater, check, materials.
#include <CLI/CLI.hpp>
#include <spawn.h>
#include <sys/wait.h>
#include <fmt/format.h>
#include <spdlog/sinks/stdout_color_sinks.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "grit/core/error.hpp"
#include "grit/dem/grain_material.hpp"
#include "grit/io/case_reader.hpp"
#include "grit/io/run_folder.hpp"
#include "grit/material/library.hpp"
#include "grit/parallel/parallel.hpp"
#include "grit/sim/run_estimate.hpp"
#include "grit/sim/simulation.hpp"
#include "grit/sim/version.hpp"
#include "grit/wear/wear_models.hpp"
#include "crater_measures.hpp"
#include "sweep.hpp"

extern char** environ;

namespace {

constexpr int exit_input_error = 2;
constexpr int exit_blow_up = 3;

int run_command(const std::string& case_file, const std::vector<std::string>& sets, const std::string& out,
                double end_time, bool has_end_time, int threads, bool quiet, const std::string& restart,
                long dump_from, bool fixed_threads, bool overwrite, double max_wall_time, double progress_every) {
    // A restart applies the checkpointed run's --set first (a sweep's parameter, a changed grain size), so
    // that it continues the same physics; its own --set come after and win.
    std::vector<std::string> overrides;
    if (!restart.empty()) {
        overrides = grit::sim::checkpoint_overrides(grit::sim::resolve_checkpoint(restart),
                                                    grit::io::read_case(case_file, sets).name);
        if (!quiet && !overrides.empty())
            fmt::print(stderr, "restart: the checkpointed run's --set apply first: {}\n", fmt::join(overrides, " "));
    }
    overrides.insert(overrides.end(), sets.begin(), sets.end());
    // Every --set is validated as given, also where --end-time then replaces it.
    if (has_end_time) (void)grit::io::read_case(case_file, overrides);
    if (has_end_time) overrides.push_back(fmt::format("time.end={:.17g}", end_time));
    const grit::io::CaseSpec spec = grit::io::read_case(case_file, overrides);
    if (threads > 0) grit::parallel::set_threads(threads);
    grit::sim::RunOptions options;
    options.output_dir = out.empty() ? std::filesystem::path("output") / spec.name : std::filesystem::path(out);
    options.quiet = quiet;
    options.dump_from_step = dump_from;
    options.adapt_threads = !fixed_threads;
    options.max_wall_time_s = max_wall_time;
    options.progress_every_s = progress_every;
    if (restart.empty()) {
        // A fresh run never replaces an earlier one without being told to.
        const std::string earlier = grit::io::earlier_run(options.output_dir);
        if (!earlier.empty() && !overwrite)
            throw grit::core::InputError(fmt::format(
                "--out {}: the folder holds {}; continue it with --restart {} (and --set time.end=... to extend "
                "it), or replace it with --overwrite",
                options.output_dir.string(), earlier, options.output_dir.string()));
        grit::io::check_writable_folder(options.output_dir, "--out");
    } else {
        if (overwrite)
            throw grit::core::InputError("--overwrite: a restart continues its run's files; leave --overwrite out");
        // A restart continues the files of the run the checkpoint belongs to (its folder holds checkpoints/).
        options.restart = restart;
        const auto checkpoint = grit::sim::resolve_checkpoint(restart);
        const auto parent = checkpoint.parent_path();
        const auto folder = parent.filename() == "checkpoints" ? parent.parent_path() : parent;
        if (!out.empty() && !std::filesystem::equivalent(std::filesystem::path(out), folder))
            throw grit::core::InputError(fmt::format("--out {}: a restart continues the run in {}; leave --out out",
                                                     out, folder.string()));
        options.output_dir = folder;
    }
    grit::sim::refuse_beyond_memory(spec);
    const auto summary = grit::sim::run_case(spec, options);
    if (!summary.message.empty()) {
        fmt::print(stderr, "grit: {}\n", summary.message);
        return 0;
    }
    if (!quiet)
        fmt::print("{}: {} steps to t = {:.6g} s, {} particles, {:.3g} s wall, {:.3g} particle-steps/s -> {}\n",
                   spec.name, summary.steps, summary.end_time, summary.particles, summary.wall_time_s,
                   summary.particle_steps_per_second, options.output_dir.string());
    if (!quiet) {
        // The erosion results an AWJ user reads first, when the case computes them.
        std::vector<std::string> results;
        auto add = [&](const char* name, const char* label, double scale, const char* unit) {
            for (const auto& v : summary.values)
                if (v.name == name && v.in_summary && std::isfinite(v.value))
                    results.push_back(fmt::format("{} = {:.4g}{}{}", label, v.value * scale, *unit ? " " : "", unit));
        };
        add("crater_depth", "crater depth C_d", 1e3, "mm");
        add("crater_width", "crater width C_w", 1e3, "mm");
        add("crater_rim_width", "rim to rim", 1e3, "mm");
        for (const auto& v : summary.values)  // V (0.5) or U (0.785 and above); nothing while there is no crater
            if (v.name == "crater_shape_factor" && v.in_summary && v.value > 0.0)
                results.push_back(fmt::format("shape area / (C_d C_w) = {:.2f}", v.value));
        add("crater_length", "length along the traverse", 1e3, "mm");
        add("eroded_mass", "eroded mass", spec.dimension == 2 ? 1e3 : 1e6, spec.dimension == 2 ? "g/m" : "mg");
        add("first_removal_time", "first removal", 1e3, "ms");
        add("grains_injected", "grains fed", 1.0, "");
        add("impacts", "impacts", 1.0, "");
        if (!results.empty()) fmt::print("  {}\n", fmt::join(results, ", "));
        if (spec.symmetry_plane)
            fmt::print("  ({} runs the x >= 0 half: masses, energies and counts are the half's, double them for the "
                       "whole; C_d and C_w are the whole crater's)\n",
                       spec.symmetry_key);
    }
    return 0;
}

/// `grit plot FOLDER`: scripts/grit_plot.py with Debian's python3 (numpy, matplotlib).
int plot_command(const std::string& folder) {
    if (!std::filesystem::is_directory(folder))
        throw grit::core::InputError(fmt::format("plot {}: no such folder", folder));
    // An installed grit finds its scripts beside it (PREFIX/bin/grit, PREFIX/share/grit/scripts), a built
    // one in its source tree.
    std::error_code ec;
    const auto exe = std::filesystem::read_symlink("/proc/self/exe", ec);
    const std::filesystem::path installed = exe.parent_path().parent_path() / GRIT_INSTALLED_SCRIPTS_DIR / "grit_plot.py";
    const std::filesystem::path script =
        !ec && std::filesystem::exists(installed) ? installed : std::filesystem::path(GRIT_SCRIPTS_DIR) / "grit_plot.py";
    if (!std::filesystem::exists(script))
        throw grit::core::InputError(fmt::format("plot: {} is missing (reinstall grit, or run it from its build tree)",
                                                 script.string()));
    const std::string python = std::filesystem::exists("/usr/bin/python3") ? "/usr/bin/python3" : "python3";
    std::vector<std::string> args = {python, script.string(), folder};
    std::vector<char*> argv;
    for (auto& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    pid_t pid = 0;
    if (posix_spawnp(&pid, argv[0], nullptr, nullptr, argv.data(), environ) != 0)
        throw std::runtime_error("plot: cannot start " + python);
    int status = 0;
    waitpid(pid, &status, 0);
    return WIFEXITED(status) ? WEXITSTATUS(status) : 1;
}

/// The stages of one step as `grit check --pipeline` prints them: hook point, stage, module, and "prime"
/// for the stages that also run once before the first step.
void print_pipeline(const std::vector<grit::sim::StageInfo>& stages) {
    fmt::print("pipeline ({} stages, in the order one step runs them):\n", stages.size());
    auto line = [](std::string text) {
        text.erase(text.find_last_not_of(' ') + 1);
        fmt::print("{}\n", text);
    };
    line(fmt::format("  {:<15} {:<28} {:<16} {}", "hook", "stage", "module", "prime"));
    for (const auto& s : stages)
        line(fmt::format("  {:<15} {:<28} {:<16} {}", grit::sim::hook_name(s.hook), s.name, s.module, s.prime ? "yes" : ""));
}

/// --threads N: a positive whole number (checked here: CLI11's range check prints a 300-digit bound).
int parse_threads(const std::string& text) {
    int n = 0;
    const char* end = text.data() + text.size();
    const auto [stop, ec] = std::from_chars(text.data(), end, n);
    if (ec != std::errc{} || stop != end || n < 1)
        throw grit::core::InputError(fmt::format("--threads {}: must be a positive whole number", text));
    return n;
}

/// --max-wall-time: seconds ("3600", "5400.5") or H:MM:SS / MM:SS ("1:30:00"), more than zero.
double parse_wall_time(const std::string& text) {
    double seconds = 0.0;
    std::size_t start = 0;
    int fields = 0;
    bool ok = !text.empty();
    while (ok && start <= text.size()) {
        const auto colon = text.find(':', start);
        const std::string part = text.substr(start, colon == std::string::npos ? std::string::npos : colon - start);
        double v = 0.0;
        const auto [stop, ec] = std::from_chars(part.data(), part.data() + part.size(), v);
        ok = !part.empty() && ec == std::errc{} && stop == part.data() + part.size() && v >= 0.0 && std::isfinite(v);
        seconds = seconds * 60.0 + v;
        ++fields;
        if (colon == std::string::npos) break;
        start = colon + 1;
    }
    if (!ok || fields > 3 || !(seconds > 0.0))
        throw grit::core::InputError(fmt::format(
            "--max-wall-time {}: must be a wall time above zero, in seconds or as H:MM:SS", text));
    return seconds;
}

/// One line for a command-line error CLI11 reports (its own message, less the "Run with --help" line).
std::string usage_error(const CLI::App& app, const CLI::ParseError& e) {
    if (dynamic_cast<const CLI::RequiredError*>(&e) && app.get_subcommands().empty()) {
        const auto extra = app.remaining();
        if (extra.empty()) return "a command is required: run, sweep, plot, check or materials (grit --help)";
        if (extra.front().starts_with('-')) return fmt::format("unknown option '{}' (grit --help)", extra.front());
        return fmt::format("unknown command '{}': the commands are run, sweep, plot, check and materials (grit --help)",
                           extra.front());
    }
    std::string message = e.what();
    std::replace(message.begin(), message.end(), '\n', ' ');
    if (message.size() > 1 && std::isupper(static_cast<unsigned char>(message[0])) &&
        std::islower(static_cast<unsigned char>(message[1])))
        message[0] = static_cast<char>(std::tolower(static_cast<unsigned char>(message[0])));
    const auto subcommands = app.get_subcommands();
    const std::string help = subcommands.empty() ? "grit --help" : "grit " + subcommands.front()->get_name() + " --help";
    return fmt::format("{} ({})", message, help);
}

}  // namespace

int main(int argc, char** argv) {
    // Warnings of the library (spdlog's default logger) go to stderr, with grit's other messages; stdout
    // carries only what a command is asked for.
    spdlog::set_default_logger(spdlog::stderr_color_mt("grit"));
    CLI::App app{"grit: SPH-DEM simulation of erosion by fluids carrying abrasive grains"};
    app.require_subcommand(1);
    app.set_version_flag("--version", std::string("grit " GRIT_VERSION " (git ") + grit::sim::git_revision() + ")");

    std::string case_file, out;
    std::vector<std::string> sets;
    double end_time = 0.0;
    std::string threads_text;
    bool quiet = false;
    std::string restart;
    long dump_from = 0;
    bool fixed_threads = false;
    bool overwrite = false;
    std::string max_wall_text;
    double progress_every = 30.0;

    auto* run = app.add_subcommand("run", "run a case");
    run->add_option("case", case_file, "case file (TOML)")->required();
    run->add_option("--out", out, "output folder (default: output/<case name>)");
    run->add_option("--set", sets, "override a case value: key.path=value (repeatable)");
    auto* end_opt = run->add_option("--end-time", end_time, "simulated end time [s] (0 writes the initial state)");
    auto* threads_opt = run->add_option("--threads", threads_text, "number of threads")->type_name("N");
    run->add_flag("--fixed-threads", fixed_threads,
                  "keep the thread count even while another process holds a core (by default the run uses fewer "
                  "threads then, and takes them back when the core is free)");
    run->add_flag("--quiet", quiet, "no progress line or final message");
    run->add_flag("--overwrite", overwrite,
                  "replace the earlier run in the output folder (its snapshots, series, checkpoints and plots); "
                  "without it a fresh run into a folder that holds one is refused");
    run->add_option("--restart", restart,
                    "continue from a checkpoint: a run folder (its latest checkpoints/*.h5) or a checkpoint file; "
                    "the run's own --set apply again, before these");
    auto* max_wall_opt = run->add_option("--max-wall-time", max_wall_text,
                                         "write a checkpoint and stop after this much wall time (seconds, or "
                                         "H:MM:SS as batch systems write it); continue with --restart")
                             ->type_name("TIME");
    run->add_option("--progress-every", progress_every,
                    "a plain progress line (step, t, rate, ETA) every this many seconds of wall time in run.log, "
                    "and on standard error when it is not a terminal (make, tee, a batch job); 0: none")
        ->check(CLI::NonNegativeNumber)
        ->type_name("SECONDS");
    auto* dump_opt = run->add_option("--dump-from", dump_from,
                                     "write the SPH particles after every step from this step on "
                                     "(dump/<case>_step_<N>.vtu): to see how a blow-up starts, restart from a "
                                     "checkpoint before it")
                         ->type_name("STEP");

    auto* sweep = app.add_subcommand("sweep", "run a case over the product of parameter lists (sweep.csv)");
    std::vector<std::string> params;
    int jobs = 1;
    sweep->add_option("case", case_file, "case file (TOML)")->required();
    sweep->add_option("--param", params, "a swept key and its values: key=v1,v2,... (repeatable: their product)")
        ->required();
    sweep->add_option("--out", out, "sweep folder (default: output/<case name>_sweep)");
    sweep->add_option("--set", sets, "override a case value in every run: key.path=value (repeatable)");
    sweep->add_option("--jobs", jobs, "runs at once (the threads are shared among them)")->check(CLI::PositiveNumber);
    auto* sweep_threads_opt = sweep->add_option("--threads", threads_text, "threads in all")->type_name("N");
    sweep->add_flag("--quiet", quiet, "no progress lines");

    auto* plot = app.add_subcommand("plot", "plots of a run or sweep folder into FOLDER/plots/ (matplotlib)");
    std::string plot_folder;
    plot->add_option("folder", plot_folder, "a run folder (series.csv) or a sweep folder (sweep.csv)")->required();

    auto* crater = app.add_subcommand("crater", "measure a run's crater again at every output (FOLDER/crater_measures.csv)");
    std::string crater_folder;
    crater->add_option("folder", crater_folder, "a run folder (summary.json, crater_history.csv), or a sweep folder: each of its runs")->required();

    auto* check = app.add_subcommand("check", "validate a case file without running it");
    check->add_option("case", case_file, "case file (TOML)")->required();
    check->add_option("--set", sets, "override a case value: key.path=value (repeatable)");
    bool show_pipeline = false;
    check->add_flag("--pipeline", show_pipeline,
                    "also print the stages one step runs, in order, with their hook point and module");

    app.add_subcommand("materials", "list the built-in material library");

    try {
        app.parse(argc, argv);
    } catch (const CLI::Success& e) {
        return app.exit(e);  // --help, --version: printed as CLI11 does, exit 0
    } catch (const CLI::ParseError& e) {
        fmt::print(stderr, "grit: error: {}\n", usage_error(app, e));
        return exit_input_error;
    }

    try {
        if (run->parsed()) {
            if (end_opt->count() && end_time < 0.0)
                throw grit::core::InputError(fmt::format("--end-time {}: must not be negative [s]", end_time));
            if (dump_opt->count() && dump_from < 1)
                throw grit::core::InputError(fmt::format("--dump-from {}: must be a step number, 1 or more", dump_from));
            const int threads = threads_opt->count() ? parse_threads(threads_text) : 0;
            const double max_wall = max_wall_opt->count() ? parse_wall_time(max_wall_text) : 0.0;
            return run_command(case_file, sets, out, end_time, end_opt->count() > 0, threads, quiet, restart,
                               dump_from, fixed_threads, overwrite, max_wall, progress_every);
        }
        if (sweep->parsed()) {
            grit::app::SweepOptions o;
            o.grit = std::filesystem::read_symlink("/proc/self/exe");
            o.case_file = case_file;
            o.sets = sets;
            for (const auto& p : params) o.parameters.push_back(grit::app::parse_sweep_parameter(p));
            const auto spec = grit::io::read_case(case_file, sets);
            o.out = out.empty() ? std::filesystem::path("output") / (spec.name + "_sweep") : std::filesystem::path(out);
            o.jobs = jobs;
            o.threads = sweep_threads_opt->count() ? parse_threads(threads_text) : 0;
            o.quiet = quiet;
            return grit::app::run_sweep(o);
        }
        if (plot->parsed()) return plot_command(plot_folder);
        if (crater->parsed()) {
            // A sweep folder (sweep.csv, no summary.json of its own): each of its runs with a crater.
            const std::filesystem::path folder(crater_folder);
            std::vector<std::filesystem::path> runs;
            if (std::filesystem::exists(folder / "sweep.csv") && !std::filesystem::exists(folder / "summary.json")) {
                for (const auto& entry : std::filesystem::directory_iterator(folder))
                    if (std::filesystem::exists(entry.path() / "crater_history.csv")) runs.push_back(entry.path());
                std::sort(runs.begin(), runs.end());
                if (runs.empty())
                    throw grit::core::InputError(fmt::format("crater {}: a sweep folder without a run that has crater_history.csv", crater_folder));
            } else {
                runs.push_back(folder);
            }
            for (const auto& run_folder : runs) {
                const int outputs = grit::app::measure_crater_history(run_folder);
                fmt::print("crater: {} outputs measured -> {}\n", outputs, (run_folder / "crater_measures.csv").string());
            }
            return 0;
        }
        if (check->parsed()) {
            const auto spec = grit::io::read_case(case_file, sets);
            // Building the particles catches geometry errors too; nothing is written.
            grit::sim::RunOptions options;
            options.write_files = false;
            // Building the particles and the first step's rates also gives the run's cost.
            grit::sim::RunEstimate plan;
            std::vector<grit::sim::StageInfo> stages;
            auto examine = [&](auto&& simulation) {
                plan = simulation.estimate();
                stages = simulation.pipeline().stages();
            };
            if (spec.dimension == 2)
                examine(grit::sim::Simulation<2>(spec, options));
            else
                examine(grit::sim::Simulation<3>(spec, options));
            fmt::print("{}: ok ({}D, {} material(s), {} grain material(s))\n", case_file, spec.dimension,
                       spec.materials.size(), spec.grain_materials.size());
            fmt::print("estimate: {}\n", plan.text());
            if (show_pipeline) print_pipeline(stages);
            return 0;
        }
        for (const auto& m : grit::material::library()) fmt::print("{}\n", grit::material::describe(m));
        for (const auto& g : grit::dem::grain_material_library())
            fmt::print("{}: grain (DEM): rho = {} kg/m^3, E = {:g} Pa, nu = {}, mu = {}, e = {}, d = {:g} m\n", g.name,
                       g.density, g.youngs_modulus, g.poisson_ratio, g.friction, g.restitution, g.diameter);
        for (const auto& w : grit::wear::wear_material_library())
            fmt::print("{}: wear (mesh walls): rho = {} kg/m^3, E = {:g} Pa, nu = {}, flow_stress = {:g} Pa, "
                       "elastic_limit = {:g} Pa, vickers_hardness = {} GPa, finnie_k = {}, finnie_psi = {}, "
                       "bitter_exponent = {}, bitter_roundness = {}, bitter_deformation_factor = {:.3g} J/m^3 "
                       "(derived from Oka at {:g} m/s, {:g} mm quartz), "
                       "oka_K = {} mm^3/kg, oka_k1 = {}, oka_k3 = {}, liggghts_k = {} s^2/m^2\n",
                       w.name, w.density, w.youngs_modulus, w.poisson_ratio, w.flow_stress, w.elastic_limit,
                       w.vickers_hardness, w.finnie_k, w.finnie_psi, w.bitter_exponent, w.bitter_roundness,
                       w.bitter_deformation_factor, w.bitter_calibration_speed, 1e3 * w.bitter_calibration_diameter,
                       w.oka_K, w.oka_k1, w.oka_k3, w.liggghts_k);
        return 0;
    } catch (const grit::core::InputError& e) {
        fmt::print(stderr, "grit: error: {}\n", e.what());
        return exit_input_error;
    } catch (const grit::sim::Interrupted& e) {
        fmt::print(stderr, "grit: {}\n", e.what());
        // 130 for Ctrl-C (SIGINT), 143 for SIGTERM, 138 for SIGUSR1; 0 at --max-wall-time, a planned stop.
        return e.signal() == 0 ? 0 : 128 + e.signal();
    } catch (const grit::core::BlowUpError& e) {
        fmt::print(stderr, "grit: {}\n", e.what());
        return exit_blow_up;
    } catch (const std::exception& e) {
        fmt::print(stderr, "grit: error: {}\n", e.what());
        return 1;
    }
}
