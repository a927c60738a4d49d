// run.log.
#include "grit/sim/run_log.hpp"

#include <spdlog/sinks/basic_file_sink.h>
#include <spdlog/spdlog.h>

namespace grit::sim {

RunLog::RunLog(const std::filesystem::path& dir, bool append) {
    auto sink = std::make_shared<spdlog::sinks::basic_file_sink_mt>((dir / "run.log").string(), !append);
    logger_ = std::make_shared<spdlog::logger>("run", std::move(sink));
    logger_->set_pattern("%Y-%m-%d %H:%M:%S [%l] %v");
    logger_->flush_on(spdlog::level::info);
}

RunLog::~RunLog() = default;

void RunLog::info(const std::string& line) { logger_->info(line); }
void RunLog::warn(const std::string& line) { logger_->warn(line); }
void RunLog::error(const std::string& line) { logger_->error(line); }

}  // namespace grit::sim
