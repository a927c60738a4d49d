// run.log in a run's output folder: what was run (grit version and revision, the case file, the
// overrides, threads, particles) and how it ended, one time-stamped line each (spdlog). A restarted
// run appends to its folder's log.
#pragma once

#include <filesystem>
#include <memory>
#include <string>

#include "grit/core/types.hpp"
#include "grit/io/case_spec.hpp"

namespace spdlog {
class logger;
}

namespace grit::sim {

class RunLog {
public:
    /// Opens dir/run.log: a fresh file, or (append) the one a restarted run continues.
    RunLog(const std::filesystem::path& dir, bool append);
    ~RunLog();
    RunLog(const RunLog&) = delete;
    RunLog& operator=(const RunLog&) = delete;

    /// The header of a run: version and revision, threads, the case, every --set, a restart's origin,
    /// the particle count and times.
    void start(const io::CaseSpec& spec, Index particles, Index grains, const std::string& restarted_from,
               long step, double time);
    void info(const std::string& line);
    void warn(const std::string& line);
    void error(const std::string& line);

private:
    std::shared_ptr<spdlog::logger> logger_;
};

}  // namespace grit::sim
