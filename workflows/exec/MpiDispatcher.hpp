#pragma once
// Rank 0 hands stage instances to idle worker ranks (1..N-1) and collects their outcomes; it
// is the only rank that writes the database. An instance asking for ranks_per_instance = r gets
// r idle workers, which build their own communicator with MPI_Comm_create_group (collective
// over those r ranks only, so the others keep working).
#include <deque>
#include <filesystem>
#include <map>
#include <set>

#include "workflows/exec/Dispatcher.hpp"
#include "workflows/stages/StageRegistry.hpp"

namespace grainbridge::workflows::exec {

class MpiDispatcher final : public Dispatcher {
 public:
  MpiDispatcher();
  ~MpiDispatcher() override;  // tells every worker to stop
  [[nodiscard]] int idleRanks() const override { return static_cast<int>(idle_.size()); }
  [[nodiscard]] int maxRanks() const override { return worldSize_ - 1; }
  std::vector<int> reserve(int ranks) override;
  void submit(std::size_t instance, const InstanceTask& task) override;
  [[nodiscard]] int inFlight() const override { return static_cast<int>(running_.size()); }
  std::optional<std::pair<std::size_t, InstanceOutcome>> poll() override;

 private:
  int worldSize_ = 1;
  int nextTag_ = 100;
  std::set<int> idle_;
  std::map<int, std::pair<std::size_t, std::vector<int>>> running_;  // leader rank -> (instance, group)
};

// The loop every rank but 0 runs: receive a task, run it, send the outcome back (group leader
// only), until rank 0 says stop.
void runMpiWorker(const stages::StageRegistry& registry, const std::filesystem::path& resultsRoot);

}  // namespace grainbridge::workflows::exec
