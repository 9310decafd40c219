#include "engines/fluid/PetscKsp.hpp"

#include <petscksp.h>

#include <algorithm>
#include <cstdlib>
#include <memory>
#include <mutex>
#include <vector>

#include "core/Error.hpp"
#include "core/parallel/Communicator.hpp"

namespace grainbridge::fluid {

namespace {

// PETSc's message for its first error since the last call of takeMessage (its error codes alone
// say "unknown type", not which); PETSc prints nothing itself.
// (The statics here are never destroyed: PETSc is finalised by an exit handler, which may run
// after the destructors of statics made later than its registration.)
std::string& lastMessage() {
  static auto* message = new std::string;
  return *message;
}

PetscErrorCode keepMessage(MPI_Comm, int, const char*, const char*, PetscErrorCode code, PetscErrorType kind,
                           const char* message, void*) {
  if (kind == PETSC_ERROR_INITIAL && message != nullptr) lastMessage() = message;
  return code;
}

struct PetscFailure : Error {
  using Error::Error;
};

// Throws PetscFailure with PETSc's message when `code` is an error.
void check(PetscErrorCode code, const char* call) {
  if (code == 0) return;
  std::string message = std::move(lastMessage());
  lastMessage().clear();
  if (message.empty()) {
    const char* text = nullptr;
    PetscErrorMessage(code, &text, nullptr);
    message = text != nullptr ? text : "error " + std::to_string(static_cast<int>(code));
  }
  throw PetscFailure(std::string(call) + ": " + message);
}

// A KSP with its matrix and vectors for one sparsity pattern, options string and tolerance.
struct Solver {
  std::vector<int> start, column;
  std::string options;
  double tolerance = 0.0;
  PetscOptions database = nullptr;
  Mat A = nullptr;
  Vec b = nullptr, x = nullptr;
  KSP ksp = nullptr;

  Solver() = default;
  Solver(const Solver&) = delete;
  Solver& operator=(const Solver&) = delete;
  ~Solver() {
    // Errors here have nowhere to go: the objects are released as far as PETSc can.
    if (ksp != nullptr) KSPDestroy(&ksp);
    if (x != nullptr) VecDestroy(&x);
    if (b != nullptr) VecDestroy(&b);
    if (A != nullptr) MatDestroy(&A);
    if (database != nullptr) PetscOptionsDestroy(&database);
  }
  [[nodiscard]] bool matches(const CompressedRows& m, const std::string& o, double t) const {
    const auto n = static_cast<std::size_t>(m.rows);
    return o == options && t == tolerance && start.size() == n + 1 && std::equal(start.begin(), start.end(), m.start) &&
           std::equal(column.begin(), column.end(), m.column);
  }
};

std::mutex& petscMutex() {
  static auto* mutex = new std::mutex;
  return *mutex;
}

// Kept solvers, most recent last; a few patterns per engine (a momentum component per axis, the
// pressure and fraction corrections), so a short list is enough.
std::vector<std::unique_ptr<Solver>>& kept() {
  static auto* solvers = new std::vector<std::unique_ptr<Solver>>;
  return *solvers;
}

void finalizePetsc() {
  std::lock_guard lock(petscMutex());
  PetscBool initialised = PETSC_FALSE, finalised = PETSC_FALSE;
  PetscInitialized(&initialised);
  PetscFinalized(&finalised);
  int mpiFinalised = 0;
  MPI_Finalized(&mpiFinalised);
  if (initialised != PETSC_TRUE || finalised == PETSC_TRUE || mpiFinalised != 0) return;
  kept().clear();
  PetscFinalize();
}

// Whether MPI was started here (a plain `grainbridge run`, a test): then it is finalised here too,
// at exit, unless core::parallel::finalize did it first.
bool& startedMpi() {
  static bool started = false;
  return started;
}

void finalizeAtExit() {
  finalizePetsc();
  if (startedMpi() && core::parallel::mpiActive()) MPI_Finalize();
}

// Initialises PETSc once (the caller holds the mutex). PETSc needs MPI, and PETSC_COMM_WORLD may be
// set only once MPI runs: a process that no launcher started (a serial `grainbridge run`) starts
// MPI as a singleton here.
void initialise() {
  PetscBool initialised = PETSC_FALSE;
  PetscInitialized(&initialised);
  if (initialised == PETSC_TRUE) return;
  if (!core::parallel::mpiActive()) {
    int provided = 0;
    MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided);
    startedMpi() = true;
  }
  PETSC_COMM_WORLD = MPI_COMM_SELF;
  check(PetscOptionsSetValue(nullptr, "-no_signal_handler", nullptr), "PetscOptionsSetValue");
  check(PetscOptionsSetValue(nullptr, "-skip_petscrc", nullptr), "PetscOptionsSetValue");
  int argc = 0;
  char** argv = nullptr;
  check(PetscInitialize(&argc, &argv, nullptr, nullptr), "PetscInitialize");
  check(PetscPushErrorHandler(keepMessage, nullptr), "PetscPushErrorHandler");
  core::parallel::beforeFinalize(finalizePetsc);
  std::atexit(finalizeAtExit);
}

// A solver for the pattern of `m` with the given options, its matrix holding m's values.
std::unique_ptr<Solver> makeSolver(const CompressedRows& m, const std::string& options, double tolerance) {
  auto s = std::make_unique<Solver>();
  const auto n = static_cast<std::size_t>(m.rows);
  s->start.assign(m.start, m.start + n + 1);
  s->column.assign(m.column, m.column + m.start[n]);
  s->options = options;
  s->tolerance = tolerance;
  check(PetscOptionsCreate(&s->database), "PetscOptionsCreate");
  check(PetscOptionsInsertString(s->database, options.c_str()), "PetscOptionsInsertString");
  check(MatCreate(PETSC_COMM_SELF, &s->A), "MatCreate");
  check(MatSetSizes(s->A, m.rows, m.rows, m.rows, m.rows), "MatSetSizes");
  check(MatSetType(s->A, MATSEQAIJ), "MatSetType");
  check(MatSeqAIJSetPreallocationCSR(s->A, m.start, m.column, m.value), "MatSeqAIJSetPreallocationCSR");
  check(MatCreateVecs(s->A, &s->x, &s->b), "MatCreateVecs");
  check(KSPCreate(PETSC_COMM_SELF, &s->ksp), "KSPCreate");
  check(PetscObjectSetOptions(reinterpret_cast<PetscObject>(s->ksp), s->database), "PetscObjectSetOptions");
  PC pc = nullptr;
  check(KSPGetPC(s->ksp, &pc), "KSPGetPC");
  check(PetscObjectSetOptions(reinterpret_cast<PetscObject>(pc), s->database), "PetscObjectSetOptions");
  check(KSPSetOperators(s->ksp, s->A, s->A), "KSPSetOperators");
  check(KSPSetTolerances(s->ksp, tolerance, PETSC_DEFAULT, PETSC_DEFAULT, PETSC_DEFAULT), "KSPSetTolerances");
  check(KSPSetInitialGuessNonzero(s->ksp, PETSC_TRUE), "KSPSetInitialGuessNonzero");
  check(KSPSetFromOptions(s->ksp), "KSPSetFromOptions");
  return s;
}

// The kept solver for m's pattern, options and tolerance, made if there is none.
Solver& solverFor(const CompressedRows& m, const std::string& options, double tolerance) {
  auto& solvers = kept();
  for (auto it = solvers.begin(); it != solvers.end(); ++it) {
    if ((*it)->matches(m, options, tolerance)) {
      std::rotate(it, it + 1, solvers.end());  // most recent last
      return *solvers.back();
    }
  }
  if (solvers.size() >= 16) solvers.erase(solvers.begin());  // many grids in one process (tests)
  solvers.push_back(makeSolver(m, options, tolerance));
  return *solvers.back();
}

// Copies m's values into the solver's matrix (the same pattern, in the same order).
void setValues(Solver& s, const CompressedRows& m) {
  PetscScalar* a = nullptr;
  check(MatSeqAIJGetArray(s.A, &a), "MatSeqAIJGetArray");
  std::copy(m.value, m.value + m.start[m.rows], a);
  check(MatSeqAIJRestoreArray(s.A, &a), "MatSeqAIJRestoreArray");  // marks the matrix changed
}

bool solveWith(Solver& s, const double* b, double* x) {
  const auto n = static_cast<std::ptrdiff_t>(s.start.size() - 1);
  PetscScalar* v = nullptr;
  check(VecGetArrayWrite(s.b, &v), "VecGetArrayWrite");
  std::copy(b, b + n, v);
  check(VecRestoreArrayWrite(s.b, &v), "VecRestoreArrayWrite");
  check(VecGetArrayWrite(s.x, &v), "VecGetArrayWrite");
  std::copy(x, x + n, v);
  check(VecRestoreArrayWrite(s.x, &v), "VecRestoreArrayWrite");
  check(KSPSolve(s.ksp, s.b, s.x), "KSPSolve");
  KSPConvergedReason reason = KSP_CONVERGED_ITERATING;
  check(KSPGetConvergedReason(s.ksp, &reason), "KSPGetConvergedReason");
  const PetscScalar* out = nullptr;
  check(VecGetArrayRead(s.x, &out), "VecGetArrayRead");
  std::copy(out, out + n, x);
  check(VecRestoreArrayRead(s.x, &out), "VecRestoreArrayRead");
  return reason > 0;
}

}  // namespace

