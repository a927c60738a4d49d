// Truncating a CSV file to the rows a checkpoint had seen.
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

}  // namespace grit::io
