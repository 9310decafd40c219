#pragma once
// Thin wrapper over an MPI communicator. grainbridge initialises MPI only when it was started
// by a launcher (mpirun, srun): a plain `grainbridge run` is then a serial program that needs no
// MPI runtime, while stage code always receives a Communicator (MPI_COMM_SELF in serial), so a
// multi-rank DEM stage later slots in without changing the executors.
#include <mpi.h>

namespace grainbridge::core::parallel {

// True when the environment shows an MPI launcher started this process.
bool launchedByMpiLauncher();
// Initialises MPI if launched by a launcher; otherwise does nothing. Idempotent.
void initialize(int* argc, char*** argv);
// Runs the hooks registered by beforeFinalize (last first), then finalises MPI if it is active.
void finalize();
// A library that holds MPI resources (PETSc) registers its own finalisation here, to run before
// MPI_Finalize; registering the same hook twice runs it once.
void beforeFinalize(void (*hook)());
bool mpiActive();
int worldRank();  // 0 when MPI is not active
int worldSize();  // 1 when MPI is not active

class Communicator {
 public:
  static Communicator self();
  static Communicator world();
  explicit Communicator(MPI_Comm comm, bool owned = false) : comm_(comm), owned_(owned) {}
  Communicator(const Communicator&) = delete;
  Communicator& operator=(const Communicator&) = delete;
  Communicator(Communicator&& other) noexcept;
  Communicator& operator=(Communicator&& other) noexcept;
  ~Communicator();

  [[nodiscard]] int rank() const;
  [[nodiscard]] int size() const;
  [[nodiscard]] MPI_Comm raw() const { return comm_; }
  [[nodiscard]] bool isMpi() const { return comm_ != MPI_COMM_NULL; }

 private:
  MPI_Comm comm_ = MPI_COMM_NULL;  // MPI_COMM_NULL: serial, MPI not initialised
  bool owned_ = false;             // freed on destruction (created by MPI_Comm_create_group)
};

}  // namespace grainbridge::core::parallel
