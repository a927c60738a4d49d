# grit::io sources, relative to src/grit (included from src/grit/CMakeLists.txt).
set(GRIT_IO_SOURCES
  io/vtu_writer.cpp
  io/pvd_writer.cpp
  io/series_writer.cpp
  io/csv_file.cpp
  io/hdf5_file.cpp
  io/particle_budget.cpp
  io/run_folder.cpp
  io/durable_file.cpp
  io/case_section.cpp
  io/material_tables.cpp
  io/shape_reader.cpp
  io/case_tables.cpp
)
