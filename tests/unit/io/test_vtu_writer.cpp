// Unit tests of the io writers: VTU bytes read back exactly, PVD and CSV text.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include <unistd.h>

#include "grit/io/point_data.hpp"
#include "grit/io/pvd_writer.hpp"
#include "grit/io/series_writer.hpp"
#include "grit/io/vtu_writer.hpp"

namespace {

namespace fs = std::filesystem;
using grit::io::PointArray;
using grit::io::PointCloud;

/// A fresh directory per test, removed afterwards.
class IoWriterTest : public ::testing::Test {
protected:
    void SetUp() override {
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        dir_ = fs::temp_directory_path() /
               (std::string("grit_io_") + info->test_suite_name() + "_" + info->name() + "_" +
                std::to_string(::getpid()));
        fs::remove_all(dir_);
        fs::create_directories(dir_);
    }
    void TearDown() override {
        std::error_code ec;
        fs::remove_all(dir_, ec);
    }
    fs::path dir_;
};

std::string read_all(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::vector<std::string> dir_entries(const fs::path& dir) {
    std::vector<std::string> names;
    for (const auto& e : fs::directory_iterator(dir)) {
        names.push_back(e.path().filename().string());
    }
    return names;
}

/// The opening tag `<name ...>` of the first such element in `xml` (empty if absent).
std::string element(const std::string& xml, const std::string& name) {
    const auto start = xml.find("<" + name + " ");
    EXPECT_NE(start, std::string::npos) << name;
    if (start == std::string::npos) return {};
    return xml.substr(start, xml.find('>', start) + 1 - start);
}

/// The value of attribute `name` in one tag (fails the test and returns "0" if absent).
std::string attribute(const std::string& tag, const std::string& name) {
    const std::string key = " " + name + "=\"";
    const auto start = tag.find(key);
    EXPECT_NE(start, std::string::npos) << name << " in " << tag;
    if (start == std::string::npos) return "0";
    const auto value = start + key.size();
    return tag.substr(value, tag.find('"', value) - value);
}

/// One appended DataArray as parsed back from the file.
struct ParsedArray {
    std::string type;
    int components = 0;
    std::uint64_t offset = 0;
    std::string payload;  ///< the raw bytes after the UInt64 byte count
};

/// Parses a VTU written by write_vtu: the DataArray tags and their appended payloads.
/// Checks that the blocks tile the appended section exactly (count headers match sizes).
struct ParsedVtu {
    std::string xml;  ///< everything before the appended bytes
    std::map<std::string, ParsedArray> arrays;
    std::uint64_t number_of_points = 0;
    std::uint64_t number_of_cells = 0;

    explicit ParsedVtu(const std::string& text) {
        const std::string marker = "<AppendedData encoding=\"raw\">";
        const auto at = text.find(marker);
        EXPECT_NE(at, std::string::npos);
        if (at == std::string::npos) return;
        const auto underscore = text.find('_', at + marker.size());
        EXPECT_NE(underscore, std::string::npos);
        if (underscore == std::string::npos) return;
        // Only whitespace between the tag and the '_'.
        for (auto i = at + marker.size(); i < underscore; ++i) {
            EXPECT_TRUE(text[i] == ' ' || text[i] == '\n') << "byte " << i;
        }
        xml = text.substr(0, underscore);
        const std::size_t base = underscore + 1;

        const std::string piece = element(xml, "Piece");
        number_of_points = std::stoull(attribute(piece, "NumberOfPoints"));
        number_of_cells = std::stoull(attribute(piece, "NumberOfCells"));

        std::vector<std::uint64_t> offsets;
        for (std::size_t from = 0;;) {
            const auto start = xml.find("<DataArray ", from);
            if (start == std::string::npos) break;
            const auto end = xml.find("/>", start);
            EXPECT_NE(end, std::string::npos);
            if (end == std::string::npos) break;
            const std::string tag = xml.substr(start, end + 2 - start);
            from = end;
            EXPECT_EQ(attribute(tag, "format"), "appended") << tag;
            ParsedArray a;
            a.type = attribute(tag, "type");
            a.components = std::stoi(attribute(tag, "NumberOfComponents"));
            a.offset = std::stoull(attribute(tag, "offset"));
            const std::string name = attribute(tag, "Name");
            std::uint64_t count = 0;
            EXPECT_LE(base + a.offset + sizeof count, text.size()) << name;
            if (base + a.offset + sizeof count > text.size()) continue;
            std::memcpy(&count, text.data() + base + a.offset, sizeof count);
            EXPECT_LE(base + a.offset + sizeof count + count, text.size()) << name;
            if (base + a.offset + sizeof count + count > text.size()) continue;
            a.payload = text.substr(base + a.offset + sizeof count, count);
            offsets.push_back(a.offset);
            EXPECT_TRUE(arrays.emplace(name, a).second) << "duplicate " << name;
        }

        // The blocks must tile the appended section with no gaps or overlaps, and the
        // section must end with the closing tags.
        std::sort(offsets.begin(), offsets.end());
        std::uint64_t expected = 0;
        for (const std::uint64_t off : offsets) {
            EXPECT_EQ(off, expected);
            for (const auto& [name, a] : arrays) {
                if (a.offset == off) expected = off + 8 + a.payload.size();
            }
        }
        EXPECT_EQ(text.substr(base + expected), "\n  </AppendedData>\n</VTKFile>\n");
    }

    template <class T>
    std::vector<T> values(const std::string& name) const {
        const auto it = arrays.find(name);
        EXPECT_NE(it, arrays.end()) << name;
        if (it == arrays.end()) return {};
        EXPECT_EQ(it->second.payload.size() % sizeof(T), 0U) << name;
        std::vector<T> out(it->second.payload.size() / sizeof(T));
        if (!out.empty()) std::memcpy(out.data(), it->second.payload.data(), it->second.payload.size());
        return out;
    }
};

/// Bitwise equality, so -0.0 and NaN payloads are compared exactly too.
void expect_same_bits(const std::vector<double>& actual, const std::vector<double>& expected,
                      const std::string& what) {
    ASSERT_EQ(actual.size(), expected.size()) << what;
    EXPECT_EQ(std::memcmp(actual.data(), expected.data(), expected.size() * sizeof(double)), 0)
        << what;
}

PointCloud sample_cloud() {
    PointCloud c;
    c.points = {0.0, 0.0, 0.0,  0.1, 0.2, 0.0,  -1.5, 2.25, 0.0,
                1e-300, -0.0, 3.0,  1.0 / 3.0, 2.0 / 3.0, 0.0};
    PointArray density = PointArray::reals("density", 1, {1000.0, 999.5, 1000.0 / 7.0, 0.0, -1.0});
    PointArray velocity = PointArray::reals("velocity", 3);
    for (int i = 0; i < 15; ++i) velocity.real.push_back(0.01 * i - 0.07);
    PointArray phase = PointArray::integers("phase", 1, {0, 1, 2, 3, -7});
    c.arrays = {density, velocity, phase};
    return c;
}

TEST_F(IoWriterTest, VtuHeaderNamesAndExactValues) {
    const PointCloud c = sample_cloud();
    const fs::path file = dir_ / "frame.vtu";
    grit::io::write_vtu(file, c);

    const std::string text = read_all(file);
    const std::string header = "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" "
                               "version=\"1.0\" byte_order=\"LittleEndian\" "
                               "header_type=\"UInt64\">";
    EXPECT_EQ(text.rfind(header, 0), 0U) << text.substr(0, 200);
    EXPECT_NE(text.find("Name=\"density\""), std::string::npos);
    EXPECT_NE(text.find("Name=\"velocity\""), std::string::npos);
    EXPECT_NE(text.find("Name=\"phase\""), std::string::npos);

    const ParsedVtu v(text);
    EXPECT_EQ(v.number_of_points, 5U);
    EXPECT_EQ(v.number_of_cells, 5U);
    ASSERT_EQ(v.arrays.size(), 7U);  // Points, 3 cell arrays, 3 point-data arrays

    EXPECT_EQ(v.arrays.at("Points").type, "Float64");
    EXPECT_EQ(v.arrays.at("Points").components, 3);
    expect_same_bits(v.values<double>("Points"), c.points, "Points");

    EXPECT_EQ(v.arrays.at("connectivity").type, "Int64");
    EXPECT_EQ(v.arrays.at("offsets").type, "Int64");
    EXPECT_EQ(v.arrays.at("types").type, "UInt8");
    EXPECT_EQ(v.values<std::int64_t>("connectivity"), (std::vector<std::int64_t>{0, 1, 2, 3, 4}));
    EXPECT_EQ(v.values<std::int64_t>("offsets"), (std::vector<std::int64_t>{1, 2, 3, 4, 5}));
    EXPECT_EQ(v.values<std::uint8_t>("types"), (std::vector<std::uint8_t>(5, 1)));

    EXPECT_EQ(v.arrays.at("density").type, "Float64");
    EXPECT_EQ(v.arrays.at("density").components, 1);
    expect_same_bits(v.values<double>("density"), c.arrays[0].real, "density");
    EXPECT_EQ(v.arrays.at("velocity").type, "Float64");
    EXPECT_EQ(v.arrays.at("velocity").components, 3);
    expect_same_bits(v.values<double>("velocity"), c.arrays[1].real, "velocity");
    EXPECT_EQ(v.arrays.at("phase").type, "Int32");
    EXPECT_EQ(v.arrays.at("phase").components, 1);
    EXPECT_EQ(v.values<std::int32_t>("phase"), c.arrays[2].integer);

    // Arrays sit inside <PointData>, the coordinates inside <Points>, cells inside <Cells>.
    const auto pd = v.xml.find("<PointData>");
    const auto pd_end = v.xml.find("</PointData>");
    ASSERT_NE(pd, std::string::npos);
    ASSERT_NE(pd_end, std::string::npos);
    for (const char* name : {"density", "velocity", "phase"}) {
        const auto at = v.xml.find(std::string("Name=\"") + name + "\"");
        EXPECT_GT(at, pd);
        EXPECT_LT(at, pd_end);
    }
    EXPECT_NE(v.xml.find("<Cells>"), std::string::npos);
    EXPECT_NE(v.xml.find("<Points>"), std::string::npos);

    // Written through a temporary file that is gone afterwards.
    EXPECT_EQ(dir_entries(dir_), std::vector<std::string>{"frame.vtu"});
}

TEST_F(IoWriterTest, VtuEmptyCloud) {
    PointCloud c;
    c.arrays = {PointArray::reals("density", 1), PointArray::reals("velocity", 3), PointArray::integers("phase", 1)};
    const fs::path file = dir_ / "empty.vtu";
    grit::io::write_vtu(file, c);

    const ParsedVtu v(read_all(file));
    EXPECT_EQ(v.number_of_points, 0U);
    EXPECT_EQ(v.number_of_cells, 0U);
    ASSERT_EQ(v.arrays.size(), 7U);
    for (const auto& [name, a] : v.arrays) {
        EXPECT_TRUE(a.payload.empty()) << name;
    }
}

TEST_F(IoWriterTest, VtuOverwritesExistingFile) {
    const fs::path file = dir_ / "frame.vtu";
    grit::io::write_vtu(file, sample_cloud());
    PointCloud small;
    small.points = {1.0, 2.0, 3.0};
    grit::io::write_vtu(file, small);
    const ParsedVtu v(read_all(file));
    EXPECT_EQ(v.number_of_points, 1U);
    expect_same_bits(v.values<double>("Points"), small.points, "Points");
    EXPECT_EQ(v.arrays.count("density"), 0U);
    EXPECT_EQ(dir_entries(dir_), std::vector<std::string>{"frame.vtu"});
}

TEST_F(IoWriterTest, VtuEscapesArrayNames) {
    PointCloud c;
    c.points = {0.0, 0.0, 0.0};
    c.arrays = {PointArray::reals("a<b>&\"c\"", 1, {2.0})};
    const fs::path file = dir_ / "frame.vtu";
    grit::io::write_vtu(file, c);
    EXPECT_NE(read_all(file).find("Name=\"a&lt;b&gt;&amp;&quot;c&quot;\""), std::string::npos);
}

TEST_F(IoWriterTest, VtuRejectsInconsistentSizes) {
    const fs::path file = dir_ / "bad.vtu";
    PointCloud c = sample_cloud();
    c.arrays[1].real.pop_back();
    EXPECT_THROW(grit::io::write_vtu(file, c), std::invalid_argument);
    c = sample_cloud();
    c.arrays[2].integer.push_back(1);
    EXPECT_THROW(grit::io::write_vtu(file, c), std::invalid_argument);
    c = sample_cloud();
    c.points.push_back(1.0);
    EXPECT_THROW(grit::io::write_vtu(file, c), std::invalid_argument);
    c = sample_cloud();
    c.arrays[0].components = 0;
    EXPECT_THROW(grit::io::write_vtu(file, c), std::invalid_argument);
    EXPECT_TRUE(dir_entries(dir_).empty());
}

TEST_F(IoWriterTest, VtuIoFailureNamesPath) {
    const fs::path file = dir_ / "no_such_dir" / "frame.vtu";
    try {
        grit::io::write_vtu(file, sample_cloud());
        FAIL() << "expected std::runtime_error";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find(file.string()), std::string::npos) << e.what();
    }
}

TEST_F(IoWriterTest, AtomicWriteRemovesTemporaryOnException) {
    const fs::path file = dir_ / "out.txt";
    EXPECT_THROW(grit::io::write_file_atomically(file,
                                                 [](std::ostream& out) {
                                                     out << "partial";
                                                     throw std::runtime_error("boom");
                                                 }),
                 std::runtime_error);
    EXPECT_TRUE(dir_entries(dir_).empty());
}

TEST_F(IoWriterTest, PvdText) {
    const fs::path file = dir_ / "run.pvd";
    grit::io::PvdWriter pvd(file);
    EXPECT_FALSE(fs::exists(file));

    pvd.add(0.0, "frames/frame_000000.vtu");
    EXPECT_EQ(read_all(file),
              "<?xml version=\"1.0\"?>\n"
              "<VTKFile type=\"Collection\" version=\"1.0\" byte_order=\"LittleEndian\">\n"
              "  <Collection>\n"
              "    <DataSet timestep=\"0\" group=\"\" part=\"0\" file=\"frames/frame_000000.vtu\"/>\n"
              "  </Collection>\n"
              "</VTKFile>\n");

    pvd.add(0.1, "frames/frame_000001.vtu");
    pvd.add(1.0 / 3.0, "frames/a&b.vtu");
    EXPECT_EQ(read_all(file),
              "<?xml version=\"1.0\"?>\n"
              "<VTKFile type=\"Collection\" version=\"1.0\" byte_order=\"LittleEndian\">\n"
              "  <Collection>\n"
              "    <DataSet timestep=\"0\" group=\"\" part=\"0\" file=\"frames/frame_000000.vtu\"/>\n"
              "    <DataSet timestep=\"0.10000000000000001\" group=\"\" part=\"0\" file=\"frames/frame_000001.vtu\"/>\n"
              "    <DataSet timestep=\"0.33333333333333331\" group=\"\" part=\"0\" file=\"frames/a&amp;b.vtu\"/>\n"
              "  </Collection>\n"
              "</VTKFile>\n");
    ASSERT_EQ(pvd.entries().size(), 3U);
    EXPECT_EQ(pvd.entries()[1].time, 0.1);
    EXPECT_EQ(dir_entries(dir_), std::vector<std::string>{"run.pvd"});

    EXPECT_THROW(pvd.add(std::numeric_limits<double>::quiet_NaN(), "x.vtu"), std::invalid_argument);
    EXPECT_THROW(pvd.add(2.0, ""), std::invalid_argument);
    EXPECT_EQ(pvd.entries().size(), 3U);
}

TEST_F(IoWriterTest, PvdIoFailureNamesPathAndDropsEntry) {
    const fs::path file = dir_ / "missing" / "run.pvd";
    grit::io::PvdWriter pvd(file);
    try {
        pvd.add(0.0, "a.vtu");
        FAIL() << "expected std::runtime_error";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find(file.string()), std::string::npos) << e.what();
    }
    EXPECT_TRUE(pvd.entries().empty());
}

