// Helpers for tests that run the cases in cases/ in memory (no files written).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "grit/analysis/diagnostics.hpp"
#include "grit/io/case_reader.hpp"
#include "grit/sim/simulation.hpp"

namespace grit::testing {

/// Reads cases/<relative> with overrides (reduced sizes for CI).
inline io::CaseSpec load_case(const std::string& relative, const std::vector<std::string>& overrides = {}) {
    return io::read_case(std::filesystem::path(GRIT_SOURCE_DIR) / "cases" / relative, overrides);
}

inline sim::RunOptions in_memory() {
    sim::RunOptions o;
    o.write_files = false;
    o.quiet = true;
    return o;
}

}  // namespace grit::testing
