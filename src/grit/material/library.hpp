// The built-in material library, with the published parameters.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "grit/material/material.hpp"

namespace grit::material {

/// All built-in materials, in the order `grit materials` lists them.
const std::vector<Material>& library();

/// The built-in material of that name, if any.
std::optional<Material> find_in_library(const std::string& name);

/// One human-readable block per material (used by `grit materials`).
std::string describe(const Material& m);

}  // namespace grit::material
