// Mesh topology and checks: welding, open and flat edges, degenerate and non-manifold facets, placement.
#include <gtest/gtest.h>

#include <numbers>

#include "grit/core/error.hpp"
#include "grit/mesh/triangle_mesh.hpp"
#include "unit/mesh/test_support.hpp"

using namespace grit::mesh;
using namespace grit::mesh::testing;

namespace {

std::string error_of(const std::vector<Facet>& f, bool watertight) {
    try {
        TriangleMesh::from_facets(f, {}, "test.stl", watertight);
    } catch (const grit::core::InputError& e) {
        return e.what();
    }
    return "";
}

}  // namespace

// A box: 8 vertices, 18 edges (12 sharp, 6 face diagonals inside flat squares), closed.
TEST(TriangleMesh, BoxTopology) {
    const auto m = TriangleMesh::from_facets(box_facets(V{{0, 0, 0}}, V{{1, 1, 1}}), {}, "box.stl", true);
    EXPECT_EQ(m.vertex_count(), 8u);
    EXPECT_EQ(m.triangle_count(), 12u);
    EXPECT_EQ(m.edge_count(), 18u);
    EXPECT_EQ(m.open_edge_count(), 0u);
    int active = 0;
    for (std::size_t e = 0; e < m.edge_count(); ++e)
        active += m.edge_active(e);
    EXPECT_EQ(active, 12);
    for (std::size_t v = 0; v < m.vertex_count(); ++v)
        EXPECT_TRUE(m.vertex_active(v));
    double area = 0.0;
    for (std::size_t t = 0; t < m.triangle_count(); ++t)
        area += m.area(t);
    EXPECT_NEAR(area, 6.0, 1e-12);
    EXPECT_NEAR(m.normal(0)[2], -1.0, 1e-12);  // the z = 0 face points out of the box
}

// A plate of 4 x 4 squares: the inner edges and vertices are flat, the rim is open.
TEST(TriangleMesh, PlateInteriorIsFlatAndRimIsOpen) {
    const auto m = TriangleMesh::from_facets(plate_facets(1.0, 4), {}, "plate.stl", false);
    EXPECT_EQ(m.open_edge_count(), 16u);
    std::size_t active = 0;
    for (std::size_t e = 0; e < m.edge_count(); ++e)
        active += m.edge_active(e);
    EXPECT_EQ(active, 16u);  // exactly the rim
    std::size_t active_vertices = 0;
    for (std::size_t v = 0; v < m.vertex_count(); ++v)
        active_vertices += m.vertex_active(v);
    EXPECT_EQ(active_vertices, 16u);  // the 16 rim vertices of the 5 x 5 grid
    const std::string why = error_of(plate_facets(1.0, 4), true);
    EXPECT_NE(why.find("16 open edges"), std::string::npos) << why;
    EXPECT_NE(why.find("test.stl"), std::string::npos) << why;
}

TEST(TriangleMesh, DegenerateAndNonManifoldFacetsAreErrors) {
    auto f = plate_facets(1.0, 1);
    f.push_back({V{{0, 0, 0}}, V{{1, 1, 0}}, V{{2, 2, 0}}});  // collinear corners
    const std::string degenerate = error_of(f, false);
    EXPECT_NE(degenerate.find("facet 3 is degenerate"), std::string::npos) << degenerate;

    auto g = plate_facets(1.0, 1);  // the diagonal (-1,-1)-(1,1) gets a third facet
    g.push_back({V{{-1, -1, 0}}, V{{1, 1, 0}}, V{{0, 0, 1}}});
    const std::string fin = error_of(g, false);
    EXPECT_NE(fin.find("more than two facets"), std::string::npos) << fin;
    EXPECT_NE(fin.find("not manifold"), std::string::npos) << fin;
}

// x = translate + R_z R_y R_x (scale x_file).
TEST(TriangleMesh, PlacementScalesRotatesAndTranslates) {
    Placement p;
    p.scale = 2.0;
    p.rotate = V{{0.0, 0.0, 90.0}};
    p.translate = V{{1.0, 0.0, 0.0}};
    const V x = p.apply(V{{1.0, 0.0, 0.5}});
    EXPECT_NEAR(x[0], 1.0, 1e-12);
    EXPECT_NEAR(x[1], 2.0, 1e-12);
    EXPECT_NEAR(x[2], 1.0, 1e-12);
    Placement q;
    q.rotate = V{{90.0, 0.0, 0.0}};  // y onto z
    const V y = q.apply(V{{0.0, 1.0, 0.0}});
    EXPECT_NEAR(y[2], 1.0, 1e-12);
}
