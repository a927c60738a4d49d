// A run's output folder: what an earlier run left in it, and clearing that for a fresh run. A fresh run
// never replaces an earlier one silently: the CLI refuses unless told --overwrite (or --restart).
#pragma once

#include <filesystem>
#include <string>

namespace grit::io {

/// One line on the earlier run whose files lie in `dir` ("a completed run of case 'demo' to t = 0.0005 s",
/// "an interrupted run of case 'demo' (checkpoint at step 4210)"), or empty when it holds none.
std::string earlier_run(const std::filesystem::path& dir);

/// Removes what a run and its tools write in `dir` (snapshots, checkpoints, dumps, grain and wall frames,
/// plots, the series, summary, logs and collections), so no stale file sits beside the new run's. Files
/// grit does not write (a case file, notes) stay.
void clear_run_folder(const std::filesystem::path& dir);

/// A digest of a case file's text (64-bit FNV-1a, hex): summary.json keeps it, so that a sweep can tell a
/// kept run of another case text from one of this.
std::string case_digest(const std::filesystem::path& case_file);
/// The same digest of a case's text.
std::string text_digest(const std::string& text);

/// Checks, before a run, that its files can be written in `dir` (or that `dir` can be created, without
/// creating it); throws core::InputError naming `option` (--out), the folder and the reason otherwise.
void check_writable_folder(const std::filesystem::path& dir, const std::string& option);

}  // namespace grit::io
