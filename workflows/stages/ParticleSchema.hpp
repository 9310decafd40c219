#pragma once
// The particle keys the stages that run the DEM share (`dem`, and `tfdem` with the gas around the
// particles): species, the contact coefficients of pairs and walls under the contact law's
// sub-models, and the rules between them, each written once here so both stages refuse the same
// input with the same message at the same pointer below their params.
#include <memory>
#include <nlohmann/json.hpp>
#include <string>

#include "core/engine/SetupProblem.hpp"
#include "core/json/Diagnostics.hpp"
#include "workflows/params/ParamSchema.hpp"
#include "workflows/stages/DemSetup.hpp"

namespace grainbridge::workflows::stages {

// The contact law's sub-models: normal_model, damping_model, tangential_model.
void addContactModelParams(params::ParamSchema& s);

// The contact coefficients of particle pairs and walls (Eqs. 6.5-6.6, Table 6.1): kn or
// contact_time, kt, one normal damping (gamma_n, eta_n or restitution), impact_velocity, the
// tangential damping, mu.
void addContactParams(params::ParamSchema& s);

// The damping keys contact object `c` (at `where`) may carry under the stage's damping_model, and
// that a Hertzian restitution or contact time is given what it depends on. `p` holds the stage's
// normal_model, damping_model and tangential_model.
[[nodiscard]] std::vector<core::engine::SetupProblem> checkContactKeys(const nlohmann::json& c, const nlohmann::json& p,
                                                                       const std::string& where);

// species (required), contact (required) and pair_contacts, in this order: the particles and
// their contact coefficients as every stage that runs the DEM declares them.
void addSpeciesParams(params::ParamSchema& s);
// What addSpeciesParams' keys cannot be, each at its pointer below /params: a species name used
// twice, a contact object (`contact`, each of pair_contacts) with keys its damping model does not
// take, a pair contact naming no species.
[[nodiscard]] std::vector<core::engine::SetupProblem> checkSpeciesParams(const nlohmann::json& p);
// skin: the Verlet skin in largest diameters; seed: the random seed of the insertion.
params::ParamSpec skinParam();
params::ParamSpec seedParam();

// A species: name, diameter, density, count, frozen.
std::shared_ptr<params::ParamSchema> speciesSchema();
// One set of contact coefficients (the `contact` key, a wall's material).
std::shared_ptr<params::ParamSchema> contactSchema();
// The coefficients of one species pair (species, with, and the contact keys).
std::shared_ptr<params::ParamSchema> pairContactSchema();

// Every pair must rebound (not overdamped) and be resolved in time: dt <= t_c/10 (Eq. 6.10).
// Pointers are the timings' own, below /params.
[[nodiscard]] std::vector<core::engine::SetupProblem> checkContactTimes(const DemSetup& setup, double dt);

}  // namespace grainbridge::workflows::stages
