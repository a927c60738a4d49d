# grit::material unit tests, relative to tests/ (included from tests/CMakeLists.txt).
set(GRIT_MATERIAL_TEST_SOURCES
  unit/material/test_johnson_cook.cpp
  unit/material/test_johnson_holmquist.cpp
)
