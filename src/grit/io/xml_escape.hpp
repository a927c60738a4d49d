// Text for XML attributes, shared by the VTK writers (.vtu, .pvd).
#pragma once

#include <string>
#include <string_view>

namespace grit::io {

/// Escapes the five XML special characters for use inside a double-quoted attribute.
inline std::string xml_escape(std::string_view s) {
    std::string out;
    out.reserve(s.size());
    for (const char c : s) {
        switch (c) {
            case '&': out += "&amp;"; break;
            case '<': out += "&lt;"; break;
            case '>': out += "&gt;"; break;
            case '"': out += "&quot;"; break;
            case '\'': out += "&apos;"; break;
            default: out += c;
        }
    }
    return out;
}

}  // namespace grit::io
