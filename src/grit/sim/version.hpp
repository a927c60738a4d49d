// grit's version (CMake's project(VERSION)), written to summary.json and checkpoints.
#pragma once

namespace grit::sim {

#ifndef GRIT_VERSION
#define GRIT_VERSION "unknown"
#endif
inline constexpr const char* version = GRIT_VERSION;

}  // namespace grit::sim
