#include "workflows/plan/Plan.hpp"

#include <algorithm>

#include "core/Error.hpp"
#include "core/Sha256.hpp"
#include "core/json/Diagnostics.hpp"
#include "core/text/NumberText.hpp"

namespace grainbridge::workflows::plan {

using nlohmann::json;

std::string StageInstance::label() const {
  json shown = sweepWritten.empty() ? sweepPoint : sweepWritten;
  shown.merge_patch(replica.shown);
  if (shown.empty()) return stage;
  std::string s = stage + "[";
  bool first = true;
  for (const auto& [k, v] : shown.items()) {
    s += (first ? "" : ", ") + k + "=" + core::humanText(v);
    first = false;
  }
  return s + "]";
}

std::string StageInstance::relativeDir(const std::string& workflow) const { return workflow + "/" + stage + "/" + key; }

json keyMaterial(const stages::StageType& type, const json& resolvedParams,
                 const std::vector<std::string>& upstreamKeys, const json& tables) {
  json material{{"type", type.name()},
                {"impl_version", type.implVersion()},
                {"params", type.params().keyParams(resolvedParams)},
                {"upstream", upstreamKeys}};
  if (!tables.empty()) material["closure_tables"] = tables;
  return material;
}

std::string stageKey(const json& material) {
  // nlohmann::json objects keep keys sorted and dump doubles in shortest round-trip form,
  // so equal content always gives equal text.
  return core::sha256Hex(material.dump());
}

namespace {

// Combinations of upstream instances a per-instance stage runs over (one from each `from`).
std::vector<std::vector<std::size_t>> upstreamCombinations(const config::StageConfig& stage, const Plan& plan) {
  std::vector<std::vector<std::size_t>> combos{{}};
  for (const auto& up : stage.from) {
    std::vector<std::vector<std::size_t>> next;
    for (const auto& c : combos) {
      for (auto idx : plan.byStage.at(up)) {
        auto d = c;
        d.push_back(idx);
        next.push_back(std::move(d));
      }
    }
    combos = std::move(next);
  }
  return combos;
}

}  // namespace

Plan makePlan(const config::WorkflowConfig& config, const TableLookup& lookup) {
  Plan plan;
  plan.workflow = config.name;
  for (const auto& stage : config.stages) {
    std::vector<std::vector<std::size_t>> inputSets;
    if (stage.type->inputMode() == stages::InputMode::PerInstance) {
      inputSets = upstreamCombinations(stage, plan);
    } else {
      std::vector<std::size_t> all;
      for (const auto& up : stage.from) {
        const auto& v = plan.byStage.at(up);
        all.insert(all.end(), v.begin(), v.end());
      }
      inputSets.push_back(std::move(all));
    }
    for (const auto& inputs : inputSets) {
      const auto points = config::sweepPoints(stage.sweep);
      const auto written = config::sweepPointsAsWritten(stage.sweep);
      for (std::size_t p = 0; p < points.size(); ++p) {
        const json swept = config::withSweepPoint(stage.params, points[p]);
        for (const auto& replica : stage.type->replicas(swept)) {
          StageInstance inst;
          inst.index = plan.instances.size();
          inst.stage = stage.name;
          inst.type = stage.type;
          inst.params = swept;
          inst.params.merge_patch(replica.overlay);
          inst.sweepPoint = points[p];
          inst.sweepWritten = written[p];
          inst.replica = replica;
          inst.upstream = inputs;
          inst.ranks = stage.ranksPerInstance;
          std::vector<std::string> upKeys;
          for (auto i : inputs) upKeys.push_back(plan.instances[i].key);
          // A gathering stage does not care in which order its inputs were listed.
          if (stage.type->inputMode() == stages::InputMode::Gather) std::sort(upKeys.begin(), upKeys.end());
          json tables = json::object();
          for (const auto& ref : stage.type->closureTables(inst.params)) {
            StageInstance::TableInput in{ref.name, ref.quantity, "", ""};
            for (auto i : inputs) {
              const auto planned = plan.instances[i].type->plannedOutput(plan.instances[i].params);
              if (planned && planned->closureTables == ref.name) in.runKey = plan.instances[i].key;
            }
            if (in.runKey.empty()) {
              const TableFound found = lookup ? lookup(ref.name, ref.quantity) : TableFound{};
              in.sha256 = found.sha256;
              if (!in.sha256.empty() && found.grains) {
                core::json::Diagnostics d;
                stage.type->checkTableGrains(inst.params, "/stages/" + stage.name + "/params", ref, *found.grains, d);
                if (!d.empty()) throw core::json::InputError(config.sourcePath.string(), std::move(d));
              }
              if (const std::string needs = stage.type->tableErrorsNeededBy(inst.params);
                  !in.sha256.empty() && !found.hasErrors && !needs.empty()) {
                core::json::Diagnostics d;
                d.add("/stages/" + stage.name + "/params" + needs,
                      "closure table \"" + ref.name + "\" (" + ref.quantity +
                          ") in the workflow database has no standard errors to draw samples within (tabulate it "
                          "again from closure points with errors)");
                throw core::json::InputError(config.sourcePath.string(), std::move(d));
              }
              if (in.sha256.empty()) {
                core::json::Diagnostics d;
                d.add("/stages/" + stage.name + "/params" + ref.pointer,
                      "closure table \"" + ref.name + "\" (" + ref.quantity +
                          ") is neither in the workflow database (" + config.database.string() +
                          ") nor made by a tabulate stage this stage takes `from`");
                throw core::json::InputError(config.sourcePath.string(), std::move(d));
              }
            }
            tables[ref.name + "/" + ref.quantity] = in.runKey.empty() ? in.sha256 : "upstream";
            inst.tables.push_back(std::move(in));
          }
          inst.key = stageKey(keyMaterial(*stage.type, inst.params, upKeys, tables));
          plan.byStage[stage.name].push_back(inst.index);
          plan.instances.push_back(std::move(inst));
        }
      }
    }
    if (plan.byStage.find(stage.name) == plan.byStage.end()) plan.byStage[stage.name] = {};
  }
  return plan;
}

}  // namespace grainbridge::workflows::plan
