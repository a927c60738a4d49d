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

/// Points (always 3 coordinates, z = 0 in 2D) and their arrays.
struct PointCloud {
    std::vector<double> points;  ///< size 3 n
    std::vector<PointArray> arrays;
    std::size_t size() const { return points.size() / 3; }
};

}  // namespace grit::io
