// A build without PETSc (issue 58): the stage schemas refuse `<family>_solver: petsc` at check
// with this note, so nothing here is reached by a checked config.
#include "core/Error.hpp"
#include "engines/fluid/PetscKsp.hpp"

namespace grainbridge::fluid {

bool petscAvailable() { return false; }

std::string petscBuildNote() {
#ifdef GRAINBRIDGE_PETSC_OFF_REASON
  return std::string("off: ") + GRAINBRIDGE_PETSC_OFF_REASON;
#else
  return "off";
#endif
}

std::optional<std::string> petscOptionsProblem(const std::string&) {
  return "this build has no PETSc (" + petscBuildNote() + "): install libpetsc-real-dev and rebuild";
}

bool petscSolve(const CompressedRows&, const double*, double*, double, const std::string&) {
  throw Error("fluid: this build has no PETSc (" + petscBuildNote() + ")");
}

}  // namespace grainbridge::fluid
