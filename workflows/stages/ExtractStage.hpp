#pragma once
// `extract`: the micro-to-macro step, as wiring. Reads the particle frames of one upstream
// instance through core's data model (their materials included: core/data/Materials), picks the
// frames after a start time or strain, averages each over the whole domain once, and feeds them
// to the analyses its parameters ask for, each an observer in extract/observe: the closure point
// (Eq. 2.3 stress, Eq. 3.38 temperature, solid fraction, coordination, dissipation rate, time-
// averaged with block errors, closure forms), coarse-grained fields, force networks and the
// multi-pass MST (structure_statistics), force statistics pooled over the frames, and the height
// of chosen particles against the local free surface (surface.csv, the Brazil-nut criterion).
#include "workflows/stages/StageType.hpp"

namespace grainbridge::workflows::stages {

class ExtractStage final : public StageType {
 public:
  ExtractStage();
  [[nodiscard]] std::string name() const override { return "extract"; }
  // 2: time-averaged fields (mean/); 3: network extent also in smallest-grain diameters,
  // velocity statistics over every frame, no failure when no frame has a contact; 4: under
  // Lees-Edwards shear the dissipation rate is the shear work (frictional sliding losses included);
  // 5: every CSV at full precision (was 12 significant digits); 6: the contact-to-drag ratio;
  // 7: a sheared point's inertial number and stress ratio; 8: the solid fraction's error in the summary
  // 9: a mixture's species and species-pair points (issue 60)
  // 10: block-averaging errors never from a level of fewer than 4 blocks (issue 63)
  // 11: block errors extrapolated to the plateau; theta forms' errors and correlations from the
  //     linearised frame series; error_warning (issue 63)
  // 12: the bond-orientational order and crystalline share per frame, the point's ordered flag
  //     (issue 61)
  [[nodiscard]] int implVersion() const override { return 12; }
  // The state and the closure forms (shear-scaled, then theta-scaled: core/ClosureForms).
  [[nodiscard]] std::vector<ResultColumn> keyResults() const override {
    return {{"solid_fraction", "–"}, {"restitution", "–"}, {"friction", "–"},  {"p_shear", "–"}, {"tau_shear", "–"},
            {"t_shear", "–"},        {"p_theta", "–"},     {"eta_theta", "–"}, {"j_theta", "–"}};
  }
  [[nodiscard]] std::string summary() const override {
    return "closure point (stress, temperature, dissipation, ...) and structure statistics from particle frames";
  }
  [[nodiscard]] const params::ParamSchema& params() const override { return schema_; }
  [[nodiscard]] InputMode inputMode() const override { return InputMode::PerInstance; }
  // A gaussian/lucy kernel's width, the grid's size, an empty window: before any upstream work.
  void checkParams(const nlohmann::json& resolved, const std::string& pointer,
                   core::json::Diagnostics& diagnostics) const override;
  // The averaging window and surface_particles against what each upstream run will produce.
  void checkAgainstUpstream(const nlohmann::json& resolved, const std::string& pointer,
                            const std::vector<UpstreamPlan>& upstream,
                            core::json::Diagnostics& diagnostics) const override;
  void run(StageContext& ctx) const override;
  // A closure point unless closure_point is false (closure_points; its summary holds the state
  // and the closure forms).
  [[nodiscard]] std::optional<PlannedOutput> plannedOutput(const nlohmann::json& resolved) const override {
    PlannedOutput out;
    out.closurePoint = resolved.at("closure_point").get<bool>();
    return out;
  }

 private:
  params::ParamSchema schema_;
};

}  // namespace grainbridge::workflows::stages
