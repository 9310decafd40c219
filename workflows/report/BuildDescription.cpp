#include "workflows/report/BuildDescription.hpp"

#include "core/BuildInfo.hpp"
#include "core/Version.hpp"
#include "db/Database.hpp"
#include "engines/fluid/PetscKsp.hpp"
#include "engines/lammps/LammpsInput.hpp"

namespace grainbridge::workflows::report {

std::string codeDescription() {
  const auto& v = core::codeVersion();
  return "grainbridge " + v.release + " (git " + v.gitSha + (v.dirty ? ", dirty" : ", clean") + ")";
}

std::string librariesDescription() {
  return "HDF5 " + core::hdf5Version() + ", SQLite " + db::sqliteVersion() + ", Eigen " + core::eigenVersion() +
         ", MPI: " + core::mpiVersion();
}

std::string enginesDescription() {
  // dem, fluid (mfm) and tfdem are always built; engine lammps only where liblammps was usable,
  // the fluid solver petsc only where PETSc was found.
  return "Engines: dem, mfm, tfdem; lammps: " + lammps::lammpsBuildNote() +
         "; fluid solver petsc: " + fluid::petscBuildNote();
}

}  // namespace grainbridge::workflows::report
