// Writes a time series (one row of numbers per step) as a CSV file with a header line.
#pragma once

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace grit::io {

/// A CSV time series: a header line of column names, then one row per write_row(), each value
/// printed with `{:.10g}` and the file flushed after every row so it can be followed live.
/// Column names containing a comma, quote or line break are quoted as in RFC 4180.
class SeriesWriter {
public:
    /// Creates (truncates) `file` and writes the header line. Throws std::invalid_argument
    /// for an empty column list and std::runtime_error naming the path on I/O failure.
    SeriesWriter(std::filesystem::path file, std::vector<std::string> columns);
    /// Continues an existing series after a restart: keeps its header and first `rows` rows and
    /// appends. A header that lacks some of `columns` (a series from an older grit) is rewritten with
    /// them, its rows holding "nan" there (added_columns() names them); one that has a column not in
    /// `columns` throws std::runtime_error naming the file.
    SeriesWriter(std::filesystem::path file, std::vector<std::string> columns, long rows);

    /// Appends one row and flushes. Throws std::logic_error if `values.size()` differs from
    /// the number of columns, std::runtime_error naming the path on I/O failure.
    void write_row(const std::vector<double>& values);

    /// Rows written so far (continued ones included).
    long rows() const { return rows_; }

    /// The column names, in order.
    const std::vector<std::string>& columns() const { return columns_; }

    /// The CSV file.
    const std::filesystem::path& file() const { return file_; }

    /// The columns a continued series did not have, in order (empty for a new or matching one).
    const std::vector<std::string>& added_columns() const { return added_columns_; }

private:
    void add_missing_columns(const std::string& header);

    std::filesystem::path file_;
    std::vector<std::string> columns_;
    std::ofstream out_;
    long rows_ = 0;
    std::vector<std::string> added_columns_;
};

}  // namespace grit::io
