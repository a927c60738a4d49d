// A particle snapshot in the form the writers take: points plus named point-data arrays.
#pragma once

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace grit::io {

/// One point-data array: `components` values per point, Float64, Int32 or (ids) Int64.
struct PointArray {
    std::string name;
    int components = 1;
    bool is_integer = false;
    bool is_int64 = false;                ///< with is_integer: the values are in integer64
    std::vector<double> real;             ///< size n * components when !is_integer
    std::vector<std::int32_t> integer;    ///< size n * components when is_integer and not is_int64
    std::vector<std::int64_t> integer64;  ///< size n * components when is_int64

    static PointArray reals(std::string name, int components, std::vector<double> values = {}) {
        PointArray a;
        a.name = std::move(name);
        a.components = components;
        a.real = std::move(values);
        return a;
    }
    static PointArray integers(std::string name, int components, std::vector<std::int32_t> values = {}) {
        PointArray a = reals(std::move(name), components);
        a.is_integer = true;
        a.integer = std::move(values);
        return a;
    }
    static PointArray integers64(std::string name, int components, std::vector<std::int64_t> values = {}) {
        PointArray a = integers(std::move(name), components);
        a.is_int64 = true;
        a.integer64 = std::move(values);
        return a;
    }

    /// The VTK type name, the number of values, the bytes of one value and the values' storage.
    const char* vtk_type() const noexcept { return is_int64 ? "Int64" : is_integer ? "Int32" : "Float64"; }
    std::size_t value_count() const noexcept {
        return is_int64 ? integer64.size() : is_integer ? integer.size() : real.size();
    }
    std::size_t value_bytes() const noexcept {
        return is_int64 ? sizeof(std::int64_t) : is_integer ? sizeof(std::int32_t) : sizeof(double);
    }
    const void* data() const noexcept {
        return is_int64 ? static_cast<const void*>(integer64.data())
                        : is_integer ? static_cast<const void*>(integer.data()) : static_cast<const void*>(real.data());
    }
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