TEST_F(IoWriterTest, SeriesText) {
    const fs::path file = dir_ / "series.csv";
    grit::io::SeriesWriter s(file, {"time", "kinetic_energy", "mass"});
    EXPECT_EQ(read_all(file), "time,kinetic_energy,mass\n");  // header flushed at once

    s.write_row({0.0, 1.0 / 3.0, 1000.0});
    EXPECT_EQ(read_all(file), "time,kinetic_energy,mass\n0,0.3333333333,1000\n");  // flushed

    s.write_row({1e-5, 1e20, -2.5});
    EXPECT_EQ(read_all(file),
              "time,kinetic_energy,mass\n0,0.3333333333,1000\n1e-05,1e+20,-2.5\n");

    EXPECT_THROW(s.write_row({1.0, 2.0}), std::logic_error);
    EXPECT_THROW(s.write_row({1.0, 2.0, 3.0, 4.0}), std::logic_error);
    EXPECT_EQ(read_all(file),
              "time,kinetic_energy,mass\n0,0.3333333333,1000\n1e-05,1e+20,-2.5\n");
}

TEST_F(IoWriterTest, SeriesQuotesAwkwardColumnNames) {
    const fs::path file = dir_ / "series.csv";
    grit::io::SeriesWriter s(file, {"t", "a,b", "say \"hi\""});
    EXPECT_EQ(read_all(file), "t,\"a,b\",\"say \"\"hi\"\"\"\n");
}

