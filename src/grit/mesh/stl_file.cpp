// STL reader and writer.
#include "grit/mesh/stl_file.hpp"

#include <fmt/format.h>

#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>

#include "grit/core/error.hpp"

namespace grit::mesh {

namespace {

[[noreturn]] void fail(const std::filesystem::path& file, const std::string& what) {
    throw core::InputError(fmt::format("mesh file '{}': {}", file.string(), what));
}

std::vector<Facet> read_binary(const std::filesystem::path& file, const std::string& bytes, std::uint32_t count) {
    std::vector<Facet> facets(count);
    for (std::uint32_t f = 0; f < count; ++f) {
        const char* p = bytes.data() + 84 + 50 * static_cast<std::size_t>(f) + 12;  // after the normal
        for (int c = 0; c < 3; ++c)
            for (int k = 0; k < 3; ++k) {
                float value;
                std::memcpy(&value, p + 4 * (3 * c + k), 4);
                if (!std::isfinite(value))
                    fail(file, fmt::format("facet {} has a coordinate that is not finite", f + 1));
                facets[f][static_cast<std::size_t>(c)][k] = static_cast<double>(value);
            }
    }
    return facets;
}

std::vector<Facet> read_ascii(const std::filesystem::path& file, const std::string& text) {
    std::vector<Facet> facets;
    std::istringstream lines(text);
    std::string line;
    long line_number = 0;
    Facet facet{};
    int corners = -1;  // -1: outside a loop
    while (std::getline(lines, line)) {
        ++line_number;
        std::istringstream words(line);
        std::string word;
        if (!(words >> word)) continue;
        if (word == "outer") {
            corners = 0;
        } else if (word == "vertex") {
            if (corners < 0 || corners >= 3)
                fail(file, fmt::format("line {}: a vertex outside an 'outer loop' of three", line_number));
            for (int k = 0; k < 3; ++k) {
                std::string number;
                double value = 0.0;
                if (!(words >> number)) fail(file, fmt::format("line {}: a vertex needs three numbers", line_number));
                const auto [end, ec] = std::from_chars(number.data(), number.data() + number.size(), value);
                if (ec != std::errc() || end != number.data() + number.size() || !std::isfinite(value))
                    fail(file, fmt::format("line {}: '{}' is not a finite number", line_number, number));
                facet[static_cast<std::size_t>(corners)][k] = value;
            }
            ++corners;
        } else if (word == "endloop") {
            if (corners != 3)
                fail(file, fmt::format("line {}: a loop with {} vertices (a facet needs 3)", line_number,
                                       std::max(corners, 0)));
            facets.push_back(facet);
            corners = -1;
        } else if (word != "solid" && word != "facet" && word != "endfacet" && word != "endsolid") {
            fail(file, fmt::format("line {}: unexpected '{}' in an ASCII STL", line_number, word));
        }
    }
    if (corners >= 0) fail(file, "the file ends inside a facet");
    return facets;
}

}  // namespace

std::vector<Facet> read_stl(const std::filesystem::path& file) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(file, ec)) fail(file, "no such file");
    std::ifstream in(file, std::ios::binary);
    if (!in) fail(file, "cannot be opened");
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (bytes.empty()) fail(file, "the file is empty");
    std::vector<Facet> facets;
    std::uint32_t count = 0;
    if (bytes.size() >= 84) std::memcpy(&count, bytes.data() + 80, 4);
    // Many binary exporters begin the header with "solid" too: the size decides.
    if (bytes.size() >= 84 && bytes.size() == 84 + 50 * static_cast<std::size_t>(count)) {
        facets = read_binary(file, bytes, count);
    } else if (const auto start = bytes.find_first_not_of(" \t\r\n");
               start != std::string::npos && bytes.compare(start, 5, "solid") == 0) {
        facets = read_ascii(file, bytes);
    } else {
        fail(file, fmt::format("neither an ASCII STL (it does not begin with 'solid') nor a binary one ({} bytes, "
                               "where a binary STL of {} facets has {})",
                               bytes.size(), count, 84 + 50 * static_cast<std::size_t>(count)));
    }
    if (facets.empty()) fail(file, "the file holds no facet");
    return facets;
}

void write_stl(const std::filesystem::path& file, const std::vector<Facet>& facets) {
    std::ofstream out(file, std::ios::binary | std::ios::trunc);
    if (!out) throw std::runtime_error("cannot open '" + file.string() + "' for writing");
    char header[80] = "binary STL written by grit";
    out.write(header, 80);
    const auto count = static_cast<std::uint32_t>(facets.size());
    out.write(reinterpret_cast<const char*>(&count), 4);
    for (const Facet& f : facets) {
        core::Vec<3> n = core::cross(f[1] - f[0], f[2] - f[0]);
        const double length = core::norm(n);
        if (length > 0.0) n *= 1.0 / length;
        float values[12];
        for (int k = 0; k < 3; ++k)
            values[k] = static_cast<float>(n[k]);
        for (int c = 0; c < 3; ++c)
            for (int k = 0; k < 3; ++k)
                values[3 + 3 * c + k] = static_cast<float>(f[static_cast<std::size_t>(c)][k]);
        out.write(reinterpret_cast<const char*>(values), sizeof values);
        const std::uint16_t attribute = 0;
        out.write(reinterpret_cast<const char*>(&attribute), 2);
    }
    if (!out) throw std::runtime_error("error writing '" + file.string() + "'");
}

}  // namespace grit::mesh
