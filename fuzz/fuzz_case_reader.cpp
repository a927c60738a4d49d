// libFuzzer target: the case reader. The input is a case file's text, then optionally a line "#--set" and
// one override per line ("key.path=value", as `grit run --set` takes it). Whatever the bytes, the reader
// either returns a case or throws core::InputError (exit 2 in the command); any other exception, crash,
// hang or sanitizer report is a finding.
#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string>
#include <vector>

#include "grit/core/error.hpp"
#include "grit/io/case_reader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string input(reinterpret_cast<const char*>(data), size);
    std::string text = input;
    std::vector<std::string> overrides;
    if (const auto at = input.find("\n#--set\n"); at != std::string::npos) {
        text = input.substr(0, at + 1);
        std::istringstream lines(input.substr(at + 8));
        for (std::string line; std::getline(lines, line);)
            if (!line.empty()) overrides.push_back(line);
    }
    try {
        // A folder that does not exist: a mesh named by a relative path is not found, as in a case without it.
        (void)grit::io::read_case_text(text, "/nonexistent/fuzz/case.toml", overrides);
    } catch (const grit::core::InputError&) {
    }
    return 0;
}
