#include "grit/io/durable_file.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <system_error>

namespace grit::io {

namespace fs = std::filesystem;

namespace {

// fsync of a file or folder; the errno of the first failure, 0 on success.
int sync_path(const fs::path& path, int flags) {
    const int fd = ::open(path.c_str(), flags | O_CLOEXEC);
    if (fd < 0) return errno;
    const int rc = ::fsync(fd) == 0 ? 0 : errno;
    ::close(fd);
    return rc;
}

}  // namespace

fs::path temporary_name(const fs::path& file) {
    // Built by appending: GCC 12 warns (a false -Wstringop-overflow) on "." + std::string at -O3.
    std::string name = ".";
    name += file.filename().string();
    name += ".tmp";
    return file.parent_path() / name;
}

void commit_file(const fs::path& temporary, const fs::path& file) {
    std::error_code ignored;
    if (const int err = sync_path(temporary, O_RDONLY); err != 0) {
        fs::remove(temporary, ignored);
        throw std::system_error(err, std::generic_category(), "cannot flush " + file.string() + " to the disk");
    }
    std::error_code ec;
    fs::rename(temporary, file, ec);
    if (ec) {
        fs::remove(temporary, ignored);
        throw std::system_error(ec, "cannot put " + file.string() + " in place");
    }
    // The rename itself reaches the disk with the folder's entry (EINVAL: a file system without it).
    const fs::path folder = file.parent_path().empty() ? fs::path(".") : file.parent_path();
    if (const int err = sync_path(folder, O_RDONLY | O_DIRECTORY); err != 0 && err != EINVAL)
        throw std::system_error(err, std::generic_category(), "cannot flush the folder of " + file.string());
}

}  // namespace grit::io
