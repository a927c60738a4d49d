// `grit crater`: the crater measures of every output, from crater_history.csv.
#include "crater_measures.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "grit/analysis/crater.hpp"
#include "grit/core/error.hpp"

namespace grit::app {

namespace fs = std::filesystem;

namespace {

struct Row {
    std::vector<double> values;  // x, surface (2D) or x, y, surface (3D)
    std::string time;            // as written, so that one output's rows group exactly
};

std::vector<Row> read_history(const fs::path& path, int dimension) {
    std::ifstream in(path);
    if (!in) throw core::InputError(fmt::format("{}: cannot be read (the run has no [crater], or it was not written)", path.string()));
    std::string line;
    std::getline(in, line);
    const std::string expected = dimension == 2 ? "x,surface,time" : "x,y,surface,time";
    if (line != expected)
        throw core::InputError(fmt::format("{}: header '{}', expected '{}' for a {}D run", path.string(), line, expected, dimension));
    std::vector<Row> rows;
    long number = 1;
    while (std::getline(in, line)) {
        ++number;
        if (line.empty()) continue;
        Row row;
        std::stringstream fields(line);
        std::string field;
        std::vector<std::string> parts;
        while (std::getline(fields, field, ',')) parts.push_back(field);
        if (parts.size() != static_cast<std::size_t>(dimension) + 1)
            throw core::InputError(fmt::format("{}: line {} has {} fields, expected {}", path.string(), number, parts.size(), dimension + 1));
        for (std::size_t k = 0; k + 1 < parts.size(); ++k) {
            char* end = nullptr;
            row.values.push_back(std::strtod(parts[k].c_str(), &end));
            if (end == parts[k].c_str())
                throw core::InputError(fmt::format("{}: line {}: '{}' is not a number", path.string(), number, parts[k]));
        }
        row.time = parts.back();
        rows.push_back(std::move(row));
    }
    return rows;
}

double number_in(const nlohmann::json& j, const char* key, const fs::path& path) {
    if (!j.contains(key) || !j[key].is_number())
        throw core::InputError(fmt::format("{}: no number '{}' (the run has no [crater]?)", path.string(), key));
    return j[key].get<double>();
}

}  // namespace

int measure_crater_history(const fs::path& folder) {
    const fs::path summary_path = folder / "summary.json";
    std::ifstream summary_in(summary_path);
    if (!summary_in) throw core::InputError(fmt::format("{}: cannot be read (not a run folder?)", summary_path.string()));
    nlohmann::json summary;
    try {
        summary = nlohmann::json::parse(summary_in);
    } catch (const nlohmann::json::exception& e) {
        throw core::InputError(fmt::format("{}: not valid JSON ({})", summary_path.string(), e.what()));
    }
    if (!summary.contains("crater_region"))
        throw core::InputError(fmt::format("{}: no crater_region: the run had no [crater]", summary_path.string()));
    const auto& region = summary["crater_region"];
    const double spacing = number_in(summary, "particle_spacing", summary_path);
    const double surface = number_in(region, "surface", summary_path);
    const int dimension = static_cast<int>(number_in(summary, "dimension", summary_path));

    const auto rows = read_history(folder / "crater_history.csv", dimension);
    std::string out = dimension == 2 ? "time,crater_depth,crater_width,crater_rim_width,crater_lip_height,crater_area,crater_shape_factor\n"
                                     : "time,crater_depth,crater_width,crater_rim_width,crater_lip_height,crater_area,crater_shape_factor,crater_length\n";
    int outputs = 0;
    for (std::size_t first = 0; first < rows.size();) {
        std::size_t last = first;
        while (last < rows.size() && rows[last].time == rows[first].time) ++last;
        if (dimension == 2) {
            analysis::CraterProfile p;
            for (std::size_t r = first; r < last; ++r) {
                p.x.push_back(rows[r].values[0]);
                p.surface.push_back(rows[r].values[1]);
            }
            analysis::measure_profile(p, surface, spacing);
            out += fmt::format("{},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g}\n", rows[first].time, p.depth, p.width,
                               p.rim_width, p.lip_height, p.area, p.shape_factor);
        } else {
            // The map's rows run over x fastest, then y (crater module's write_output).
            analysis::CraterMap m;
            for (std::size_t r = first; r < last && (m.x.empty() || rows[r].values[0] > m.x.back()); ++r)
                m.x.push_back(rows[r].values[0]);
            for (std::size_t r = first; r < last; r += m.x.size()) m.y.push_back(rows[r].values[1]);
            if (m.x.size() * m.y.size() != last - first)
                throw core::InputError(fmt::format("{}: the map at time {} is not {} x {} cells", (folder / "crater_history.csv").string(),
                                                   rows[first].time, m.x.size(), m.y.size()));
            for (std::size_t r = first; r < last; ++r) m.surface.push_back(rows[r].values[2]);
            analysis::measure_map(m, surface, spacing);
            out += fmt::format("{},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g}\n", rows[first].time, m.depth, m.width,
                               m.rim_width, m.lip_height, m.area, m.shape_factor, m.length);
        }
        ++outputs;
        first = last;
    }
    std::ofstream(folder / "crater_measures.csv") << out;
    return outputs;
}

}  // namespace grit::app
