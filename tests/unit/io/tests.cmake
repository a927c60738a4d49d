# grit::io unit tests, relative to tests/ (included from tests/CMakeLists.txt).
# tests/unit/io/check_vtu_with_vtk.py is a separate checker run with /usr/bin/python3 (python3-vtk9).
set(GRIT_IO_TEST_SOURCES
  unit/io/test_vtu_writer.cpp
  unit/io/test_jet_builder.cpp
)
