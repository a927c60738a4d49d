// A particle snapshot in the form the writers take: points plus named point-data arrays.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace grit::io {

/// One point-data array: `components` values per point, either Float64 or Int32.
struct PointArray {
    std::string name;
    int components = 1;
    bool is_integer = false;
    std::vector<double> real;        ///< size n * components when !is_integer
    std::vector<std::int32_t> integer;  ///< size n * components when is_integer
};

/// A named list of strings stored with a dataset rather than per point (VTK field data): the names
/// behind an integer code, such as `material_names` for the `material` array.
struct NameList {
    std::string name;
    std::vector<std::string> values;
};

/// Points (always 3 coordinates, z = 0 in 2D), their arrays and the dataset's name lists.
struct PointCloud {
    std::vector<double> points;  ///< size 3 n
    std::vector<PointArray> arrays;
    std::vector<NameList> names;
    std::size_t size() const { return points.size() / 3; }
};

}  // namespace grit::io
