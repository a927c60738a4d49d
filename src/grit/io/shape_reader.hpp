// Shapes of the case's particle blocks and walls ([[fluid]], [[solid]], [[wall]], boxes of outlets and
// clamps) and the STL meshes placed in them or given to the grains ([[mesh]]).
#pragma once

#include <filesystem>
#include <memory>

#include "grit/io/case_section.hpp"
#include "grit/io/case_spec.hpp"
#include "grit/io/material_tables.hpp"
#include "grit/mesh/triangle_mesh.hpp"

namespace grit::io {

/// An axis-aligned box `min`/`max` (outlets, clamps).
OutletSpec read_box(const Section& s, int dim);

/// An STL file's triangles placed by the section's `scale`, `rotate` and `translate` (relative paths from
/// the case file's folder).
std::shared_ptr<const mesh::TriangleMesh> read_placed_mesh(const Section& s, const std::filesystem::path& folder,
                                                           bool watertight, std::filesystem::path* resolved = nullptr);

/// A block's shape: box, disc/sphere, cylinder (3D), and for walls (`allow_tank`) tank and mesh (3D).
ShapeSpec read_shape(const Section& s, int dim, double dx, bool allow_tank, const std::filesystem::path& folder = {});

/// [[mesh]]: STL walls for grains (3D), their placement, motion and wear model.
void read_meshes(const Section& top, CaseSpec& c, GrainMaterialTable& grain_table);

}  // namespace grit::io
