# grit::analysis unit tests, relative to tests/ (included from tests/CMakeLists.txt).
set(GRIT_ANALYSIS_TEST_SOURCES
  unit/analysis/test_crater.cpp
  unit/analysis/test_cracks.cpp
  unit/analysis/test_fluid_in_solid.cpp
  unit/analysis/test_erosion_log.cpp
  unit/analysis/test_split_analyses.cpp
)
