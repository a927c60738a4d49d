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

// The whole file or an error: every facet is `facet ... outer loop, three vertices, endloop, endfacet`,
// every solid ends with `endsolid`, so a file cut short anywhere is refused, not read in part.
std::vector<Facet> read_ascii(const std::filesystem::path& file, const std::string& text) {
    std::vector<Facet> facets;
    std::istringstream lines(text);
    std::string line;
    long line_number = 0;
    Facet facet{};
    enum class In { nothing, solid, in_facet, loop, looped } in = In::nothing;
    int corners = 0;
    long solid_at = 0, facet_at = 0;  // the lines of the solid and the facet open
    auto expect = [&](In where, const char* word) {
        if (in != where)
            fail(file, fmt::format("line {}: '{}' out of place (an ASCII STL is solid, facet, outer loop, three "
                                   "vertices, endloop, endfacet, ..., endsolid)",
                                   line_number, word));
    };
    while (std::getline(lines, line)) {
        ++line_number;
        std::istringstream words(line);
        std::string word;
        if (!(words >> word)) continue;
        if (word == "solid") {
            expect(In::nothing, "solid");
            in = In::solid;
            solid_at = line_number;
        } else if (word == "facet") {
            expect(In::solid, "facet");
            in = In::in_facet;
            facet_at = line_number;
        } else if (word == "outer") {
            expect(In::in_facet, "outer loop");
            in = In::loop;
            corners = 0;
        } else if (word == "vertex") {
            if (in != In::loop || corners >= 3)
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
            expect(In::loop, "endloop");
            if (corners != 3)
                fail(file, fmt::format("line {}: a loop with {} vertices (a facet needs 3)", line_number, corners));
            in = In::looped;
        } else if (word == "endfacet") {
            expect(In::looped, "endfacet");
            facets.push_back(facet);
            in = In::solid;
        } else if (word == "endsolid") {
            expect(In::solid, "endsolid");
            in = In::nothing;
        } else {
            fail(file, fmt::format("line {}: unexpected '{}' in an ASCII STL", line_number, word));
        }
    }
    if (in == In::solid)
        fail(file, fmt::format("the file ends without the 'endsolid' of the solid opened at line {} (cut short?)",
                               solid_at));
    if (in != In::nothing)
        fail(file, fmt::format("the file ends inside the facet opened at line {} (cut short?)", facet_at));
    return facets;
}

}  // namespace

std::vector<Facet> read_stl(const std::filesystem::path& file) {
    std::error_code ec;
    if (!std::filesystem::exists(file, ec)) fail(file, "no such file");
    if (!std::filesystem::is_regular_file(file, ec)) fail(file, "not a regular file (a folder, a device or a pipe)");
    std::ifstream in(file, std::ios::binary);
    if (!in) fail(file, "cannot be opened");
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    return parse_stl(bytes, file);
}

std::vector<Facet> parse_stl(const std::string& bytes, const std::filesystem::path& file) {
    if (bytes.empty()) fail(file, "the file is empty");
    std::vector<Facet> facets;
    std::uint32_t count = 0;
    if (bytes.size() >= 84) std::memcpy(&count, bytes.data() + 80, 4);
    // Many binary exporters begin the header with "solid" too: the size decides.
    if (bytes.size() >= 84 && bytes.size() == 84 + 50 * static_cast<std::size_t>(count)) {
        facets = read_binary(file, bytes, count);
    } else if (const auto start = bytes.find_first_not_of(" \t\r\n");
               start != std::string::npos && bytes.compare(start, 5, "solid") == 0 &&
               bytes.find('\0') == std::string::npos) {
        facets = read_ascii(file, bytes);
    } else if (bytes.size() >= 84 && bytes.find('\0') != std::string::npos) {
        // Binary (text has no NUL byte) whose size does not match the triangle count in its header.
        fail(file, fmt::format("a binary STL of {} bytes, where its header's {} facets need {}: {}", bytes.size(),
                               count, 84 + 50 * static_cast<std::size_t>(count),
                               bytes.size() < 84 + 50 * static_cast<std::size_t>(count) ? "cut short"
                                                                                         : "bytes after the last facet"));
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
