// Truncating a CSV file to the rows a checkpoint had seen, and opening a growing log.
#include "grit/io/csv_file.hpp"

#include <fmt/format.h>

#include <fstream>
#include <stdexcept>
#include <string>

namespace grit::io {

void keep_csv_rows(const std::filesystem::path& file, long rows) {
    std::ifstream in(file, std::ios::binary);
    if (!in) throw std::runtime_error(fmt::format("cannot read '{}' to continue it", file.string()));
    std::string kept, line;
    long lines = 0;
    while (lines <= rows && std::getline(in, line)) {
        kept += line;
        kept += '\n';
        ++lines;
    }
    if (lines <= rows)
        throw std::runtime_error(fmt::format("'{}' has {} row(s), fewer than the checkpoint's {}", file.string(),
                                             lines - 1, rows));
    in.close();
    std::ofstream out(file, std::ios::binary | std::ios::trunc);
    out << kept;
    if (!out) throw std::runtime_error(fmt::format("cannot rewrite '{}'", file.string()));
}

void open_csv_log(std::ofstream& out, const std::filesystem::path& file, const std::string& header, long rows) {
    if (rows >= 0) {
        keep_csv_rows(file, rows);
        out.open(file, std::ios::app);
    } else {
        out.open(file);
        out << header << '\n';
    }
    if (!out) throw std::runtime_error(fmt::format("cannot open '{}' for writing", file.string()));
}

}  // namespace grit::io
