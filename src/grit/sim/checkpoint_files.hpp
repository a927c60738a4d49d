// Where a run's checkpoints lie: checkpoints/checkpoint_<step>.h5 in its run folder.
#pragma once

#include <filesystem>
#include <vector>

namespace grit::sim {

/// The step number of checkpoints/checkpoint_<step>.h5, or -1 for another name.
long checkpoint_step(const std::filesystem::path& file);

/// The checkpoints in `dir`, oldest (lowest step) first.
std::vector<std::filesystem::path> checkpoints_in(const std::filesystem::path& dir);

}  // namespace grit::sim
