// Helpers for the CSV files a run appends to (series.csv, impacts.csv) when it is restarted.
#pragma once

#include <filesystem>

namespace grit::io {

/// Cuts `file` to its header line and its first `rows` data rows (the rows a checkpoint had seen; a
/// run killed after the checkpoint may have written more). Throws std::runtime_error naming the file
/// when it is missing or has fewer rows.
void keep_csv_rows(const std::filesystem::path& file, long rows);

}  // namespace grit::io
