#pragma once
// A stage type (dem, extract, tabulate, report, ...): its name, impl_version, declared
// parameters and how it consumes upstream stages. Virtual dispatch happens once per stage
// instance, never in a hot loop.
#include <optional>
#include <string>
#include <vector>

#include "workflows/params/ParamSchema.hpp"
#include "workflows/stages/PlannedOutput.hpp"
#include "workflows/stages/StageContext.hpp"

namespace grainbridge::workflows::stages {

enum class InputMode {
  None,         // takes no `from`
  PerInstance,  // one instance per combination of upstream instances (dem sweep -> extract each)
  Gather,       // one instance consuming every upstream instance (extract -> tabulate, report)
};

using contract::ResultColumn;

// A copy of an instance a stage asks the planner for beyond its sweep points (an mfm stage's
// closure samples). `overlay` is merged into the resolved params, so it enters the copy's key and
// reaches its run, which records what tells the copy apart among its products (its summary), for
// comparing stages to read by name. A copy keeps its instance's sweep point. `shown` names the
// copy in logs and status ({"closure_sample": 3} shows as bed[closure_sample=3]) and nowhere
// else: it is in no manifest or task, so nothing downstream reads it. The instance itself is the
// replica with an empty overlay.
struct Replica {
  nlohmann::json overlay = nlohmann::json::object();
  nlohmann::json shown = nlohmann::json::object();
};

// A closure table an instance reads from the workflow database, and the parameter naming it
// (below the stage's /params, for messages).
struct ClosureTableRef {
  std::string name;
  std::string quantity;  // p_theta, eta_theta, j_theta; mu_of_I for the rheology rows of that name
  std::string pointer;
};

class StageType {
 public:
  virtual ~StageType() = default;
  [[nodiscard]] virtual std::string name() const = 0;
  // Bump whenever what the stage computes changes: it is part of every stage key, so cached
  // results of the old code are not reused.
  [[nodiscard]] virtual int implVersion() const = 0;
  [[nodiscard]] virtual std::string summary() const = 0;  // one-line description
  [[nodiscard]] virtual const params::ParamSchema& params() const = 0;
  [[nodiscard]] virtual InputMode inputMode() const = 0;
  // Checks across parameters that single declarations cannot express (a time step against
  // the contact time, one of two alternatives given): called at config load for the resolved
  // parameters of every instance, before any work starts. Problems go to `diagnostics` at
  // `pointer` (the stage's /params) or below it.
  virtual void checkParams(const nlohmann::json& /*resolved*/, const std::string& /*pointer*/,
                           core::json::Diagnostics& /*diagnostics*/) const {}
  // What an instance with these resolved params will produce, for the checks of downstream
  // stages; nullopt when the type promises nothing (the default).
  [[nodiscard]] virtual std::optional<PlannedOutput> plannedOutput(const nlohmann::json& /*resolved*/) const {
    return std::nullopt;
  }
  // Checks across stages: called at config load, after every stage's own checks passed, with
  // the planned outputs of every upstream instance (one per sweep point of each stage in
  // `from`; empty for a type that declares none). Stages never read another stage's params:
  // they name the product they need and refuse an upstream whose plan lacks it.
  virtual void checkAgainstUpstream(const nlohmann::json& /*resolved*/, const std::string& /*pointer*/,
                                    const std::vector<UpstreamPlan>& /*upstream*/,
                                    core::json::Diagnostics& /*diagnostics*/) const {}
  // The closure tables an instance with these resolved params reads from the workflow database
  // (a continuum stage's `table` closure). The planner puts each table's content hash into the
  // stage key (for a table a tabulate stage in `from` makes, that stage's key stands for it);
  // the executor loads them before the instance runs (StageContext::closureTables).
  [[nodiscard]] virtual std::vector<ClosureTableRef> closureTables(const nlohmann::json& /*resolved*/) const {
    return {};
  }
  // The copies of each instance (one per sweep point) the planner makes: by default the instance
  // alone. Parameters that only ask for copies should not affect results (doesNotAffectResults),
  // so the first copy, with an empty overlay, keeps the key the instance has without them.
  [[nodiscard]] virtual std::vector<Replica> replicas(const nlohmann::json& /*resolved*/) const { return {Replica{}}; }
  // The summary values in which a replica records which copy it is (a closure sample's
  // closure_sample and closure_perturbed): a report shows them beside the sweep point.
  [[nodiscard]] virtual std::vector<std::string> replicaSummaryKeys() const { return {}; }
  // The parameter (below the stage's /params) that needs the standard errors of the closure
  // tables the instance reads, when one does (closure samples draw within them); "" otherwise.
  // The planner refuses a database table without errors naming it, before any work starts.
  [[nodiscard]] virtual std::string tableErrorsNeededBy(const nlohmann::json& /*resolved*/) const { return ""; }
  // Checks a closure input this instance reads (closureTables) against the grains it was made
  // from, as the database records them or the plan of the tabulate stage in `from` that makes it
  // says: called at config load, so a rheology of other grains is refused before any work.
  virtual void checkTableGrains(const nlohmann::json& /*resolved*/, const std::string& /*pointer*/,
                                const ClosureTableRef& /*ref*/, const Grains& /*grains*/,
                                core::json::Diagnostics& /*diagnostics*/) const {}
  // The summary values a report shows as columns and plots, in order; every summary value is in
  // the stage's CSV regardless. Empty: the report shows the summary values that vary (no plots,
  // as their units are not declared).
  [[nodiscard]] virtual std::vector<ResultColumn> keyResults() const { return {}; }
  // Whether an instance can run on several ranks (ranks_per_instance > 1): every rank runs run()
  // in step and the stage's engine divides the work (dem on engine lammps). Others run on one
  // rank, and the workflow check refuses more.
  [[nodiscard]] virtual bool runsOnSeveralRanks(const nlohmann::json& /*resolved*/) const { return false; }
  // Runs one instance. Throws grainbridge::Error on failure (the instance is then recorded
  // failed and never cached) or StageInterrupted after a clean stop.
  virtual void run(StageContext& ctx) const = 0;
};

}  // namespace grainbridge::workflows::stages