TEST_F(IoWriterTest, SeriesContinuedByANewerRunGainsItsColumns) {
    // A series written before a column was added (an older grit) is continued with that column as nan.
    const fs::path file = dir_ / "series.csv";
    {
        std::ofstream out(file);
        out << "time,mass\n0,1\n1,2\n2,3\n";
    }
    grit::io::SeriesWriter s(file, {"time", "depth", "mass", "width"}, 2);
    EXPECT_EQ(s.added_columns(), (std::vector<std::string>{"depth", "width"}));
    s.write_row({2.0, 0.5, 3.5, 0.25});
    EXPECT_EQ(read_all(file), "time,depth,mass,width\n0,nan,1,nan\n1,nan,2,nan\n2,0.5,3.5,0.25\n");

    // A matching header is kept as it is.
    grit::io::SeriesWriter same(file, {"time", "depth", "mass", "width"}, 3);
    EXPECT_TRUE(same.added_columns().empty());

    // A column the run no longer writes would be lost: refused, naming the file.
    try {
        grit::io::SeriesWriter fewer(file, {"time", "mass", "width"}, 3);
        FAIL() << "expected std::runtime_error";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find(file.string()), std::string::npos) << e.what();
    }
}

TEST_F(IoWriterTest, SeriesIoFailureNamesPath) {
    const fs::path file = dir_ / "missing" / "series.csv";
    try {
        grit::io::SeriesWriter s(file, {"t"});
        FAIL() << "expected std::runtime_error";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find(file.string()), std::string::npos) << e.what();
    }
    EXPECT_THROW(grit::io::SeriesWriter(dir_ / "x.csv", {}), std::invalid_argument);
}

}  // namespace

