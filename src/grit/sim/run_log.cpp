// run.log.
#include "grit/sim/run_log.hpp"

#include <fmt/format.h>
#include <spdlog/sinks/basic_file_sink.h>
#include <spdlog/spdlog.h>

#include <cstdlib>
#include <string>

#include "grit/parallel/parallel.hpp"
#include "grit/sim/version.hpp"

namespace grit::sim {

namespace {

/// How the OpenMP threads wait at a loop's end, as the environment sets it.
std::string thread_waits() {
    if (const char* s = std::getenv("GOMP_SPINCOUNT")) return std::string("GOMP_SPINCOUNT=") + s;
    if (const char* p = std::getenv("OMP_WAIT_POLICY")) return std::string("OMP_WAIT_POLICY=") + p;
    return "libgomp's default waits";
}

}  // namespace

RunLog::RunLog(const std::filesystem::path& dir, bool append) {
    auto sink = std::make_shared<spdlog::sinks::basic_file_sink_mt>((dir / "run.log").string(), !append);
    logger_ = std::make_shared<spdlog::logger>("run", std::move(sink));
    logger_->set_pattern("%Y-%m-%d %H:%M:%S [%l] %v");
    logger_->flush_on(spdlog::level::info);
}

RunLog::~RunLog() = default;

void RunLog::start(const io::CaseSpec& spec, Index particles, Index grains, const std::string& restarted_from,
                   long step, double time) {
    info(fmt::format("grit {} (git {}), {} thread(s), {}", version, git_revision(), parallel::max_threads(),
                     thread_waits()));
    info(fmt::format("case {} ('{}'), {}D", spec.source.string(), spec.title, spec.dimension));
    for (const auto& o : spec.overrides) info("--set " + o);
    if (!restarted_from.empty()) info(fmt::format("restarted from {} at step {} (t = {:.9g} s)", restarted_from, step, time));
    info(fmt::format("{} particles, {} grains, dx = {} m, end time {} s, output every {} s", particles, grains,
                     spec.particle_spacing, spec.end_time, spec.output_interval));
}

void RunLog::info(const std::string& line) { logger_->info(line); }
void RunLog::warn(const std::string& line) { logger_->warn(line); }
void RunLog::error(const std::string& line) { logger_->error(line); }

}  // namespace grit::sim
