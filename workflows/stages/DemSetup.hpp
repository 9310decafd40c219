#pragma once
// Turns the `dem` stage's resolved parameters (SI) into the engine's setup: per species-pair and
// per wall-species materials (restitution converted with each pair's m_eff, contact/Conversions.hpp),
// walls,
// and the list of problems that must stop a run before its first step (overdamped pairs, a time
// step above t_c/10). Shared by the stage's config check and its run, so both see the same
// numbers.
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "core/data/Materials.hpp"
#include "engines/dem/Simulation.hpp"

namespace grainbridge::workflows::stages {

struct DemSpecies {
  std::string name;
  double radius;
  double mass;
  std::int64_t count;
  bool frozen;
};

struct PairTiming {
  std::string pair;     // "small-large", "small-wall 0"
  std::string pointer;  // JSON pointer of the material that sets it, relative to /params
  double restitution;   // of a head-on collision (Eq. 6.9 for a linear spring)
  double contactTime;   // Eq. 6.10 for a linear spring; +inf when overdamped
  bool exact;           // false: a Hertzian pair without impact_velocity, given the linear spring's
};

struct DemSetup {
  dem::SimulationSetup engine;
  std::vector<DemSpecies> species;
  std::vector<PairTiming> timings;
  std::vector<std::int64_t> trackedIds;  // particles whose height the series records
  // What every frame carries for its readers (core/data/Materials): species, the coefficients
  // of each species pair and wall, gravity.
  core::data::Materials materials;
};

// Builds the setup; assumes individually valid parameters.
DemSetup makeDemSetup(const nlohmann::json& params);
// The solid fraction the species' counts fill in box_lo/box_hi's box (a compressed box holds it).
double speciesSolidFraction(const nlohmann::json& params);

// The particles alone, from the keys the dem and tfdem stages share (ParticleSchema.hpp: species,
// contact, pair_contacts, skin, dt and the contact sub-models): species, pair materials and their
// timings, the frames' species and pairs. The box, gravity and walls are the caller's.
DemSetup makeParticleSetup(const nlohmann::json& params);

// Appends `wall` with one material per species from the contact keys `contact` (a wall object, or
// a material written once for several walls), its timings at `pointer` (below /params).
void addWall(DemSetup& setup, dem::Wall wall, const nlohmann::json& contact, const std::string& pointer);

}  // namespace grainbridge::workflows::stages
