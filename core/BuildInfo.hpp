#pragma once
// What this binary is and what it was built with, for `grainbridge --version` and report
// footers: the code version (Version.hpp) and the versions of the libraries core links (HDF5,
// Eigen, MPI), read from the libraries themselves where they say so at run time.
#include <string>

namespace grainbridge::core {

[[nodiscard]] std::string hdf5Version();   // "1.10.8" (H5get_libversion)
[[nodiscard]] std::string eigenVersion();  // "3.4.0" (compile time: Eigen is header-only)
[[nodiscard]] std::string mpiVersion();    // first line of MPI_Get_library_version: "Open MPI v4.1.4, ..."

}  // namespace grainbridge::core
