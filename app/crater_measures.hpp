// `grit crater`: a run's crater measured again at every output from its crater_history.csv, by the
// current rules (C_d, C_w, rim width, lips, area, shape factor, and in 3D the length), into
// crater_measures.csv. A run made before a measure was added, or a sweep's runs, get it without being run again.
#pragma once

#include <filesystem>

namespace grit::app {

/// Reads FOLDER/summary.json (the spacing and the crater region) and FOLDER/crater_history.csv, writes
/// FOLDER/crater_measures.csv; returns the number of outputs measured. Throws core::InputError naming
/// the file and what is wrong with it.
int measure_crater_history(const std::filesystem::path& folder);

}  // namespace grit::app
