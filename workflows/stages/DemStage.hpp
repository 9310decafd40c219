#pragma once
// `dem`: a soft-sphere DEM run (engines/dem; Chapter 6 of the reference). Species are inserted
// at random without overlap and evolve under gravity, contacts and walls; particle + contact
// frames (HDF5 + XDMF) and a per-step series (energies, contacts, coordination, whole-domain
// stress, wall forces, species centres of mass) are written for the extraction layer.
#include "engines/particle_engines/ParticleEngines.hpp"
#include "workflows/stages/StageType.hpp"

namespace grainbridge::workflows::stages {

class DemStage final : public StageType {
 public:
  DemStage();
  [[nodiscard]] std::string name() const override { return "dem"; }
  // 2: series.csv gains top_z_<species> (free surface)
  // 3: the kinetic stress in series.csv takes C about the mean peculiar velocity under Lees-Edwards
  // 4: the Lees-Edwards rebuild counts the offset drift with both displacements
  // 5: the set-up force evaluation keeps the contact history (initial contacts no longer start
  //    with their slip counted twice; LAMMPS does the same); the first frame after a preparation
  //    carries the contacts of its own state; inserted particles start at exactly the asked
  //    initial_temperature (the Maxwellian particle_gas uses, rescaled)
  // 6: frames carry their materials (core/data/Materials), which extract reads instead of params
  // 7: the pair loop takes n, v_n and the history's projection from r_ij and 1 / r^2 (as LAMMPS),
  //    and Eq. 6.4's rescale from a series for small turns: the same equations, rounded
  //    differently in the last bits (a chaotic run then drifts from there)
  // 8: the Lees-Edwards list rebuild counts the peculiar displacement and the shear's distortion
  //    (rebuilds at other steps, so particles are wrapped and re-sorted at others: round-off);
  //    frictionless pairs skip the tangential step (its force was 0 to round-off). Runs without
  //    shear and with friction are unchanged to the bit.
  [[nodiscard]] int implVersion() const override { return 8; }
  [[nodiscard]] std::vector<ResultColumn> keyResults() const override {
    return {{"final_coordination", "–"},
            {"final_contacts", "–"},
            {"final_ke_translational", "J"},
            {"final_ke_rotational", "J"},
            {"steps", "–"}};
  }
  [[nodiscard]] std::string summary() const override {
    return "soft-sphere DEM: random insertion, gravity, frictional contacts with history, walls; frames and series";
  }
  [[nodiscard]] const params::ParamSchema& params() const override { return schema_; }
  [[nodiscard]] InputMode inputMode() const override { return InputMode::None; }
  void checkParams(const nlohmann::json& resolved, const std::string& pointer,
                   core::json::Diagnostics& diagnostics) const override;
  void run(StageContext& ctx) const override;
  [[nodiscard]] std::optional<PlannedOutput> plannedOutput(const nlohmann::json& resolved) const override;
  // LAMMPS divides the box over the instance's ranks; grainbridge's engine runs on one.
  [[nodiscard]] bool runsOnSeveralRanks(const nlohmann::json& resolved) const override {
    return particle_engines::particleEngine(resolved.at("engine").get<std::string>()).severalRanks;
  }

 private:
  params::ParamSchema schema_;
};

}  // namespace grainbridge::workflows::stages
