#pragma once
// PETSc's Krylov solvers (KSP) for the fluid engines' linear systems (issue 58): a stage's
// `<family>_solver: petsc` with `<family>_petsc_options`, a PETSc options string such as
// "-ksp_type gmres -ksp_pc_side right -pc_type hypre". Each options string is read into its own
// options database, so the families (momentum, pressure, fraction) never see each other's options,
// and no solver option comes from the command line, PETSC_OPTIONS or ~/.petscrc: a workflow config
// says all of it. PETSC_OPTIONS still reaches PETSc's global options, which is how a user profiles
// the solves: PETSC_OPTIONS="-log_view :log.txt" grainbridge run ... One rank for now: the matrix is
// PETSc's sequential AIJ on MPI_COMM_SELF.
//
// PETSc is initialised at the first use, with PETSC_COMM_WORLD = MPI_COMM_SELF (each rank on its
// own: the ranks of a multi-instance run reach their first solve at different times) and without
// PETSc's signal handlers (the workflow driver's SIGTERM handler writes the checkpoint); it is
// finalised before MPI (core::parallel::finalize) or at exit. PETSc needs MPI: a process no
// launcher started (a serial `grainbridge run`) starts it then, as a singleton.
#include <optional>
#include <string>

namespace grainbridge::fluid {

// A square sparse matrix in compressed rows, zero-based, each row's columns ascending.
struct CompressedRows {
  int rows = 0;
  const int* start = nullptr;  // rows + 1 offsets into column and value
  const int* column = nullptr;
  const double* value = nullptr;
};

// Whether this build has PETSc; its version ("PETSc 3.18.5") or why not ("off: ...").
[[nodiscard]] bool petscAvailable();
[[nodiscard]] std::string petscBuildNote();

// What is wrong with an options string for a KSP, or nothing: PETSc's own message for a type it
// does not know ("-ksp_type nosuch"), or the options it did not use (a misspelt name, which PETSc
// itself ignores). Sets a KSP up from the string and solves a 1 x 1 system with it, so the check
// finds at load what the first solve would. Initialises PETSc.
[[nodiscard]] std::optional<std::string> petscOptionsProblem(const std::string& options);

// Solves A x = b by KSP from the guess x holds, to the relative tolerance `tolerance` (KSP's rtol,
// which the options may override). False when KSP did not converge or PETSc failed on the way (a
// zero pivot in an incomplete factorisation): x is then unspecified, and the caller takes its
// direct solve. The matrix, solver and preconditioner objects are kept per sparsity pattern,
// options and tolerance, and reused with the new values (PETSc sets the preconditioner up again
// for them).
[[nodiscard]] bool petscSolve(const CompressedRows& A, const double* b, double* x, double tolerance,
                              const std::string& options);

}  // namespace grainbridge::fluid
