// Reads and validates a TOML case file (with --set overrides) into a CaseSpec.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "grit/io/case_spec.hpp"

namespace grit::io {

/// Reads `file`, applies `overrides` ("key.path=value", the value in TOML syntax or a bare string)
/// and validates everything. Throws core::InputError naming the key, the value and the reason.
CaseSpec read_case(const std::filesystem::path& file, const std::vector<std::string>& overrides = {});

/// The same for a case given as text (the Python module's Case.from_string): `file` names it in messages,
/// gives the run its name, and its folder is where relative paths (meshes) start.
CaseSpec read_case_text(const std::string& text, const std::filesystem::path& file,
                        const std::vector<std::string>& overrides = {});

}  // namespace grit::io
