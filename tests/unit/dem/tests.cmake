# grit::dem unit tests, relative to tests/ (included from tests/CMakeLists.txt).
set(GRIT_DEM_TEST_SOURCES
  unit/dem/test_contact_laws.cpp
  unit/dem/test_grain_neighbors.cpp
  unit/dem/test_dem_system.cpp
  unit/dem/test_head_on_pair.cpp
  unit/dem/test_grain_particle_contact.cpp
)
