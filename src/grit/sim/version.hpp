// grit's version (CMake's project(VERSION)) and the git revision it was built from, written to
// summary.json, run.log and checkpoints.
#pragma once

namespace grit::sim {

#ifndef GRIT_VERSION
#define GRIT_VERSION "unknown"
#endif
inline constexpr const char* version = GRIT_VERSION;
/// `git describe --always --dirty` when the build was configured ("unknown" outside a checkout).
const char* git_revision() noexcept;

}  // namespace grit::sim
