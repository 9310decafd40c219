#pragma once
// `tabulate`: closure points -> named closure tables a continuum engine can load
// (core::ClosureTable through db::ClosureStore::loadTable). Gathers extract instances, keeps the
// points of one friction, and lays the theta-scaled forms p/(rho_p theta), mu/(rho_p d
// sqrt(theta)) and J d/(rho_p theta^(3/2)) (DESIGN.md "Closures") on the grid of the points'
// solid fractions [x restitutions]. Every grid node needs exactly one point: a missing or
// doubled state is an error naming it, because an engine interpolating across a hole would
// silently invent a closure there. Sheared points also give the dense-flow rheology, mu(I) and
// phi(I) with their fits, per restitution (TabulateRheology).
#include "workflows/stages/StageType.hpp"

namespace grainbridge::workflows::stages {

class TabulateStage final : public StageType {
 public:
  TabulateStage();
  [[nodiscard]] std::string name() const override { return "tabulate"; }
  // 2: table CSV at full precision (17 significant digits, was 12)
  // 3: the mu(I) and phi(I) tables and fits (rheology records, TabulateRheology)
  // 4: each table keeps its nodes' correlations with the other theta forms (issue 63)
  // 5: points whose box ordered are left out unless keep_ordered; mu(I) and phi(I) also as
  //    power laws near the critical point, with the better form by chi2/dof (issue 61)
  // 6: a power law whose exponent runs to 0 is reported as no fit, with the reason
  [[nodiscard]] int implVersion() const override { return 6; }
  [[nodiscard]] std::string summary() const override {
    return "closure tables (p_theta, eta_theta, j_theta against solid fraction [and restitution]) from closure "
           "points";
  }
  [[nodiscard]] const params::ParamSchema& params() const override { return schema_; }
  [[nodiscard]] InputMode inputMode() const override { return InputMode::Gather; }
  // The tables it makes are named by `table` (a continuum stage downstream reads them). A species'
  // table of a mixture is not offered: the multi-fluid model's tables are of one phase.
  [[nodiscard]] std::optional<PlannedOutput> plannedOutput(const nlohmann::json& resolved) const override {
    PlannedOutput out;
    if (resolved.value("species", std::string()).empty()) out.closureTables = resolved.at("table").get<std::string>();
    return out;
  }
  // second_variable volume_share needs a species.
  void checkParams(const nlohmann::json& resolved, const std::string& pointer,
                   core::json::Diagnostics& diagnostics) const override;
  // Every upstream must record closure points (extract's plannedOutput says so).
  void checkAgainstUpstream(const nlohmann::json& resolved, const std::string& pointer,
                            const std::vector<UpstreamPlan>& upstream,
                            core::json::Diagnostics& diagnostics) const override;
  void run(StageContext& ctx) const override;

 private:
  params::ParamSchema schema_;
};

}  // namespace grainbridge::workflows::stages
