// VTK XML UnstructuredGrid writer (raw binary appended data) and the atomic-file helper.
#include "grit/io/vtu_writer.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <bit>
#include <cstdint>
#include <fstream>
#include <ostream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

#include <unistd.h>

#include "grit/io/xml_escape.hpp"

namespace grit::io {

static_assert(std::endian::native == std::endian::little,
              "the VTU writer emits the host byte order and declares LittleEndian");

namespace {

/// One DataArray of the appended block: its XML description and its payload size.
struct Block {
    std::string type;  ///< VTK type name: Float64, Int32, Int64, UInt8
    std::string name;
    int components = 1;
    std::uint64_t bytes = 0;
    std::uint64_t offset = 0;  ///< from the byte after '_' to this block's UInt64 header
};

std::string data_array_tag(const Block& b, std::string_view indent) {
    return fmt::format(
        "{}<DataArray type=\"{}\" Name=\"{}\" NumberOfComponents=\"{}\" format=\"appended\" "
        "offset=\"{}\"/>\n",
        indent, b.type, xml_escape(b.name), b.components, b.offset);
}

void write_raw(std::ostream& out, const void* data, std::uint64_t bytes) {
    if (bytes > 0) {
        out.write(static_cast<const char*>(data), static_cast<std::streamsize>(bytes));
    }
}

void write_count(std::ostream& out, std::uint64_t bytes) { write_raw(out, &bytes, sizeof bytes); }

/// Writes first, first+step, ... (n values) as Int64 without materialising the whole array.
void write_int64_sequence(std::ostream& out, std::int64_t first, std::uint64_t n) {
    std::array<std::int64_t, 4096> chunk{};
    std::uint64_t done = 0;
    while (done < n) {
        const std::uint64_t m = std::min<std::uint64_t>(chunk.size(), n - done);
        for (std::uint64_t k = 0; k < m; ++k) {
            chunk[k] = first + static_cast<std::int64_t>(done + k);
        }
        write_raw(out, chunk.data(), m * sizeof(std::int64_t));
        done += m;
    }
}

void write_uint8_fill(std::ostream& out, std::uint8_t value, std::uint64_t n) {
    std::array<std::uint8_t, 4096> chunk{};
    chunk.fill(value);
    std::uint64_t done = 0;
    while (done < n) {
        const std::uint64_t m = std::min<std::uint64_t>(chunk.size(), n - done);
        write_raw(out, chunk.data(), m);
        done += m;
    }
}

/// The dataset's name lists as VTK field data: String arrays in ascii form, each string written as its
/// byte values and ended by 0 (the form VTK's own XML writer uses).
std::string field_data(const PointCloud& cloud) {
    if (cloud.names.empty()) return {};
    std::string xml = "    <FieldData>\n";
    for (const NameList& list : cloud.names) {
        xml += fmt::format("      <Array type=\"String\" Name=\"{}\" NumberOfTuples=\"{}\" format=\"ascii\">\n       ",
                           xml_escape(list.name), list.values.size());
        for (const std::string& value : list.values) {
            for (const char c : value) xml += fmt::format(" {}", static_cast<unsigned>(static_cast<unsigned char>(c)));
            xml += " 0";
        }
        xml += "\n      </Array>\n";
    }
    xml += "    </FieldData>\n";
    return xml;
}

void validate(const PointCloud& cloud) {
    if (cloud.points.size() % 3 != 0) {
        throw std::invalid_argument(fmt::format(
            "write_vtu: point coordinate count {} is not a multiple of 3", cloud.points.size()));
    }
    for (const NameList& list : cloud.names) {
        if (list.name.empty()) throw std::invalid_argument("write_vtu: a name list has an empty name");
        for (const std::string& value : list.values)
            if (value.find('\0') != std::string::npos)
                throw std::invalid_argument(fmt::format("write_vtu: name list '{}' holds a NUL character", list.name));
    }
    const std::size_t n = cloud.size();
    for (const PointArray& a : cloud.arrays) {
        if (a.name.empty()) {
            throw std::invalid_argument("write_vtu: a point-data array has an empty name");
        }
        if (a.components < 1) {
            throw std::invalid_argument(fmt::format(
                "write_vtu: array '{}' has {} components (must be >= 1)", a.name, a.components));
        }
        const std::size_t expected = n * static_cast<std::size_t>(a.components);
        const std::size_t actual = a.value_count();
        if (actual != expected) {
            throw std::invalid_argument(fmt::format(
                "write_vtu: array '{}' has {} {} values, expected {} ({} points x {} components)",
                a.name, actual, a.vtk_type(), expected, n, a.components));
        }
    }
}

/// The appended blocks of a grid, in file order, with their offsets: points, connectivity (`links`
/// indices), offsets and types (one per cell), then the data arrays (`items` values of each: points or
/// cells).
std::vector<Block> grid_blocks(std::uint64_t points, std::uint64_t links, std::uint64_t cells,
                               const std::vector<PointArray>& arrays, std::uint64_t items) {
    std::vector<Block> blocks;
    blocks.push_back({"Float64", "Points", 3, 3 * points * sizeof(double), 0});
    blocks.push_back({"Int64", "connectivity", 1, links * sizeof(std::int64_t), 0});
    blocks.push_back({"Int64", "offsets", 1, cells * sizeof(std::int64_t), 0});
    blocks.push_back({"UInt8", "types", 1, cells * sizeof(std::uint8_t), 0});
    for (const PointArray& a : arrays) {
        const std::uint64_t count = items * static_cast<std::uint64_t>(a.components);
        blocks.push_back({a.vtk_type(), a.name, a.components, count * a.value_bytes(), 0});
    }
    std::uint64_t offset = 0;
    for (Block& b : blocks) {
        b.offset = offset;
        offset += sizeof(std::uint64_t) + b.bytes;
    }
    return blocks;
}

/// The XML before the appended data; the data arrays go under `data` ("PointData" or "CellData").
std::string grid_xml(const std::vector<Block>& blocks, const std::string& field, std::uint64_t points,
                     std::uint64_t cells, const char* data) {
    std::string xml;
    xml += "<?xml version=\"1.0\"?>\n";
    xml += "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" "
           "header_type=\"UInt64\">\n";
    xml += "  <UnstructuredGrid>\n";
    xml += field;
    xml += fmt::format("    <Piece NumberOfPoints=\"{}\" NumberOfCells=\"{}\">\n", points, cells);
    xml += fmt::format("      <{}>\n", data);
    for (std::size_t i = 4; i < blocks.size(); ++i) xml += data_array_tag(blocks[i], "        ");
    xml += fmt::format("      </{}>\n", data);
    xml += "      <Points>\n";
    xml += data_array_tag(blocks[0], "        ");
    xml += "      </Points>\n";
    xml += "      <Cells>\n";
    for (std::size_t i = 1; i < 4; ++i) xml += data_array_tag(blocks[i], "        ");
    xml += "      </Cells>\n";
    xml += "    </Piece>\n";
    xml += "  </UnstructuredGrid>\n";
    xml += "  <AppendedData encoding=\"raw\">\n   _";
    return xml;
}

constexpr std::uint8_t vtk_vertex = 1;
constexpr std::uint8_t vtk_triangle = 5;

}  // namespace

void write_file_atomically(const std::filesystem::path& file,
                           const std::function<void(std::ostream&)>& body) {
    // The temporary name is unique per process and call, so concurrent writers never collide.
    static std::atomic<unsigned long> counter{0};
    std::filesystem::path tmp = file;
    tmp += fmt::format(".tmp.{}.{}", static_cast<long>(::getpid()), counter.fetch_add(1));

    auto discard = [&tmp] {
        std::error_code ignored;
        std::filesystem::remove(tmp, ignored);
    };

    {
        std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
        if (!out) {
            throw std::runtime_error(
                fmt::format("cannot open '{}' for writing (writing '{}')", tmp.string(),
                            file.string()));
        }
        try {
            body(out);
        } catch (...) {
            out.close();
            discard();
            throw;
        }
        out.flush();
        const bool ok = static_cast<bool>(out);
        out.close();
        if (!ok || out.fail()) {
            discard();
            throw std::runtime_error(fmt::format("error writing '{}'", file.string()));
        }
    }

    std::error_code ec;
    std::filesystem::rename(tmp, file, ec);
    if (ec) {
        discard();
        throw std::runtime_error(fmt::format("cannot rename '{}' to '{}': {}", tmp.string(),
                                             file.string(), ec.message()));
    }
}

void write_vtu(const std::filesystem::path& file, const PointCloud& cloud) {
    validate(cloud);
    const std::uint64_t n = cloud.size();

    // Every point is a one-point cell.
    const std::vector<Block> blocks = grid_blocks(n, n, n, cloud.arrays, n);
    const std::string xml = grid_xml(blocks, field_data(cloud), n, n, "PointData");

    write_file_atomically(file, [&](std::ostream& out) {
        out.write(xml.data(), static_cast<std::streamsize>(xml.size()));

        write_count(out, blocks[0].bytes);
        write_raw(out, cloud.points.data(), blocks[0].bytes);

        write_count(out, blocks[1].bytes);
        write_int64_sequence(out, 0, n);  // connectivity: point i is cell i
        write_count(out, blocks[2].bytes);
        write_int64_sequence(out, 1, n);  // offsets: end of each one-point cell
        write_count(out, blocks[3].bytes);
        write_uint8_fill(out, vtk_vertex, n);

        for (std::size_t i = 0; i < cloud.arrays.size(); ++i) {
            const PointArray& a = cloud.arrays[i];
            const Block& b = blocks[4 + i];
            write_count(out, b.bytes);
            write_raw(out, a.data(), b.bytes);
        }

        static constexpr std::string_view tail = "\n  </AppendedData>\n</VTKFile>\n";
        out.write(tail.data(), static_cast<std::streamsize>(tail.size()));
    });
}

void write_surface_vtu(const std::filesystem::path& file, const TriangleSurface& surface) {
    if (surface.points.size() % 3 != 0 || surface.triangles.size() % 3 != 0)
        throw std::invalid_argument("write_surface_vtu: points and triangles need three values each");
    const std::uint64_t points = surface.points.size() / 3, cells = surface.triangles.size() / 3;
    for (const std::int64_t v : surface.triangles)
        if (v < 0 || static_cast<std::uint64_t>(v) >= points)
            throw std::invalid_argument(fmt::format("write_surface_vtu: point index {} out of range", v));
    // The cell arrays are checked as the point arrays of a cloud of one point per triangle.
    PointCloud check;
    check.points.assign(3 * cells, 0.0);
    check.arrays = surface.cell_arrays;
    check.names = surface.names;
    validate(check);

    const std::vector<Block> blocks = grid_blocks(points, 3 * cells, cells, surface.cell_arrays, cells);
    const std::string xml = grid_xml(blocks, field_data(check), points, cells, "CellData");

    write_file_atomically(file, [&](std::ostream& out) {
        out.write(xml.data(), static_cast<std::streamsize>(xml.size()));
        write_count(out, blocks[0].bytes);
        write_raw(out, surface.points.data(), blocks[0].bytes);
        write_count(out, blocks[1].bytes);
        write_raw(out, surface.triangles.data(), blocks[1].bytes);
        write_count(out, blocks[2].bytes);
        std::vector<std::int64_t> ends(cells);
        for (std::uint64_t c = 0; c < cells; ++c) ends[c] = 3 * static_cast<std::int64_t>(c + 1);
        write_raw(out, ends.data(), blocks[2].bytes);
        write_count(out, blocks[3].bytes);
        write_uint8_fill(out, vtk_triangle, cells);
        for (std::size_t i = 0; i < surface.cell_arrays.size(); ++i) {
            const PointArray& a = surface.cell_arrays[i];
            write_count(out, blocks[4 + i].bytes);
            write_raw(out, a.data(), blocks[4 + i].bytes);
        }
        static constexpr std::string_view tail = "\n  </AppendedData>\n</VTKFile>\n";
        out.write(tail.data(), static_cast<std::streamsize>(tail.size()));
    });
}

}  // namespace grit::io
