// STL reading: ASCII and binary forms, and the messages for files that are not STL.
#include <gtest/gtest.h>

#include <fstream>

#include "grit/core/error.hpp"
#include "grit/mesh/stl_file.hpp"
#include "unit/mesh/test_support.hpp"

using namespace grit::mesh;
using namespace grit::mesh::testing;

namespace {

void write_text(const std::filesystem::path& file, const std::string& text) {
    std::ofstream(file) << text;
}

std::string error_of(const std::filesystem::path& file) {
    try {
        read_stl(file);
    } catch (const grit::core::InputError& e) {
        return e.what();
    }
    return "";
}

}  // namespace

TEST(StlFile, ReadsAsciiFacets) {
    const auto dir = scratch("ascii");
    write_text(
        dir / "t.stl",
        "solid one\n facet normal 0 0 1\n  outer loop\n   vertex 0 0 0\n   vertex 1 0 0\n   vertex 0 1.5e-1 0\n"
        "  endloop\n endfacet\nendsolid one\nsolid two\nfacet normal 0 0 0\nouter loop\nvertex 1 1 1\nvertex 2 1 1\n"
        "vertex 1 2 1\nendloop\nendfacet\nendsolid\n");
    const auto f = read_stl(dir / "t.stl");
    ASSERT_EQ(f.size(), 2u);
    EXPECT_DOUBLE_EQ(f[0][2][1], 0.15);
    EXPECT_DOUBLE_EQ(f[1][1][0], 2.0);
}

// A binary file whose 80-byte header begins with "solid" (many exporters write that) is still binary.
TEST(StlFile, BinaryRoundTripEvenWithSolidInTheHeader) {
    const auto dir = scratch("binary");
    const auto facets = box_facets(V{{0, 0, 0}}, V{{1, 2, 3}});
    write_stl(dir / "b.stl", facets);
    auto back = read_stl(dir / "b.stl");
    ASSERT_EQ(back.size(), facets.size());
    for (std::size_t t = 0; t < facets.size(); ++t)
        for (std::size_t c = 0; c < 3; ++c)
            for (int k = 0; k < 3; ++k)
                EXPECT_EQ(back[t][c][k], facets[t][c][k]);
    std::fstream patch(dir / "b.stl", std::ios::in | std::ios::out | std::ios::binary);
    patch.write("solid box", 9);
    patch.close();
    EXPECT_EQ(read_stl(dir / "b.stl").size(), facets.size());
}

TEST(StlFile, ErrorsNameTheFileAndTheProblem) {
    const auto dir = scratch("errors");
    EXPECT_NE(error_of(dir / "missing.stl").find("no such file"), std::string::npos);
    write_text(dir / "empty.stl", "");
    EXPECT_NE(error_of(dir / "empty.stl").find("empty"), std::string::npos);
    write_text(dir / "junk.stl", "this is not a mesh at all, it is a sentence of text");
    EXPECT_NE(error_of(dir / "junk.stl").find("neither an ASCII STL"), std::string::npos);
    write_text(dir / "number.stl", "solid s\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 x 0\n");
    const std::string bad = error_of(dir / "number.stl");
    EXPECT_NE(bad.find("line 5"), std::string::npos) << bad;
    EXPECT_NE(bad.find("'x'"), std::string::npos) << bad;
    EXPECT_NE(bad.find("number.stl"), std::string::npos) << bad;
    write_text(dir / "two.stl",
               "solid s\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nendloop\nendfacet\n");
    EXPECT_NE(error_of(dir / "two.stl").find("2 vertices"), std::string::npos);
    write_text(dir / "none.stl", "solid s\nendsolid s\n");
    EXPECT_NE(error_of(dir / "none.stl").find("no facet"), std::string::npos);
    std::filesystem::create_directories(dir / "folder.stl");
    EXPECT_NE(error_of(dir / "folder.stl").find("not a regular file"), std::string::npos);
}

// A file cut short anywhere is refused, never read in part: an ASCII file without its endsolid, one cut
// inside a facet, and a binary file shorter (or longer) than its triangle count says.
TEST(StlFile, FileCutShortIsRefusedWithWhereItEnds) {
    const auto dir = scratch("cut");
    const std::string facet = "facet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\nendloop\nendfacet\n";
    write_text(dir / "whole.stl", "solid s\n" + facet + facet + "endsolid s\n");
    EXPECT_EQ(read_stl(dir / "whole.stl").size(), 2u);
    write_text(dir / "no_end.stl", "solid s\n" + facet + facet);
    EXPECT_NE(error_of(dir / "no_end.stl").find("without the 'endsolid' of the solid opened at line 1"), std::string::npos)
        << error_of(dir / "no_end.stl");
    write_text(dir / "in_facet.stl", "solid s\n" + facet + "facet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\nendloop\n");
    EXPECT_NE(error_of(dir / "in_facet.stl").find("ends inside the facet opened at line 9"), std::string::npos)
        << error_of(dir / "in_facet.stl");
    write_text(dir / "no_endfacet.stl", "solid s\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\nendloop\nfacet normal 0 0 1\n");
    EXPECT_NE(error_of(dir / "no_endfacet.stl").find("line 8: 'facet' out of place"), std::string::npos)
        << error_of(dir / "no_endfacet.stl");
    const auto facets = box_facets(V{{0, 0, 0}}, V{{1, 2, 3}});
    write_stl(dir / "b.stl", facets);
    const auto size = std::filesystem::file_size(dir / "b.stl");
    for (const auto cut : {size - 1, size - 50, std::uintmax_t{100}}) {
        std::filesystem::copy_file(dir / "b.stl", dir / "cut.stl", std::filesystem::copy_options::overwrite_existing);
        std::filesystem::resize_file(dir / "cut.stl", cut);
        const std::string e = error_of(dir / "cut.stl");
        EXPECT_NE(e.find("cut short"), std::string::npos) << cut << ": " << e;
    }
    std::filesystem::resize_file(dir / "b.stl", size + 10);
    EXPECT_NE(error_of(dir / "b.stl").find("bytes after the last facet"), std::string::npos) << error_of(dir / "b.stl");
}