bool petscAvailable() { return true; }

std::string petscBuildNote() {
  return "PETSc " + std::to_string(PETSC_VERSION_MAJOR) + "." + std::to_string(PETSC_VERSION_MINOR) + "." +
         std::to_string(PETSC_VERSION_SUBMINOR);
}

std::optional<std::string> petscOptionsProblem(const std::string& options) {
  std::lock_guard lock(petscMutex());
  try {
    initialise();
    const int start[] = {0, 1};
    const int column[] = {0};
    const double value[] = {1.0};
    const CompressedRows one{1, start, column, value};
    const auto s = makeSolver(one, options, 1e-8);
    check(KSPSetUp(s->ksp), "KSPSetUp");
    double x = 0.0;
    const double b = 1.0;
    solveWith(*s, &b, &x);
    PetscInt unused = 0;
    char** names = nullptr;
    char** values = nullptr;
    check(PetscOptionsLeftGet(s->database, &unused, &names, &values), "PetscOptionsLeftGet");
    std::string left;
    for (PetscInt k = 0; k < unused; ++k) left += std::string(left.empty() ? "" : ", ") + "-" + names[k];
    check(PetscOptionsLeftRestore(s->database, &unused, &names, &values), "PetscOptionsLeftRestore");
    if (!left.empty()) return "PETSc did not use " + left + " (a misspelt option, or one for another solver)";
  } catch (const PetscFailure& e) {
    return std::string("PETSc refused \"") + options + "\": " + e.what();
  }
  return std::nullopt;
}

bool petscSolve(const CompressedRows& A, const double* b, double* x, double tolerance, const std::string& options) {
  std::lock_guard lock(petscMutex());
  initialise();
  try {
    Solver& s = solverFor(A, options, tolerance);
    setValues(s, A);
    return solveWith(s, b, x);
  } catch (const PetscFailure&) {
    return false;  // e.g. a zero pivot in the preconditioner's factorisation: the direct solve answers
  }
}

}  // namespace grainbridge::fluid
