#pragma once
// The one list of stage types. Registration is explicit (see StageRegistry.cpp), because
// self-registering objects in static libraries are dropped by the linker.
#include <memory>
#include <string>
#include <vector>

#include "workflows/stages/StageType.hpp"

namespace grainbridge::workflows::stages {

class StageRegistry {
 public:
  // The registry of every stage type grainbridge ships.
  static const StageRegistry& builtin();

  explicit StageRegistry(std::vector<std::unique_ptr<StageType>> types);
  [[nodiscard]] const StageType* find(const std::string& name) const;
  [[nodiscard]] std::vector<std::string> names() const;
  [[nodiscard]] const std::vector<std::unique_ptr<StageType>>& all() const { return types_; }
  // What a report shows of each type (its key results, the units of its parameters).
  [[nodiscard]] contract::StageTypeLookup reportView() const;

 private:
  std::vector<std::unique_ptr<StageType>> types_;
};

}  // namespace grainbridge::workflows::stages
