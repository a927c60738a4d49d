#include "grit/io/run_folder.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>
#include <system_error>

#include "grit/core/error.hpp"

namespace grit::io {

namespace fs = std::filesystem;

namespace {

// What a run (and `grit plot`, `grit crater`, the ParaView script) writes into its folder.
constexpr std::array<const char*, 6> run_subfolders = {"snapshots", "checkpoints", "dump", "grains", "walls", "plots"};
constexpr std::array<const char*, 9> run_files = {"series.csv",      "summary.json", "run.log",
                                                  "eroded.csv",      "crater.csv",   "crater_history.csv",
                                                  "impacts.csv",     "crater_measures.csv", "grit_view.pvsm"};

bool has_checkpoints(const fs::path& dir) {
    std::error_code ec;
    if (!fs::is_directory(dir / "checkpoints", ec)) return false;
    for (const auto& e : fs::directory_iterator(dir / "checkpoints", ec))
        if (e.path().extension() == ".h5") return true;
    return false;
}

}  // namespace

std::string earlier_run(const fs::path& dir) {
    std::error_code ec;
    if (!fs::is_directory(dir, ec)) return "";
    if (fs::exists(dir / "summary.json", ec)) {
        try {
            std::ifstream in(dir / "summary.json");
            const auto j = nlohmann::json::parse(in);
            const std::string status = j.value("status", std::string());
            const char* what = status == "completed"     ? "a completed run"
                               : status == "interrupted" ? "an interrupted run"
                               : status == "blow_up"     ? "a run that blew up"
                                                         : "an earlier run";
            return fmt::format("{} of case '{}' to t = {:.6g} s", what, j.value("case", std::string("?")),
                               j.value("end_time", 0.0));
        } catch (const std::exception&) {
            return "an earlier run (its summary.json is unreadable)";
        }
    }
    if (has_checkpoints(dir)) return "an unfinished run (it has checkpoints but no summary.json)";
    for (const char* f : {"series.csv", "run.log"})
        if (fs::exists(dir / f, ec)) return fmt::format("an earlier run's files ({})", f);
    return "";
}

void clear_run_folder(const fs::path& dir) {
    std::error_code ec;
    if (!fs::is_directory(dir, ec)) return;
    for (const char* sub : run_subfolders) fs::remove_all(dir / sub);
    for (const char* f : run_files) fs::remove(dir / f);
    for (const auto& e : fs::directory_iterator(dir))
        if (e.is_regular_file() && e.path().extension() == ".pvd") fs::remove(e.path());
}

std::string text_digest(const std::string& text) {
    std::uint64_t h = 14695981039346656037ull;
    for (const char c : text) {
        h ^= static_cast<unsigned char>(c);
        h *= 1099511628211ull;
    }
    return fmt::format("{:016x}", h);
}

std::string case_digest(const fs::path& case_file) {
    std::ifstream in(case_file, std::ios::binary);
    return text_digest(std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()));
}

void check_writable_folder(const fs::path& dir, const std::string& option) {
    // Nothing is created here (a case refused later leaves no folder behind): a folder that exists takes
    // a test file; one that does not needs its nearest existing parent to be a folder grit may write in.
    std::error_code ec;
    if (fs::exists(dir, ec)) {
        if (!fs::is_directory(dir, ec))
            throw core::InputError(fmt::format("{} {}: not a folder", option, dir.string()));
        const fs::path probe = dir / ".grit_write_test";
        std::ofstream out(probe, std::ios::binary | std::ios::trunc);
        out << "grit\n";
        out.flush();
        const int err = errno;
        const bool written = static_cast<bool>(out);
        out.close();
        fs::remove(probe, ec);
        if (!written)
            throw core::InputError(
                fmt::format("{} {}: cannot write in the folder ({})", option, dir.string(), std::strerror(err)));
        return;
    }
    fs::path parent = dir;
    while (!parent.empty() && !fs::exists(parent, ec)) parent = parent.parent_path();
    if (parent.empty()) parent = ".";
    if (!fs::is_directory(parent, ec))
        throw core::InputError(fmt::format("{} {}: cannot create the folder ({} is not a folder)", option,
                                           dir.string(), parent.string()));
    if (::access(parent.c_str(), W_OK | X_OK) != 0)
        throw core::InputError(fmt::format("{} {}: cannot create the folder in {} ({})", option, dir.string(),
                                           parent.string(), std::strerror(errno)));
}

}  // namespace grit::io
