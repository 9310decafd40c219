#pragma once
// What this binary is and what it was built with, in one place: `grainbridge --version` prints
// it and every report's footer carries it.
#include <string>

namespace grainbridge::workflows::report {

// "grainbridge 0.1.0 (git 1a2b3c4, clean)"
std::string codeDescription();
// "HDF5 1.10.8, SQLite 3.40.1, Eigen 3.4.0, MPI: Open MPI v4.1.4, ..."
std::string librariesDescription();
// "Engines: dem, mfm, tfdem; lammps: LAMMPS 20220106" (or "lammps: off: <why>")
std::string enginesDescription();

}  // namespace grainbridge::workflows::report
