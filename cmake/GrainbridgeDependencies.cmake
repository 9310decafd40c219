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
# PETSc (Debian libpetsc-real-dev: Open MPI, hypre, MUMPS) solves the fluid engines' linear systems
# with KSP where a stage asks for `<family>_solver: petsc` (issue 58). Optional, as LAMMPS is:
# without it the build is complete, `petsc` is refused at `grainbridge check`, and `grainbridge
# --version` says why. Found through its pkg-config file; the target takes its include folders and
# libraries only (the .pc's other flags, -D_FORTIFY_SOURCE among them, are the build's business).
option(GRAINBRIDGE_WITH_PETSC "solve the fluid systems through PETSc when it is found" ON)
set(GRAINBRIDGE_PETSC_OFF_REASON "")
if(GRAINBRIDGE_WITH_PETSC)
  find_package(PkgConfig QUIET)
  if(PkgConfig_FOUND)
    pkg_check_modules(PETSC QUIET PETSc)
  endif()
  if(PETSC_FOUND)
    add_library(PETSc::PETSc INTERFACE IMPORTED)
    target_include_directories(PETSc::PETSc SYSTEM INTERFACE ${PETSC_INCLUDE_DIRS})
    target_link_libraries(PETSc::PETSc INTERFACE ${PETSC_LINK_LIBRARIES} MPI::MPI_C)
  else()
    set(GRAINBRIDGE_PETSC_OFF_REASON "pkg-config found no PETSc (Debian: libpetsc-real-dev)")
  endif()
else()
  set(GRAINBRIDGE_PETSC_OFF_REASON "GRAINBRIDGE_WITH_PETSC is OFF")
endif()
# LAMMPS's library (Debian liblammps-dev, with `lammps` for the /usr/bin/lmp its CMake package
# checks) runs the dem stage's `engine` lammps (issue 32). Optional: without it the build is
# complete, the engine is refused at `grainbridge check`, and `grainbridge --version` says why.
# The package is tried in a separate project first (cmake/lammps-probe), because an incomplete one
# stops the configure step with FATAL_ERROR, which no caller can catch (issue 54).
option(GRAINBRIDGE_WITH_LAMMPS "build engine lammps when liblammps is found" ON)
set(GRAINBRIDGE_LAMMPS_OFF_REASON "")
if(NOT GRAINBRIDGE_WITH_LAMMPS)
  set(GRAINBRIDGE_LAMMPS_OFF_REASON "GRAINBRIDGE_WITH_LAMMPS is OFF")
else()
  # A configure + build of the probe as a child CMake: try_compile would turn the probe's configure
  # error into one of ours.
  set(_probe_dir ${CMAKE_BINARY_DIR}/lammps-probe)
  file(REMOVE_RECURSE ${_probe_dir})
  execute_process(
    COMMAND ${CMAKE_COMMAND} -S ${CMAKE_CURRENT_LIST_DIR}/lammps-probe -B ${_probe_dir} -G "${CMAKE_GENERATOR}"
            -DCMAKE_C_COMPILER=${CMAKE_C_COMPILER} -DCMAKE_CXX_COMPILER=${CMAKE_CXX_COMPILER}
            "-DCMAKE_PREFIX_PATH=${CMAKE_PREFIX_PATH}" "-DLAMMPS_DIR=${LAMMPS_DIR}"
    RESULT_VARIABLE _probe_rc OUTPUT_VARIABLE _probe_out ERROR_VARIABLE _probe_err)
  if(_probe_rc EQUAL 0)
    execute_process(COMMAND ${CMAKE_COMMAND} --build ${_probe_dir}
                    RESULT_VARIABLE _probe_rc OUTPUT_VARIABLE _probe_out ERROR_VARIABLE _probe_err)
  endif()
  if(_probe_rc EQUAL 0)
    set(_lammps_usable TRUE)
  else()
    set(_lammps_usable FALSE)
  endif()
  set(_lammps_probe_log "${_probe_err}\n${_probe_out}")
  if(_lammps_usable)
    find_package(MPI QUIET COMPONENTS CXX)
    find_package(LAMMPS CONFIG QUIET)
  else()
    # The probe's first CMake error names what is missing (e.g. "... references the file
    # "/usr/bin/lmp" but this file does not exist").
    string(FIND "${_lammps_probe_log}" "CMake Error" _at)
    if(_at GREATER_EQUAL 0)
      string(SUBSTRING "${_lammps_probe_log}" ${_at} 600 _lammps_error)
      foreach(_end "Possible reasons" "Call Stack")
        string(FIND "${_lammps_error}" "${_end}" _cut)
        if(_cut GREATER 0)
          string(SUBSTRING "${_lammps_error}" 0 ${_cut} _lammps_error)
        endif()
      endforeach()
      string(REGEX REPLACE "[ \n]+" " " _lammps_error "${_lammps_error}")
      string(STRIP "${_lammps_error}" _lammps_error)
    else()
      set(_lammps_error "")
    endif()
    if(NOT _lammps_error)
      set(_lammps_error "the probe in ${CMAKE_BINARY_DIR}/lammps-probe did not build")
    endif()
    set(GRAINBRIDGE_LAMMPS_OFF_REASON "the LAMMPS probe (cmake/lammps-probe) failed: ${_lammps_error}")
  endif()
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
