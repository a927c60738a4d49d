# grit::mesh unit tests, relative to tests/ (included from tests/CMakeLists.txt).
set(GRIT_MESH_TEST_SOURCES
  unit/mesh/test_stl_file.cpp
  unit/mesh/test_triangle_mesh.cpp
  unit/mesh/test_closest_point.cpp
  unit/mesh/test_signed_distance.cpp
  unit/mesh/test_mirror_partners.cpp
  unit/mesh/test_mesh_walls.cpp
  unit/wear/test_wear_models.cpp
  unit/wear/test_impact_log.cpp
)
