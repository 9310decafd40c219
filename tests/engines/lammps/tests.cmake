# engines/lammps: the dem setup as a LAMMPS input (issue 32); text only, built without LAMMPS too.
grainbridge_add_test(test_lammps_input
  SOURCES
    ${CMAKE_CURRENT_SOURCE_DIR}/lammps/LammpsInputTest.cpp
  LIBS engines_lammps
  LABELS "unit;dem")
