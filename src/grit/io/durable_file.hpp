// Putting a finished file in place so that a crash at any moment leaves either the old file or the whole
// new one: the new one is written under a temporary name, flushed to the disk (fsync), renamed over the
// old one, and the folder's entry flushed too.
#pragma once

#include <filesystem>

namespace grit::io {

/// The temporary name a file is written under before commit_file (".NAME.tmp" beside it).
std::filesystem::path temporary_name(const std::filesystem::path& file);

/// fsyncs `temporary`, renames it to `file` and fsyncs their folder. Throws std::system_error naming
/// the file and the reason (the temporary is removed then, and `file` is as it was).
void commit_file(const std::filesystem::path& temporary, const std::filesystem::path& file);

}  // namespace grit::io
