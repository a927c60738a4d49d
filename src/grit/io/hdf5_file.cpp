// HDF5 wrapper: files, groups, attributes and 2D datasets through the C API.
#include "grit/io/hdf5_file.hpp"

#include <hdf5.h>

#include <fmt/format.h>

#include <array>

namespace grit::io {

namespace {

// HDF5 prints its error stack to stderr by default; grit reports its own one-line errors instead. Done
// on first use, so programs that never open an HDF5 file do not start the library.
void silence_hdf5() {
    static const bool silenced = H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr) >= 0;
    (void)silenced;
}

hid_t check(hid_t id, const std::string& what) {
    if (id < 0) throw Hdf5Error(what);
    return id;
}

void check(herr_t status, const std::string& what) {
    if (status < 0) throw Hdf5Error(what);
}

// Closes an HDF5 object handle at scope exit.
struct Handle {
    hid_t id;
    herr_t (*close)(hid_t);
    ~Handle() {
        if (id >= 0) close(id);
    }
};

void write_attribute(hid_t group, const std::string& path, const std::string& name, hid_t type, const void* value) {
    if (H5Aexists(group, name.c_str()) > 0) check(H5Adelete(group, name.c_str()), "cannot replace " + path + "@" + name);
    const Handle space{check(H5Screate(H5S_SCALAR), "H5Screate"), H5Sclose};
    const Handle attr{check(H5Acreate2(group, name.c_str(), type, space.id, H5P_DEFAULT, H5P_DEFAULT),
                            "cannot create attribute " + path + "@" + name),
                      H5Aclose};
    check(H5Awrite(attr.id, type, value), "cannot write attribute " + path + "@" + name);
}

void read_attribute(hid_t group, const std::string& path, const std::string& name, hid_t type, void* value) {
    if (H5Aexists(group, name.c_str()) <= 0) throw Hdf5Error(fmt::format("{} has no attribute '{}'", path, name));
    const Handle attr{check(H5Aopen(group, name.c_str(), H5P_DEFAULT), "cannot open " + path + "@" + name), H5Aclose};
    check(H5Aread(attr.id, type, value), "cannot read attribute " + path + "@" + name);
}

void write_dataset(hid_t group, const std::string& path, const std::string& name, hid_t file_type, hid_t memory_type,
                   const void* data, std::size_t rows, std::size_t columns) {
    const std::array<hsize_t, 2> dims{rows, columns};
    const Handle space{check(H5Screate_simple(2, dims.data(), nullptr), "H5Screate_simple"), H5Sclose};
    const Handle set{check(H5Dcreate2(group, name.c_str(), file_type, space.id, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
                           "cannot create dataset " + path + "/" + name),
                     H5Dclose};
    if (rows * columns > 0)
        check(H5Dwrite(set.id, memory_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data),
              "cannot write dataset " + path + "/" + name);
}

template <class T>
std::vector<T> read_dataset(hid_t group, const std::string& path, const std::string& name, hid_t memory_type,
                            std::size_t columns, std::size_t& rows) {
    if (H5Lexists(group, name.c_str(), H5P_DEFAULT) <= 0)
        throw Hdf5Error(fmt::format("{} has no dataset '{}'", path, name));
    const Handle set{check(H5Dopen2(group, name.c_str(), H5P_DEFAULT), "cannot open dataset " + path + "/" + name),
                     H5Dclose};
    const Handle space{check(H5Dget_space(set.id), "H5Dget_space"), H5Sclose};
    std::array<hsize_t, 2> dims{0, 0};
    if (H5Sget_simple_extent_ndims(space.id) != 2 || H5Sget_simple_extent_dims(space.id, dims.data(), nullptr) != 2 ||
        dims[1] != columns)
        throw Hdf5Error(fmt::format("{}/{}: expected {} column(s)", path, name, columns));
    rows = static_cast<std::size_t>(dims[0]);
    std::vector<T> out(rows * columns);
    if (!out.empty())
        check(H5Dread(set.id, memory_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, out.data()),
              "cannot read dataset " + path + "/" + name + " (truncated file?)");
    return out;
}

}  // namespace

Hdf5Group::~Hdf5Group() {
    if (id_ >= 0) H5Gclose(id_);
}

Hdf5Group Hdf5Group::create_group(const std::string& name) {
    const hid_t g = check(H5Gcreate2(id_, name.c_str(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
                          "cannot create group " + path_ + "/" + name);
    return Hdf5Group(g, path_ + "/" + name);
}

Hdf5Group Hdf5Group::open_group(const std::string& name) const {
    if (!has(name)) throw Hdf5Error(fmt::format("{} has no group '{}'", path_, name));
    const hid_t g = check(H5Gopen2(id_, name.c_str(), H5P_DEFAULT), "cannot open group " + path_ + "/" + name);
    return Hdf5Group(g, path_ + "/" + name);
}

bool Hdf5Group::has(const std::string& name) const { return H5Lexists(id_, name.c_str(), H5P_DEFAULT) > 0; }

bool Hdf5Group::has_attribute(const std::string& name) const { return H5Aexists(id_, name.c_str()) > 0; }

std::vector<std::string> Hdf5Group::members() const {
    std::vector<std::string> out;
    H5G_info_t info;
    check(H5Gget_info(id_, &info), "cannot list " + path_);
    for (hsize_t k = 0; k < info.nlinks; ++k) {
        const ssize_t size = H5Lget_name_by_idx(id_, ".", H5_INDEX_NAME, H5_ITER_INC, k, nullptr, 0, H5P_DEFAULT);
        std::string name(static_cast<std::size_t>(size), '\0');
        H5Lget_name_by_idx(id_, ".", H5_INDEX_NAME, H5_ITER_INC, k, name.data(), name.size() + 1, H5P_DEFAULT);
        out.push_back(name);
    }
    return out;
}

void Hdf5Group::write(const std::string& attribute, double value) {
    write_attribute(id_, path_, attribute, H5T_NATIVE_DOUBLE, &value);
}

void Hdf5Group::write(const std::string& attribute, std::int64_t value) {
    write_attribute(id_, path_, attribute, H5T_NATIVE_INT64, &value);
}

void Hdf5Group::write(const std::string& attribute, const std::string& value) {
    const Handle type{check(H5Tcopy(H5T_C_S1), "H5Tcopy"), H5Tclose};
    check(H5Tset_size(type.id, H5T_VARIABLE), "H5Tset_size");
    check(H5Tset_cset(type.id, H5T_CSET_UTF8), "H5Tset_cset");
    const char* text = value.c_str();
    write_attribute(id_, path_, attribute, type.id, &text);
}

double Hdf5Group::read_double(const std::string& attribute) const {
    double v = 0.0;
    read_attribute(id_, path_, attribute, H5T_NATIVE_DOUBLE, &v);
    return v;
}

std::int64_t Hdf5Group::read_int(const std::string& attribute) const {
    std::int64_t v = 0;
    read_attribute(id_, path_, attribute, H5T_NATIVE_INT64, &v);
    return v;
}

std::string Hdf5Group::read_string(const std::string& attribute) const {
    if (H5Aexists(id_, attribute.c_str()) <= 0)
        throw Hdf5Error(fmt::format("{} has no attribute '{}'", path_, attribute));
    const Handle attr{check(H5Aopen(id_, attribute.c_str(), H5P_DEFAULT), "cannot open " + path_ + "@" + attribute),
                      H5Aclose};
    const Handle stored{check(H5Aget_type(attr.id), "H5Aget_type"), H5Tclose};
    if (H5Tget_class(stored.id) != H5T_STRING || H5Tis_variable_str(stored.id) <= 0)
        throw Hdf5Error(fmt::format("{}@{} is not a text attribute", path_, attribute));
    const Handle type{check(H5Tcopy(H5T_C_S1), "H5Tcopy"), H5Tclose};
    check(H5Tset_size(type.id, H5T_VARIABLE), "H5Tset_size");
    check(H5Tset_cset(type.id, H5T_CSET_UTF8), "H5Tset_cset");
    char* text = nullptr;
    check(H5Aread(attr.id, type.id, &text), "cannot read attribute " + path_ + "@" + attribute);
    std::string out = text ? text : "";
    H5free_memory(text);
    return out;
}

void Hdf5Group::write(const std::string& dataset, const double* data, std::size_t rows, std::size_t columns) {
    write_dataset(id_, path_, dataset, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, data, rows, columns);
}

void Hdf5Group::write(const std::string& dataset, const std::int32_t* data, std::size_t rows, std::size_t columns) {
    write_dataset(id_, path_, dataset, H5T_STD_I32LE, H5T_NATIVE_INT32, data, rows, columns);
}

void Hdf5Group::write(const std::string& dataset, const std::int64_t* data, std::size_t rows, std::size_t columns) {
    write_dataset(id_, path_, dataset, H5T_STD_I64LE, H5T_NATIVE_INT64, data, rows, columns);
}

std::vector<double> Hdf5Group::read_doubles(const std::string& dataset, std::size_t columns, std::size_t& rows) const {
    return read_dataset<double>(id_, path_, dataset, H5T_NATIVE_DOUBLE, columns, rows);
}

std::vector<std::int32_t> Hdf5Group::read_int32(const std::string& dataset, std::size_t columns,
                                                std::size_t& rows) const {
    return read_dataset<std::int32_t>(id_, path_, dataset, H5T_NATIVE_INT32, columns, rows);
}

std::vector<std::int64_t> Hdf5Group::read_int64(const std::string& dataset, std::size_t columns,
                                                std::size_t& rows) const {
    return read_dataset<std::int64_t>(id_, path_, dataset, H5T_NATIVE_INT64, columns, rows);
}

Hdf5File Hdf5File::create(const std::filesystem::path& file) {
    silence_hdf5();
    const hid_t f = check(H5Fcreate(file.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT),
                          "cannot create " + file.string());
    return Hdf5File(f, file.string() + ":");
}

Hdf5File Hdf5File::open(const std::filesystem::path& file) {
    silence_hdf5();
    if (!std::filesystem::is_regular_file(file)) throw Hdf5Error(file.string() + " does not exist");
    if (H5Fis_hdf5(file.c_str()) <= 0)
        throw Hdf5Error(file.string() + " is not a readable HDF5 file (truncated or of another kind)");
    const hid_t f = check(H5Fopen(file.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT),
                          file.string() + " is not a readable HDF5 file (truncated or of another kind)");
    return Hdf5File(f, file.string() + ":");
}

std::int64_t Hdf5File::open_root() { return check(H5Gopen2(file_id_, "/", H5P_DEFAULT), "cannot open " + path_ + "/"); }

void Hdf5File::close() {
    // Every handle under the root is closed by now (the groups are scoped); a write that fails only at
    // the flush (a full disk, a file-size limit) is reported here rather than lost in the destructor.
    const std::string what = path_;
    if (id_ >= 0) H5Gclose(id_);
    id_ = -1;
    if (file_id_ < 0) return;
    const herr_t flushed = H5Fflush(file_id_, H5F_SCOPE_GLOBAL);
    const herr_t closed = H5Fclose(file_id_);
    file_id_ = -1;
    if (flushed < 0 || closed < 0) throw Hdf5Error("cannot finish writing " + what + " (disk full or not writable?)");
}

Hdf5File::~Hdf5File() {
    if (id_ >= 0) H5Gclose(id_);
    id_ = -1;
    if (file_id_ >= 0) H5Fclose(file_id_);
}

}  // namespace grit::io
