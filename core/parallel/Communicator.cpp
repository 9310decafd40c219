#include "core/parallel/Communicator.hpp"

#include <algorithm>
#include <cstdlib>
#include <utility>
#include <vector>

namespace grainbridge::core::parallel {

bool launchedByMpiLauncher() {
  // Open MPI, MPICH/Hydra, PMIx and Slurm each set one of these in every launched process.
  for (const char* var : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_RANK", "SLURM_STEP_NUM_TASKS"}) {
    if (std::getenv(var) != nullptr) return true;
  }
  return false;
}

void initialize(int* argc, char*** argv) {
  if (mpiActive() || !launchedByMpiLauncher()) return;
  int provided = 0;
  // Stages run one per rank; a heartbeat thread touches SQLite only, never MPI.
  MPI_Init_thread(argc, argv, MPI_THREAD_FUNNELED, &provided);
}

namespace {

std::vector<void (*)()>& finalizeHooks() {
  static std::vector<void (*)()> hooks;
  return hooks;
}

}  // namespace

void beforeFinalize(void (*hook)()) {
  auto& hooks = finalizeHooks();
  if (std::find(hooks.begin(), hooks.end(), hook) == hooks.end()) hooks.push_back(hook);
}

void finalize() {
  auto& hooks = finalizeHooks();
  while (!hooks.empty()) {
    void (*hook)() = hooks.back();
    hooks.pop_back();
    hook();
  }
  if (mpiActive()) MPI_Finalize();
}

bool mpiActive() {
  int initialized = 0;
  int finalized = 0;
  MPI_Initialized(&initialized);
  MPI_Finalized(&finalized);
  return initialized != 0 && finalized == 0;
}

int worldRank() {
  if (!mpiActive()) return 0;
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  return rank;
}

int worldSize() {
  if (!mpiActive()) return 1;
  int size = 1;
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  return size;
}

Communicator Communicator::self() { return Communicator(mpiActive() ? MPI_COMM_SELF : MPI_COMM_NULL); }
Communicator Communicator::world() { return Communicator(mpiActive() ? MPI_COMM_WORLD : MPI_COMM_NULL); }

Communicator::Communicator(Communicator&& other) noexcept
    : comm_(std::exchange(other.comm_, MPI_COMM_NULL)), owned_(std::exchange(other.owned_, false)) {}

Communicator& Communicator::operator=(Communicator&& other) noexcept {
  if (this != &other) {
    if (owned_ && comm_ != MPI_COMM_NULL && mpiActive()) MPI_Comm_free(&comm_);
    comm_ = std::exchange(other.comm_, MPI_COMM_NULL);
    owned_ = std::exchange(other.owned_, false);
  }
  return *this;
}

Communicator::~Communicator() {
  if (owned_ && comm_ != MPI_COMM_NULL && mpiActive()) MPI_Comm_free(&comm_);
}

int Communicator::rank() const {
  if (comm_ == MPI_COMM_NULL) return 0;
  int rank = 0;
  MPI_Comm_rank(comm_, &rank);
  return rank;
}

int Communicator::size() const {
  if (comm_ == MPI_COMM_NULL) return 1;
  int size = 1;
  MPI_Comm_size(comm_, &size);
  return size;
}

}  // namespace grainbridge::core::parallel
