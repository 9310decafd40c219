# All third-party libraries come from Debian packages (scripts/install-deps.sh lists them).
find_package(Eigen3 3.4 REQUIRED NO_MODULE)
find_package(HDF5 REQUIRED COMPONENTS C)
find_package(SQLite3 REQUIRED)
find_package(nlohmann_json 3.11 REQUIRED)
find_package(MPI REQUIRED COMPONENTS C)
find_package(CLI11 REQUIRED)
find_package(spdlog REQUIRED)
find_package(OpenSSL REQUIRED COMPONENTS Crypto)
find_package(Threads REQUIRED)
# LAPACK's banded LU (dgbsv) solves the fluid engine's systems on grids narrow in one direction.
find_package(LAPACK REQUIRED)
# LAMMPS's library (Debian liblammps-dev) runs the dem stage's `engine` lammps (issue 32). Optional:
# without it the build is complete and that engine is refused at `grainbridge check`.
option(GRAINBRIDGE_WITH_LAMMPS "build engine lammps when liblammps is found" ON)
if(GRAINBRIDGE_WITH_LAMMPS)
  find_package(MPI QUIET COMPONENTS CXX)
  find_package(LAMMPS CONFIG QUIET)
endif()

# udunits2 (Unidata) parses and converts unit strings ("2.5 mm", "39 m/s", "1.2 g/cm3");
# Debian ships no CMake config for it.
find_path(UDUNITS2_INCLUDE_DIR udunits2.h PATH_SUFFIXES udunits2 REQUIRED)
find_library(UDUNITS2_LIBRARY udunits2 REQUIRED)
add_library(udunits2::udunits2 UNKNOWN IMPORTED)
set_target_properties(udunits2::udunits2 PROPERTIES
  IMPORTED_LOCATION ${UDUNITS2_LIBRARY}
  INTERFACE_INCLUDE_DIRECTORIES ${UDUNITS2_INCLUDE_DIR})

if(NOT TARGET HDF5::HDF5)
  add_library(HDF5::HDF5 INTERFACE IMPORTED)
  target_include_directories(HDF5::HDF5 SYSTEM INTERFACE ${HDF5_C_INCLUDE_DIRS} ${HDF5_INCLUDE_DIRS})
  target_link_libraries(HDF5::HDF5 INTERFACE ${HDF5_C_LIBRARIES} ${HDF5_LIBRARIES})
endif()