// Name lists become String arrays of the grid's field data, in VTK's ascii form: each string's bytes,
// then 0 (the VTK reader's side of this is checked by tests/unit/io/check_vtu_with_vtk.py in the CLI test).
TEST_F(IoWriterTest, VtuNameListsAreFieldDataStrings) {
    PointCloud c = sample_cloud();
    c.names.push_back({"material_names", {"water", "a&b"}});
    const fs::path file = dir_ / "frame.vtu";
    grit::io::write_vtu(file, c);
    const std::string text = read_all(file);
    const auto fd = text.find("<FieldData>");
    ASSERT_NE(fd, std::string::npos);
    EXPECT_LT(fd, text.find("<Piece"));
    EXPECT_NE(text.find("<Array type=\"String\" Name=\"material_names\" NumberOfTuples=\"2\" format=\"ascii\">\n"
                        "        119 97 116 101 114 0 97 38 98 0\n"),
              std::string::npos)
        << text.substr(0, 600);
    const ParsedVtu v(text);  // the appended block is unchanged
    expect_same_bits(v.values<double>("density"), c.arrays[0].real, "density");

    c.names.push_back({"bad", {std::string("a\0b", 3)}});
    EXPECT_THROW(grit::io::write_vtu(file, c), std::invalid_argument);
}
