#include "workflows/stages/StageRegistry.hpp"

#include "core/Error.hpp"
#include "workflows/stages/BedCompareStage.hpp"
#include "workflows/stages/CompareStage.hpp"
#include "workflows/stages/DemStage.hpp"
#include "workflows/stages/ExtractStage.hpp"
#include "workflows/stages/FluidizationStage.hpp"
#include "workflows/stages/MfmStage.hpp"
#include "workflows/stages/MixtureCompareStage.hpp"
#include "workflows/stages/ParticleGasStage.hpp"
#include "workflows/stages/ReportStage.hpp"
#include "workflows/stages/TabulateStage.hpp"
#include "workflows/stages/TfdemStage.hpp"

namespace grainbridge::workflows::stages {

const StageRegistry& StageRegistry::builtin() {
  static const StageRegistry registry = [] {
    std::vector<std::unique_ptr<StageType>> types;
    // Every stage type, in the order `grainbridge stages` lists them. The engines' stages
    // (dem, tfdem, mfm) and the closure stages (extract, tabulate, compare) join this list.
    types.push_back(std::make_unique<ParticleGasStage>());
    types.push_back(std::make_unique<DemStage>());
    types.push_back(std::make_unique<TfdemStage>());
    types.push_back(std::make_unique<MfmStage>());
    types.push_back(std::make_unique<ExtractStage>());
    types.push_back(std::make_unique<TabulateStage>());
    types.push_back(std::make_unique<CompareStage>());
    types.push_back(std::make_unique<MixtureCompareStage>());
    types.push_back(std::make_unique<FluidizationStage>());
    types.push_back(std::make_unique<BedCompareStage>());
    types.push_back(std::make_unique<ReportStage>());
    return StageRegistry(std::move(types));
  }();
  return registry;
}

StageRegistry::StageRegistry(std::vector<std::unique_ptr<StageType>> types) : types_(std::move(types)) {
  for (std::size_t i = 0; i < types_.size(); ++i) {
    for (std::size_t j = 0; j < i; ++j) {
      GB_ASSERT(types_[i]->name() != types_[j]->name(), "stage type '" + types_[i]->name() + "' registered twice");
    }
  }
}

const StageType* StageRegistry::find(const std::string& name) const {
  for (const auto& t : types_) {
    if (t->name() == name) return t.get();
  }
  return nullptr;
}

std::vector<std::string> StageRegistry::names() const {
  std::vector<std::string> out;
  for (const auto& t : types_) out.push_back(t->name());
  return out;
}

contract::StageTypeLookup StageRegistry::reportView() const {
  return [this](const std::string& typeName) -> std::optional<contract::StageTypeView> {
    const StageType* type = find(typeName);
    if (type == nullptr) return std::nullopt;
    return contract::StageTypeView{type->keyResults(),
                                   [type](const std::string& param) {
                                     std::string why;
                                     const auto* spec = type->params().findPath(param, why);
                                     return spec == nullptr ? std::string() : spec->dimension().siUnit();
                                   },
                                   type->replicaSummaryKeys()};
  };
}

}  // namespace grainbridge::workflows::stages
