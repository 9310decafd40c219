#pragma once
// The initial state of a multi-fluid run as MFiX's IC regions give it: boxes, later ones over
// earlier ones, each setting the solids fractions (the gas takes the rest) and each phase's
// velocity in the cells whose centres lie inside; then the gas pressure from the outlet down,
// each cell carrying the weight of the mixture above it (a bed starts at rest on its gas, not
// falling through it). A seeded perturbation of the solids fraction breaks the symmetry of a
// uniform bed between free-slip walls, which would otherwise stay one-dimensional and slug as a
// piston.
#include <cstddef>
#include <cstdint>
#include <nlohmann/json.hpp>
#include <vector>

#include "core/Types.hpp"
#include "core/data/FieldFrame.hpp"
#include "core/engine/SetupProblem.hpp"
#include "engines/fluid/FluidSetup.hpp"
#include "engines/mfm/MultiFluidEngine.hpp"

namespace grainbridge::mfm {

struct InitialRegion {
  Vec3 lo = Vec3::Zero(), hi = Vec3::Zero();  // [m]
  std::vector<double> solidsFractions;        // per solids phase
  std::vector<Vec3> velocities;               // per phase, the gas first [m/s]
  double granularTemperature = 0.0;           // theta of every solids phase [m^2/s^2]
};

struct InitialState {
  std::vector<InitialRegion> regions;
  double referencePressure = 101325.0;  // at the top of the domain (against gravity) [Pa]
  double perturbation = 0.0;            // relative amplitude, solids fractions only lowered
  std::uint64_t seed = 1;

  // Every reason these regions cannot start `solidsPhases` solids phases in `domain`, each at the
  // JSON pointer of its key ("/regions/1/hi"): a fraction count other than the phases', solids
  // above the packed fraction, a box partly outside the domain (a 2D grid's z against its depth),
  // a box that holds no cell centre (lo above hi, lo = hi, or between two centres).
  // Empty when the run can start.
  [[nodiscard]] std::vector<core::engine::SetupProblem> problems(
      const core::data::GridGeometry& domain, std::size_t solidsPhases,
      const fluid::FluidSetup::PackedFraction& packedFraction) const;
  // The same with one packed fraction for every composition.
  [[nodiscard]] std::vector<core::engine::SetupProblem> problems(const core::data::GridGeometry& domain,
                                                                 std::size_t solidsPhases, double packedFraction) const {
    return problems(domain, solidsPhases, [packedFraction](std::span<const double>) { return packedFraction; });
  }
};

// The JSON form uses the `mfm` stage's keys: regions (lo, hi, solids_fractions, gas_velocity,
// solids_velocity, granular_temperature), reference_pressure, perturbation, seed. A region gives
// every solids phase one velocity, as the stage does.
void to_json(nlohmann::json& j, const InitialRegion& r);
void from_json(const nlohmann::json& j, InitialRegion& r);
void to_json(nlohmann::json& j, const InitialState& s);
void from_json(const nlohmann::json& j, InitialState& s);

// Cells no region covers are gas at rest.
void initialise(MultiFluidEngine& engine, const InitialState& initial);

// The regions' part of initialise() alone: every cell's fractions (perturbed), granular
// temperatures and velocities; the pressure is left as it is. What the initial bed holds
// (InitialBed.hpp) is read from these without building an engine.
void applyRegions(fluid::FlowState& state, const InitialState& initial);

}  // namespace grainbridge::mfm
