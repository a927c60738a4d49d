// Helpers for the CSV files a run appends to (series.csv, impacts.csv) when it is restarted.
#pragma once

#include <filesystem>
#include <fstream>
#include <string>

namespace grit::io {

/// Cuts `file` to its header line and its first `rows` data rows (the rows a checkpoint had seen; a
/// run killed after the checkpoint may have written more). Throws std::runtime_error naming the file
/// when it is missing or has fewer rows.
void keep_csv_rows(const std::filesystem::path& file, long rows);

/// Opens a log that grows by rows (impacts.csv, eroded.csv) into `out`: a fresh file holding its `header`
/// line (without the line end), or, on a restart (`rows` >= 0), the file cut by keep_csv_rows and opened
/// to append after them. Throws std::runtime_error naming the file when it cannot be opened.
void open_csv_log(std::ofstream& out, const std::filesystem::path& file, const std::string& header, long rows);

}  // namespace grit::io
