// Maintains a ParaView .pvd collection file that lists the written snapshots with their times.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "grit/io/hdf5_file.hpp"

namespace grit::io {

/// A ParaView collection (.pvd, VTKFile type="Collection") of time-stamped datasets.
/// Every add() rewrites the whole file atomically (temporary file + rename), so the .pvd on
/// disk is always complete and lists every dataset added so far. Nothing is written before
/// the first add().
class PvdWriter {
public:
    /// One dataset of the collection.
    struct Entry {
        double time = 0.0;
        std::string relative_path;  ///< as written into the `file` attribute
    };

    /// Collection file `file`; the dataset paths given to add() are relative to its directory.
    explicit PvdWriter(std::filesystem::path file);

    /// Appends a dataset at `time` (printed with `{:.17g}`) and rewrites the .pvd.
    /// Throws std::invalid_argument for a non-finite time or an empty path, and
    /// std::runtime_error naming the path on I/O failure (the entry is then not kept).
    void add(double time, const std::string& relative_path);

    /// Replaces the list with `entries` (a restart's, from its checkpoint) and rewrites the .pvd.
    void restore(std::vector<Entry> entries) {
        entries_ = std::move(entries);
        rewrite();
    }

    /// The datasets added so far, in order.
    const std::vector<Entry>& entries() const { return entries_; }

    /// The collection file.
    const std::filesystem::path& file() const { return file_; }

private:
    void rewrite() const;

    std::filesystem::path file_;
    std::vector<Entry> entries_;
};

/// A collection's entries into a checkpoint group (`<prefix>_times`, `<prefix>_files`), and back.
void save_pvd_entries(Hdf5Group& group, const std::string& prefix, const std::vector<PvdWriter::Entry>& entries);
std::vector<PvdWriter::Entry> load_pvd_entries(const Hdf5Group& group, const std::string& prefix);

}  // namespace grit::io
