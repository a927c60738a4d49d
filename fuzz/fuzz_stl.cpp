// libFuzzer target: the STL reader (ASCII and binary). Whatever the bytes, it returns the facets of a
// whole file or throws core::InputError naming the problem; any other exception, crash, hang or
// sanitizer report is a finding.
#include <cstddef>
#include <cstdint>
#include <string>

#include "grit/core/error.hpp"
#include "grit/mesh/stl_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    try {
        (void)grit::mesh::parse_stl(std::string(reinterpret_cast<const char*>(data), size), "fuzz.stl");
    } catch (const grit::core::InputError&) {
    }
    return 0;
}
