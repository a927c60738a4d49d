// Small meshes for the mesh tests: boxes and plates as facets, and a scratch folder.
#pragma once

#include <filesystem>
#include <vector>

#include "grit/mesh/stl_file.hpp"

namespace grit::mesh::testing {

using V = core::Vec<3>;

/// The 12 facets of the box [lo, hi], normals outwards.
inline std::vector<Facet> box_facets(const V& lo, const V& hi) {
    auto p = [&](int i, int j, int k) { return V{{i ? hi[0] : lo[0], j ? hi[1] : lo[1], k ? hi[2] : lo[2]}}; };
    std::vector<Facet> f;
    auto quad = [&](V a, V b, V c, V d) {  // counter-clockwise seen from outside
        f.push_back({a, b, c});
        f.push_back({a, c, d});
    };
    quad(p(0, 0, 0), p(0, 1, 0), p(1, 1, 0), p(1, 0, 0));  // z = lo
    quad(p(0, 0, 1), p(1, 0, 1), p(1, 1, 1), p(0, 1, 1));  // z = hi
    quad(p(0, 0, 0), p(1, 0, 0), p(1, 0, 1), p(0, 0, 1));  // y = lo
    quad(p(0, 1, 0), p(0, 1, 1), p(1, 1, 1), p(1, 1, 0));  // y = hi
    quad(p(0, 0, 0), p(0, 0, 1), p(0, 1, 1), p(0, 1, 0));  // x = lo
    quad(p(1, 0, 0), p(1, 1, 0), p(1, 1, 1), p(1, 0, 1));  // x = hi
    return f;
}

/// A flat plate z = 0 over [-a, a]^2 split into n x n squares of two triangles each, normal +z.
inline std::vector<Facet> plate_facets(double a, int n) {
    std::vector<Facet> f;
    const double h = 2.0 * a / n;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
            const V p00{{-a + i * h, -a + j * h, 0.0}}, p10{{-a + (i + 1) * h, -a + j * h, 0.0}},
                p11{{-a + (i + 1) * h, -a + (j + 1) * h, 0.0}}, p01{{-a + i * h, -a + (j + 1) * h, 0.0}};
            f.push_back({p00, p10, p11});
            f.push_back({p00, p11, p01});
        }
    return f;
}

/// A fresh scratch folder under the build's temporary directory.
inline std::filesystem::path scratch(const std::string& name) {
    const auto dir = std::filesystem::temp_directory_path() / ("grit_mesh_test_" + name);
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir;
}

}  // namespace grit::mesh::testing
