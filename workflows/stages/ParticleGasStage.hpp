#pragma once
// `particle_gas`: a gas of non-overlapping monodisperse spheres at a given solid fraction in a
// periodic cube, with Maxwellian velocities at a given granular temperature (Eq. 3.38:
// T = <C^2>/3). It is the initial state of the homogeneous-cooling and elastic-gas checks and
// the test input of the kinetic stress of Eq. 2.3 (n m T I), and it exercises the whole
// pipeline (params, sweep, frames, database, report) before the DEM engine lands.
#include "workflows/stages/StageType.hpp"

namespace grainbridge::workflows::stages {

class ParticleGasStage final : public StageType {
 public:
  ParticleGasStage();
  [[nodiscard]] std::string name() const override { return "particle_gas"; }
  // 2: insertion through engines/dem (same statistics, different round-off)
  // 3: frames carry their materials (core/data/Materials)
  [[nodiscard]] int implVersion() const override { return 3; }
  [[nodiscard]] std::vector<ResultColumn> keyResults() const override {
    return {
        {"solid_fraction", "–"}, {"number_density", "1/m³"}, {"box_length", "m"}, {"granular_temperature", "m²/s²"}};
  }
  [[nodiscard]] std::string summary() const override {
    return "random non-overlapping spheres in a periodic cube with Maxwellian velocities (one particle frame)";
  }
  [[nodiscard]] const params::ParamSchema& params() const override { return schema_; }
  [[nodiscard]] InputMode inputMode() const override { return InputMode::None; }
  void run(StageContext& ctx) const override;
  // One frame at t = 0 of n_particles unsheared particles with ids 0..n-1.
  [[nodiscard]] std::optional<PlannedOutput> plannedOutput(const nlohmann::json& resolved) const override {
    PlannedOutput out;
    out.particleFrames = true;
    out.lastFrameTime = 0.0;
    out.leesEdwardsShearRate = 0.0;
    out.particleCount = resolved.at("n_particles").get<std::int64_t>();
    return out;
  }

 private:
  params::ParamSchema schema_;
};

}  // namespace grainbridge::workflows::stages
