#pragma once
// Runs each instance in this process as soon as it is submitted, on MPI_COMM_SELF (or no
// communicator at all outside mpirun).
#include <atomic>
#include <deque>
#include <filesystem>

#include "workflows/exec/Dispatcher.hpp"
#include "workflows/stages/StageRegistry.hpp"

namespace grainbridge::workflows::exec {

class SerialDispatcher final : public Dispatcher {
 public:
  SerialDispatcher(const stages::StageRegistry& registry, std::filesystem::path resultsRoot,
                   const std::atomic<bool>& stop)
      : registry_(registry), resultsRoot_(std::move(resultsRoot)), stop_(stop) {}
  [[nodiscard]] int idleRanks() const override { return done_.empty() ? 1 : 0; }
  [[nodiscard]] int maxRanks() const override { return 1; }
  std::vector<int> reserve(int) override { return {0}; }
  void submit(std::size_t instance, const InstanceTask& task) override;
  [[nodiscard]] int inFlight() const override { return static_cast<int>(done_.size()); }
  std::optional<std::pair<std::size_t, InstanceOutcome>> poll() override;

 private:
  const stages::StageRegistry& registry_;
  std::filesystem::path resultsRoot_;
  const std::atomic<bool>& stop_;
  std::deque<std::pair<std::size_t, InstanceOutcome>> done_;
};

}  // namespace grainbridge::workflows::exec
