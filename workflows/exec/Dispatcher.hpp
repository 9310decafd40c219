#pragma once
// Where stage instances run. The scheduling loop (Scheduler.cpp) is written once; a dispatcher
// either runs an instance inline (serial) or hands it to idle MPI ranks.
#include <cstddef>
#include <optional>
#include <utility>

#include "workflows/exec/InstanceTask.hpp"

namespace grainbridge::workflows::exec {

class Dispatcher {
 public:
  virtual ~Dispatcher() = default;
  // Ranks free to take work now.
  [[nodiscard]] virtual int idleRanks() const = 0;
  // Ranks this dispatcher can ever give one instance.
  [[nodiscard]] virtual int maxRanks() const = 0;
  // The world ranks an instance of `ranks` ranks would run on (the first is its leader).
  virtual std::vector<int> reserve(int ranks) = 0;
  virtual void submit(std::size_t instance, const InstanceTask& task) = 0;
  [[nodiscard]] virtual int inFlight() const = 0;
  // Waits (briefly) for a finished instance; nullopt if none finished yet.
  virtual std::optional<std::pair<std::size_t, InstanceOutcome>> poll() = 0;
};

}  // namespace grainbridge::workflows::exec
