#include "workflows/exec/SerialDispatcher.hpp"

#include "workflows/exec/InstanceRunner.hpp"

namespace grainbridge::workflows::exec {

void SerialDispatcher::submit(std::size_t instance, const InstanceTask& task) {
  auto comm = core::parallel::Communicator::self();
  done_.emplace_back(instance, runInstance(task, registry_, resultsRoot_, comm, stop_));
}

std::optional<std::pair<std::size_t, InstanceOutcome>> SerialDispatcher::poll() {
  if (done_.empty()) return std::nullopt;
  auto front = std::move(done_.front());
  done_.pop_front();
  return front;
}

}  // namespace grainbridge::workflows::exec
