#pragma once
// The initial state of a `dem` run and its preparation: random insertion (after placed
// particles), a LAMMPS data file or a saved frame, and Section 6.2's two-step preparation.
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "core/engine/SetupProblem.hpp"
#include "engines/dem/DemEngine.hpp"
#include "workflows/driver/Phase.hpp"
#include "workflows/stages/DemSetup.hpp"
#include "workflows/stages/StageContext.hpp"

namespace grainbridge::workflows::stages {

// How a run's particles are inserted, from the `dem` stage's insert_lo/hi, place, insertion, seed
// and initial_temperature (tfdem writes insert_lo/hi and seed only: its particles start at rest,
// at random), and whether its state is read from a file instead (lammps_data, initial_frame).
struct InsertionChoice {
  std::optional<Vec3> lo, hi;  // insert_lo/hi; none: the box
  struct Placed {
    std::string species;
    Vec3 position;
  };
  std::vector<Placed> place;  // inserted first (ids 0..), then the rest at random
  bool lattice = false;       // insertion "fcc_lattice"
  std::uint64_t seed = 0;
  double initialTemperature = 0.0;  // T0 of the mobile particles' Maxwellian velocities [m^2/s^2]
  bool fromFile = false;            // lammps_data or initial_frame: nothing is inserted
};
void from_json(const nlohmann::json& p, InsertionChoice& c);

// Every species at random without overlap, placed particles first (ids 0..); a stop asked of
// `ctx` ends it.
dem::Particles insertSpecies(const StageContext& ctx, const InsertionChoice& choice, const DemSetup& setup);
// Why the species' counts cannot be inserted at random into their region, or nothing: the
// spheres to insert (placed ones aside) would fill more of it than the solid fraction near which
// random insertion jams (dem::kRandomInsertionJamming), summed over every species since all share
// the region. Nothing for a state read from a file or an fcc lattice. The run would otherwise
// fail at its insertion, after the stages before it ran. `boxKeys` names the box the region
// defaults to as the stage writes it ("box_lo/box_hi").
std::optional<core::engine::SetupProblem> randomInsertionProblem(const InsertionChoice& choice, const DemSetup& setup,
                                                                 const std::string& boxKeys);
// Atoms of a LAMMPS data file, types mapped to species by lammps_types. The file's numbers are in
// the config's unit system, as its bare numbers are (SI, or d0, m0, t0 when reduced).
dem::Particles readLammpsParticles(const nlohmann::json& params, const DemSetup& setup,
                                   const core::units::UnitSystem& units);
// Particles of a saved frame, species by index.
dem::Particles readFrameParticles(const nlohmann::json& params, const DemSetup& setup);
// Section 6.2's two-step preparation as phases of the time loop before the run proper: the
// held species fixed and the container shaken, then left to relax; at the end the held
// particles are released and the run's clock starts. The driver checkpoints and resumes inside
// them like in any phase.
std::vector<driver::Phase> preparationPhases(const StageContext& ctx, const DemSetup& setup, dem::DemEngine& engine);

}  // namespace grainbridge::workflows::stages
