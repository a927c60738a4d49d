// Writes a PointCloud as a VTK XML UnstructuredGrid (.vtu) with raw binary appended data.
#pragma once

#include <filesystem>
#include <functional>
#include <cstdint>
#include <iosfwd>
#include <vector>

#include "grit/io/point_data.hpp"

namespace grit::io {

/// Writes `cloud` to `file` as a VTK XML UnstructuredGrid (version 1.0, LittleEndian,
/// header_type UInt64) with all data in one raw `<AppendedData>` block. Every point is also
/// a VTK_VERTEX cell, so ParaView shows the points without a filter. Points are Float64 x 3;
/// each array is Float64 (or Int32 when `is_integer`) with its `components`. n = 0 is allowed.
/// The cloud's name lists become String arrays of the grid's field data.
/// The file is written to a temporary file in the same directory and renamed into place.
/// Throws std::invalid_argument if an array's size is not n * components (or the point
/// count is not a multiple of 3), std::runtime_error naming the path on I/O failure.
void write_vtu(const std::filesystem::path& file, const PointCloud& cloud);

/// A triangle surface with per-triangle data (wear maps of mesh walls).
struct TriangleSurface {
    std::vector<double> points;                ///< size 3 n
    std::vector<std::int64_t> triangles;       ///< three point indices per triangle
    std::vector<PointArray> cell_arrays;       ///< one value (x components) per triangle
    std::vector<NameList> names;
};

/// Writes `surface` as a VTK XML UnstructuredGrid of VTK_TRIANGLE cells with cell data, in the form
/// and with the checks of write_vtu.
void write_surface_vtu(const std::filesystem::path& file, const TriangleSurface& surface);

/// Runs `body` on a binary stream to a temporary file next to `file`, then renames the
/// temporary file onto `file`, so readers never see a half-written file. The temporary file
/// is removed if `body` throws. Throws std::runtime_error naming the path on I/O failure.
/// Shared by the io writers that rewrite whole files.
void write_file_atomically(const std::filesystem::path& file,
                           const std::function<void(std::ostream&)>& body);

}  // namespace grit::io
