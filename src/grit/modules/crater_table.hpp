// The crater analysis' case table, [crater]: read by the crater module's own reader (io/case_tables.hpp).
#pragma once

#include <optional>

#include "grit/analysis/crater.hpp"
#include "grit/io/case_tables.hpp"

namespace grit::modules {

/// What [crater] asks for: where the crater is measured.
struct CraterSpec : io::ModuleSpec {
    static constexpr const char* key = "crater";
    analysis::CraterRegion region;
};

/// The [crater] table: surface (the original surface height [m]), x_min and x_max (the profiled range
/// [m], more than a spacing apart), in 3D y_min and y_max (the map's range across the traverse). Refused
/// in a case without a [[solid]].
io::CaseTable crater_table();

/// The crater a case measures: its [crater], or without one the region its [jet]'s specimen implies
/// (io::JetSpec::crater); none otherwise. On a symmetry plane the profile is the whole crater's: mirrored
/// at x = 0, from -x_max to x_max.
std::optional<analysis::CraterRegion> crater_region(const io::CaseSpec& spec);

}  // namespace grit::modules
