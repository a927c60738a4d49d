// ParaView .pvd collection writer: rewrites the whole file atomically after each dataset.
#include "grit/io/pvd_writer.hpp"

#include <fmt/format.h>

#include <cmath>
#include <ostream>
#include <stdexcept>
#include <string_view>
#include <utility>

#include "grit/io/vtu_writer.hpp"
#include "grit/io/xml_escape.hpp"

namespace grit::io {

PvdWriter::PvdWriter(std::filesystem::path file) : file_(std::move(file)) {}

void PvdWriter::add(double time, const std::string& relative_path) {
    if (!std::isfinite(time)) {
        throw std::invalid_argument(
            fmt::format("PvdWriter: non-finite time {} for '{}'", time, relative_path));
    }
    if (relative_path.empty()) {
        throw std::invalid_argument("PvdWriter: empty dataset path");
    }
    entries_.push_back({time, relative_path});
    try {
        rewrite();
    } catch (...) {
        entries_.pop_back();
        throw;
    }
}

void PvdWriter::rewrite() const {
    std::string text;
    text += "<?xml version=\"1.0\"?>\n";
    text += "<VTKFile type=\"Collection\" version=\"1.0\" byte_order=\"LittleEndian\">\n";
    text += "  <Collection>\n";
    for (const Entry& e : entries_) {
        text += fmt::format("    <DataSet timestep=\"{:.17g}\" group=\"\" part=\"0\" file=\"{}\"/>\n",
                            e.time, xml_escape(e.relative_path));
    }
    text += "  </Collection>\n";
    text += "</VTKFile>\n";
    write_file_atomically(file_, [&text](std::ostream& out) {
        out.write(text.data(), static_cast<std::streamsize>(text.size()));
    });
}

void save_pvd_entries(Hdf5Group& group, const std::string& prefix, const std::vector<PvdWriter::Entry>& entries) {
    std::vector<double> times;
    std::string files;
    for (const auto& e : entries) {
        times.push_back(e.time);
        files += e.relative_path + "\n";  // paths hold no line break (grit names them)
    }
    group.write(prefix + "_times", times.data(), times.size(), 1);
    group.write(prefix + "_files", files);
}

std::vector<PvdWriter::Entry> load_pvd_entries(const Hdf5Group& group, const std::string& prefix) {
    std::size_t rows = 0;
    const auto times = group.read_doubles(prefix + "_times", 1, rows);
    const std::string files = group.read_string(prefix + "_files");
    std::vector<PvdWriter::Entry> entries;
    std::size_t start = 0;
    for (std::size_t k = 0; k < rows; ++k) {
        const std::size_t end = files.find('\n', start);
        if (end == std::string::npos) throw Hdf5Error(group.path() + "/" + prefix + "_files: fewer paths than times");
        entries.push_back({times[k], files.substr(start, end - start)});
        start = end + 1;
    }
    return entries;
}

}  // namespace grit::io
