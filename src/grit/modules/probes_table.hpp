// The probes' case table, [[probe]]: read by the probes module's own reader (io/case_tables.hpp).
#pragma once

#include <vector>

#include "grit/analysis/probes.hpp"
#include "grit/io/case_tables.hpp"

namespace grit::modules {

/// What [[probe]] asks for: the probes, in case order (their series.csv columns).
struct ProbesSpec : io::ModuleSpec {
    static constexpr const char* key = "probe";
    std::vector<analysis::ProbeSpec> probes;
};

/// The [[probe]] table: each probe's name (a column name, unique), kind ("point": a quantity at a
/// position; "front": the furthest particle along an axis, optionally within a region) and phase.
io::CaseTable probes_table();

}  // namespace grit::modules
