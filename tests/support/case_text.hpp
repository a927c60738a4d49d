// Editing case-file text in tests.
#pragma once

#include <stdexcept>
#include <string>

namespace grit::testing {

/// `text` with the first occurrence of `from` replaced by `to`; `from` must occur.
inline std::string replaced(std::string text, const std::string& from, const std::string& to) {
    const auto at = text.find(from);
    if (at == std::string::npos) throw std::logic_error("test bug: '" + from + "' not in the case text");
    text.replace(at, from.size(), to);
    return text;
}

}  // namespace grit::testing
