// CSV time-series writer: header line, then rows of {:.10g} values flushed one by one.
#include "grit/io/series_writer.hpp"

#include "grit/io/csv_file.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <iterator>
#include <stdexcept>
#include <string_view>
#include <utility>

namespace grit::io {

namespace {

/// Quotes a CSV field (RFC 4180) when it contains a comma, a quote or a line break.
std::string csv_field(std::string_view s) {
    if (s.find_first_of(",\"\r\n") == std::string_view::npos) {
        return std::string(s);
    }
    std::string out = "\"";
    for (const char c : s) {
        if (c == '"') {
            out += '"';
        }
        out += c;
    }
    out += '"';
    return out;
}

/// The comma-separated fields of an unquoted CSV line.
std::vector<std::string> split_fields(const std::string& line) {
    std::vector<std::string> fields;
    std::size_t start = 0;
    for (;;) {
        const std::size_t comma = line.find(',', start);
        fields.push_back(line.substr(start, comma == std::string::npos ? std::string::npos : comma - start));
        if (comma == std::string::npos) return fields;
        start = comma + 1;
    }
}

}  // namespace

SeriesWriter::SeriesWriter(std::filesystem::path file, std::vector<std::string> columns)
    : file_(std::move(file)), columns_(std::move(columns)) {
    if (columns_.empty()) {
        throw std::invalid_argument(
            fmt::format("SeriesWriter: no columns given for '{}'", file_.string()));
    }
    out_.open(file_, std::ios::out | std::ios::trunc);
    if (!out_) {
        throw std::runtime_error(fmt::format("cannot open '{}' for writing", file_.string()));
    }
    std::string line;
    for (std::size_t i = 0; i < columns_.size(); ++i) {
        if (i > 0) {
            line += ',';
        }
        line += csv_field(columns_[i]);
    }
    line += '\n';
    out_ << line << std::flush;
    if (!out_) {
        throw std::runtime_error(fmt::format("error writing '{}'", file_.string()));
    }
}

SeriesWriter::SeriesWriter(std::filesystem::path file, std::vector<std::string> columns, long rows)
    : file_(std::move(file)), columns_(std::move(columns)), rows_(rows) {
    keep_csv_rows(file_, rows);
    std::string header;
    {
        std::ifstream in(file_);
        std::getline(in, header);
    }
    std::string expected;
    for (std::size_t i = 0; i < columns_.size(); ++i) {
        if (i > 0) expected += ',';  // appended, not ("," + field): GCC 12 warns -Wrestrict on the temporary
        expected += csv_field(columns_[i]);
    }
    if (header != expected) add_missing_columns(header);
    out_.open(file_, std::ios::out | std::ios::app);
    if (!out_) throw std::runtime_error(fmt::format("cannot open '{}' for writing", file_.string()));
}

void SeriesWriter::add_missing_columns(const std::string& header) {
    // A series written by an older grit lacks the columns added since; its rows get "nan" there, so
    // a long run can go on with a newer grit. A column this run no longer writes would lose data, and
    // quoted names are not parsed here: both are refused.
    const auto refuse = [&] {
        return std::runtime_error(fmt::format("'{}' has other columns than this run writes; cannot continue it",
                                              file_.string()));
    };
    if (header.find('"') != std::string::npos) throw refuse();
    const std::vector<std::string> old_columns = split_fields(header);
    std::vector<std::size_t> source(columns_.size(), old_columns.size());  // old_columns.size(): added
    for (std::size_t o = 0; o < old_columns.size(); ++o) {
        const auto it = std::find(columns_.begin(), columns_.end(), old_columns[o]);
        if (it == columns_.end() || source[static_cast<std::size_t>(it - columns_.begin())] != old_columns.size())
            throw refuse();
        source[static_cast<std::size_t>(it - columns_.begin())] = o;
    }
    std::string text;
    for (std::size_t i = 0; i < columns_.size(); ++i) {
        if (i > 0) text += ',';
        text += csv_field(columns_[i]);
        if (source[i] == old_columns.size()) added_columns_.push_back(columns_[i]);
    }
    text += '\n';
    std::ifstream in(file_);
    std::string line;
    std::getline(in, line);  // the old header
    while (std::getline(in, line)) {
        const std::vector<std::string> values = split_fields(line);
        if (values.size() != old_columns.size())
            throw std::runtime_error(fmt::format("'{}': a row has {} values where the header names {}", file_.string(),
                                                 values.size(), old_columns.size()));
        for (std::size_t i = 0; i < columns_.size(); ++i) {
            if (i > 0) text += ',';
            text += source[i] == old_columns.size() ? std::string("nan") : values[source[i]];
        }
        text += '\n';
    }
    in.close();
    std::ofstream out(file_, std::ios::binary | std::ios::trunc);
    out << text;
    if (!out) throw std::runtime_error(fmt::format("cannot rewrite '{}'", file_.string()));
}

void SeriesWriter::write_row(const std::vector<double>& values) {
    if (values.size() != columns_.size()) {
        throw std::logic_error(fmt::format("SeriesWriter '{}': row has {} values, expected {}",
                                           file_.string(), values.size(), columns_.size()));
    }
    fmt::memory_buffer line;
    for (std::size_t i = 0; i < values.size(); ++i) {
        if (i > 0) {
            line.push_back(',');
        }
        fmt::format_to(std::back_inserter(line), "{:.10g}", values[i]);
    }
    line.push_back('\n');
    out_.write(line.data(), static_cast<std::streamsize>(line.size()));
    out_.flush();
    ++rows_;
    if (!out_) {
        throw std::runtime_error(fmt::format("error writing '{}'", file_.string()));
    }
}

}  // namespace grit::io
