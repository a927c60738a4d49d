// Martin & Moyce (1952) surge-front data of cases/dambreak_2d/reference (T = t sqrt(2g/L), Z = z/L),
// read by the WCSPH and ISPH dam-break tests.
#pragma once

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace grit::testing {

struct FrontPoint {
    double T, Z;
};

inline std::vector<FrontPoint> martin_moyce() {
    std::ifstream in(std::filesystem::path(GRIT_SOURCE_DIR) / "cases/dambreak_2d/reference/martin_moyce_1952.csv");
    std::vector<FrontPoint> out;
    std::string line;
    while (std::getline(in, line)) {
        if (line.empty() || line[0] == '#' || line[0] == 'c') continue;
        std::stringstream ss(line);
        std::string a, T, Z;
        std::getline(ss, a, ',');
        std::getline(ss, T, ',');
        std::getline(ss, Z, ',');
        out.push_back({std::stod(T), std::stod(Z)});
    }
    return out;
}

}  // namespace grit::testing
