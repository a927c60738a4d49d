// Reading STL files (ASCII and binary) into a triangle soup. STL is three vertices per facet and an
// unreliable normal, nothing else, so a small reader is all it takes (Debian's mesh libraries, e.g.
// Assimp or CGAL, would bring far more than this and weld vertices behind our back); the mesh checks a
// user needs (open edges, degenerate triangles) are TriangleMesh's.
#pragma once

#include <array>
#include <filesystem>
#include <string>
#include <vector>

#include "grit/core/vec.hpp"

namespace grit::mesh {

/// One facet's three corners as written in the file (the file's normal is ignored: the corners'
/// order gives it).
using Facet = std::array<core::Vec<3>, 3>;

/// The facets of an STL file. Binary when the size is 84 + 50 n bytes for the n of its header, else
/// ASCII ("solid ... facet normal ... outer loop vertex x y z (3x) endloop endfacet ... endsolid"; several
/// solids are read one after the other). Throws core::InputError naming the file and the problem: missing,
/// unreadable, neither form, a bad number (with its line), a loop without three vertices, no facet, a
/// coordinate that is not finite.
std::vector<Facet> read_stl(const std::filesystem::path& file);

/// The same for a file's bytes already in memory (`file` names it in messages): what read_stl does once
/// it has read the file, and what the STL reader's fuzz target calls.
std::vector<Facet> parse_stl(const std::string& bytes, const std::filesystem::path& file);

/// Writes `facets` as a binary STL (normals from the corners' order); for tests and generated meshes.
void write_stl(const std::filesystem::path& file, const std::vector<Facet>& facets);

}  // namespace grit::mesh
