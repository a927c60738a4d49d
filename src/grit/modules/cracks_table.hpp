// The crack analysis' case table, [cracks]: read by the cracks module's own reader (io/case_tables.hpp).
#pragma once

#include <optional>

#include "grit/analysis/cracks.hpp"
#include "grit/io/case_tables.hpp"

namespace grit::modules {

/// What [cracks] asks for: which damage counts and which damaged particles form one crack.
struct CracksSpec : io::ModuleSpec {
    static constexpr const char* key = "cracks";
    analysis::CrackOptions options;
};

/// The [cracks] table: damage_threshold (0.5), link_distance (1.5 particle spacings [m]), min_particles
/// (3). Refused in a case without a [[solid]].
io::CaseTable cracks_table();

/// The crack analysis a case runs: its [cracks]; without one, the defaults when a solid is brittle (a
/// JH-2 material: the first paper's radial and lateral cracks); none otherwise.
std::optional<analysis::CrackOptions> crack_options(const io::CaseSpec& spec);

}  // namespace grit::modules
