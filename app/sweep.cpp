// `grit sweep`.
#include "sweep.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstring>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <thread>

#include "grit/core/error.hpp"
#include "grit/io/case_reader.hpp"
#include "grit/io/run_folder.hpp"

extern char** environ;

namespace grit::app {

namespace fs = std::filesystem;

SweepParameter parse_sweep_parameter(const std::string& text) {
    const auto eq = text.find('=');
    if (eq == std::string::npos || eq == 0 || eq + 1 == text.size())
        throw core::InputError(fmt::format("--param {}: expected key=value1,value2,... (e.g. jet.velocity=383,443,495)", text));
    SweepParameter p{text.substr(0, eq), {}};
    std::string rest = text.substr(eq + 1);
    std::size_t start = 0;
    while (start <= rest.size()) {
        const auto comma = rest.find(',', start);
        const std::string v = rest.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
        if (v.empty()) throw core::InputError(fmt::format("--param {}: an empty value in the list", text));
        if (v.find_first_of("/ \t") != std::string::npos)
            throw core::InputError(fmt::format("--param {}: the value '{}' cannot name a run folder (no '/' or spaces)", text, v));
        p.values.push_back(v);
        if (comma == std::string::npos) break;
        start = comma + 1;
    }
    return p;
}

std::vector<std::vector<std::string>> sweep_points(const std::vector<SweepParameter>& parameters) {
    std::vector<std::vector<std::string>> points{{}};
    for (const auto& p : parameters) {
        std::vector<std::vector<std::string>> next;
        for (const auto& point : points)
            for (const auto& v : p.values) {
                auto q = point;
                q.push_back(v);
                next.push_back(std::move(q));
            }
        points = std::move(next);
    }
    return points;
}

std::string sweep_run_name(const std::vector<SweepParameter>& parameters, const std::vector<std::string>& point) {
    std::string name;
    for (std::size_t k = 0; k < parameters.size(); ++k)
        name += (k ? "_" : "") + parameters[k].key + "=" + point[k];
    return name;
}

namespace {

/// The summary.json of a finished run, or null.
nlohmann::json finished_summary(const fs::path& dir) {
    std::ifstream in(dir / "summary.json");
    if (!in) return nullptr;
    try {
        nlohmann::json j = nlohmann::json::parse(in);
        if (j.value("status", "") == "completed") return j;
    } catch (const nlohmann::json::exception&) {
    }
    return nullptr;
}

/// The --set of one point's run, in the order the run applies them: the sweep's, then the point's.
std::vector<std::string> run_overrides(const SweepOptions& o, const std::vector<std::string>& point) {
    std::vector<std::string> sets = o.sets;
    for (std::size_t k = 0; k < point.size(); ++k) sets.push_back(o.parameters[k].key + "=" + point[k]);
    return sets;
}

/// Starts `grit run` for one point (replacing what an unfinished or outdated run left in its folder);
/// returns its process id.
pid_t start_run(const SweepOptions& o, const std::vector<std::string>& point, const fs::path& dir, int threads) {
    std::vector<std::string> args = {o.grit.string(), "run", o.case_file.string(), "--out", dir.string(), "--quiet",
                                     "--overwrite", "--threads", std::to_string(threads)};
    for (const auto& s : run_overrides(o, point)) args.insert(args.end(), {"--set", s});
    std::vector<char*> argv;
    for (auto& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    // What the run prints (an error, a blow-up) goes to console.log in its folder, beside its run.log.
    fs::create_directories(dir);
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    const std::string log = (dir / "console.log").string();
    posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    posix_spawn_file_actions_adddup2(&actions, STDOUT_FILENO, STDERR_FILENO);
    pid_t pid = 0;
    const int rc = posix_spawn(&pid, argv[0], &actions, nullptr, argv.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    if (rc != 0) throw std::runtime_error(fmt::format("cannot start {}: {}", argv[0], std::strerror(rc)));
    return pid;
}

std::string csv_number(const nlohmann::json& summary, const char* key) {
    if (summary.is_null() || !summary.contains(key) || !summary[key].is_number()) return "";
    return fmt::format("{:.10g}", summary[key].get<double>());
}

/// "yes" when the run's crater depth is at least one particle spacing, "below one spacing" when it is
/// shallower (what the run cannot resolve), empty without a crater depth.
std::string depth_resolved(const nlohmann::json& summary) {
    if (summary.is_null() || !summary.contains("crater_depth") || !summary["crater_depth"].is_number() ||
        !summary.contains("particle_spacing") || !summary["particle_spacing"].is_number())
        return "";
    return summary["crater_depth"].get<double>() >= summary["particle_spacing"].get<double>() ? "yes"
                                                                                              : "below one spacing";
}

}  // namespace

int run_sweep(const SweepOptions& o) {
    // Every point is read and checked before anything runs: a bad value stops the sweep at once.
    const auto points = sweep_points(o.parameters);
    for (const auto& point : points) {
        auto overrides = o.sets;
        for (std::size_t k = 0; k < point.size(); ++k) overrides.push_back(o.parameters[k].key + "=" + point[k]);
        try {
            (void)io::read_case(o.case_file, overrides);
        } catch (const core::InputError& e) {
            throw core::InputError(fmt::format("sweep point {}: {}", sweep_run_name(o.parameters, point), e.what()));
        }
    }
    fs::create_directories(o.out);
    const int cores = o.threads > 0 ? o.threads : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
    const int jobs = std::max(1, std::min(o.jobs, static_cast<int>(points.size())));
    const int per_run = std::max(1, cores / jobs);

    // A run done before is kept only if it ran this case text with these --set; otherwise it runs again.
    const std::string digest = io::case_digest(o.case_file);
    std::vector<std::size_t> pending;
    for (std::size_t i = 0; i < points.size(); ++i) {
        const auto name = sweep_run_name(o.parameters, points[i]);
        const auto done = finished_summary(o.out / name);
        if (done.is_null()) {
            pending.push_back(i);
            continue;
        }
        const auto overrides = run_overrides(o, points[i]);
        const bool same_case = done.value("case_digest", std::string()) == digest;
        const bool same_sets = done.contains("overrides") && done["overrides"] == nlohmann::json(overrides);
        if (same_case && same_sets) {
            if (!o.quiet) fmt::print("{}: done before, kept\n", name);
            continue;
        }
        pending.push_back(i);
        if (!o.quiet)
            fmt::print("{}: done before with {}, runs again\n", name,
                       !same_case ? "another case text" : fmt::format("other --set ({})", done.contains("overrides")
                                                                                ? done["overrides"].dump()
                                                                                : std::string("not recorded")));
    }
    std::map<pid_t, std::size_t> running;
    std::size_t next = 0;
    const auto t0 = std::chrono::steady_clock::now();
    while (next < pending.size() || !running.empty()) {
        while (next < pending.size() && static_cast<int>(running.size()) < jobs) {
            const std::size_t i = pending[next++];
            const auto name = sweep_run_name(o.parameters, points[i]);
            if (!o.quiet) fmt::print("{}: running ({} of {})\n", name, next, pending.size());
            std::fflush(stdout);
            running[start_run(o, points[i], o.out / name, per_run)] = i;
        }
        int status = 0;
        const pid_t pid = waitpid(-1, &status, 0);
        if (pid < 0) break;
        const auto it = running.find(pid);
        if (it == running.end()) continue;
        const auto name = sweep_run_name(o.parameters, points[it->second]);
        running.erase(it);
        const int code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
        if (!o.quiet)
            fmt::print("{}: {} ({:.0f} s since the sweep started)\n", name,
                       code == 0 ? "completed" : fmt::format("stopped with exit code {} (see its console.log)", code),
                       std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
        std::fflush(stdout);
        if (code == 130 || code == 143) {  // interrupted: the others got the signal too
            for (const auto& [p, _] : running) waitpid(p, &status, 0);
            running.clear();
            next = pending.size();
        }
    }

    // sweep.csv: the swept keys, then the results of each run (empty where a run has none).
    const char* results[] = {"crater_depth", "crater_width", "eroded_mass", "damaged_area", "crack_count",
                             "wall_time_s", "abrasive_mass_flow_rate", "grains_injected", "crater_rim_width",
                             "first_removal_time", "crater_area", "crater_shape_factor", "particle_spacing"};
    std::ofstream csv(o.out / "sweep.csv");
    for (const auto& p : o.parameters) csv << p.key << ',';
    for (const char* r : results) csv << r << ',';
    // A crater shallower than one particle spacing is below what the run resolves: say so beside it.
    csv << "crater_depth_resolved,status,folder\n";
    int incomplete = 0;
    for (const auto& point : points) {
        const auto name = sweep_run_name(o.parameters, point);
        const auto summary = finished_summary(o.out / name);
        for (const auto& v : point) csv << v << ',';
        for (const char* r : results) csv << csv_number(summary, r) << ',';
        csv << depth_resolved(summary) << ',';
        if (summary.is_null()) ++incomplete;
        csv << (summary.is_null() ? "incomplete" : "completed") << ',' << name << '\n';
    }
    if (!o.quiet)
        fmt::print("sweep: {} runs, {} completed -> {}\n", points.size(), points.size() - incomplete,
                   (o.out / "sweep.csv").string());
    return incomplete == 0 ? 0 : 3;
}

}  // namespace grit::app
