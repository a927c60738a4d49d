// A thin RAII layer over the HDF5 C library (Debian's libhdf5) for checkpoints: groups, scalar and
// string attributes, and 2D datasets of doubles or integers (rows = particles, columns = components).
// Readable by any HDF5 tool (h5dump, h5py). HDF5 errors become io::Hdf5Error with the object's name.
#pragma once

#include <cstdint>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

namespace grit::io {

/// A failure reading or writing an HDF5 file (missing object, wrong type, unreadable file).
class Hdf5Error : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

/// One group of an open file (the root group is the file itself). Cheap handle; closes on destruction.
class Hdf5Group {
public:
    Hdf5Group(const Hdf5Group&) = delete;
    Hdf5Group& operator=(const Hdf5Group&) = delete;
    Hdf5Group(Hdf5Group&& o) noexcept : id_(o.id_), path_(std::move(o.path_)) { o.id_ = -1; }
    Hdf5Group& operator=(Hdf5Group&&) = delete;
    ~Hdf5Group();

    /// The sub-group `name`, created when writing (it must not exist), opened when reading.
    Hdf5Group create_group(const std::string& name);
    Hdf5Group open_group(const std::string& name) const;
    bool has(const std::string& name) const;
    bool has_attribute(const std::string& name) const;
    /// Names of the sub-groups and datasets, in creation order.
    std::vector<std::string> members() const;

    void write(const std::string& attribute, double value);
    void write(const std::string& attribute, std::int64_t value);
    void write(const std::string& attribute, const std::string& value);
    void write(const std::string& attribute, const char* value) { write(attribute, std::string(value)); }
    double read_double(const std::string& attribute) const;
    std::int64_t read_int(const std::string& attribute) const;
    std::string read_string(const std::string& attribute) const;

    /// A rows x columns dataset (row-major).
    void write(const std::string& dataset, const double* data, std::size_t rows, std::size_t columns);
    void write(const std::string& dataset, const std::int32_t* data, std::size_t rows, std::size_t columns);
    void write(const std::string& dataset, const std::int64_t* data, std::size_t rows, std::size_t columns);
    /// Reads a dataset, checking that it has `columns` columns; returns the values, rows in `rows`.
    std::vector<double> read_doubles(const std::string& dataset, std::size_t columns, std::size_t& rows) const;
    std::vector<std::int32_t> read_int32(const std::string& dataset, std::size_t columns, std::size_t& rows) const;
    std::vector<std::int64_t> read_int64(const std::string& dataset, std::size_t columns, std::size_t& rows) const;

    const std::string& path() const noexcept { return path_; }

protected:
    Hdf5Group(std::int64_t id, std::string path) : id_(id), path_(std::move(path)) {}
    std::int64_t id_ = -1;  // hid_t
    std::string path_;      // for messages: file.h5:/group
};

/// An HDF5 file: created (truncated) for writing or opened read-only. Its root group is the file.
class Hdf5File : public Hdf5Group {
public:
    static Hdf5File create(const std::filesystem::path& file);
    /// Throws Hdf5Error when the file is missing or not a readable HDF5 file (for example truncated).
    static Hdf5File open(const std::filesystem::path& file);
    Hdf5File(Hdf5File&& o) noexcept : Hdf5Group(std::move(o)), file_id_(o.file_id_) { o.file_id_ = -1; }
    ~Hdf5File();
    /// Flushes and closes the file, throwing Hdf5Error if the data did not reach it (the destructor
    /// closes silently); nothing may be used after it.
    void close();

private:
    Hdf5File(std::int64_t id, std::string path) : Hdf5Group(-1, std::move(path)), file_id_(id) { id_ = open_root(); }
    std::int64_t open_root();
    std::int64_t file_id_ = -1;
};

}  // namespace grit::io
