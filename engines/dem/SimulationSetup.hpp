#pragma once
// The DEM engine's parameters, declared next to the engine (STYLE.md 6): what Simulation runs
// with, in SI, contact coefficients already derived per pair (Material.hpp). Its JSON form uses
// the keys of the `dem` stage's params where the two coincide (box_lo, box_hi, periodic,
// gravity, shear_rate, dt, skin, planar, ...), so a problem found here is reported at the JSON
// pointer of the key the user wrote, and the engine and the stage check each rule once, here.
#include <array>
#include <cstdint>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "core/Types.hpp"
#include "core/engine/SetupProblem.hpp"
#include "engines/dem/Material.hpp"
#include "engines/dem/Walls.hpp"
#include "engines/dem/contact/ContactModels.hpp"

namespace grainbridge::dem {

using core::engine::SetupProblem;

struct SimulationSetup {
  Vec3 lo = Vec3::Zero();
  Vec3 hi = Vec3::Ones();
  std::array<bool, 3> periodic{false, false, false};
  Vec3 gravity = Vec3::Zero();
  double backgroundDamping = 0.0;  // b of Eq. 6.7 [kg/s]
  // Lees-Edwards simple shear when non-zero: streaming velocity u_x = shearRate (y - y_mid); the
  // periodic image above (y + L_y) is displaced by the offset shearRate L_y t (mod L_x) in x and
  // moves with + shearRate L_y. Needs x and y periodic.
  double shearRate = 0.0;
  // Pressure-controlled Lees-Edwards shear (issue 30) when `stress` > 0: every `interval` steps
  // the box length along the gradient (y) is scaled, positions with it, by
  //   L_y <- L_y (1 + (interval dt / relaxationTime) clamp((<p_yy> - stress) / stress, -1, 1)),
  // <p_yy> the mean normal stress of Eq. 2.3 over those steps. A first-order relaxation of ln L_y
  // towards the target with time constant relaxationTime; the clamp bounds the box's strain rate
  // at 1/relaxationTime however far p_yy is from the target (a dilute start, or a jammed one).
  struct PressureControl {
    double stress = 0.0;          // target p_yy [Pa]
    double relaxationTime = 0.0;  // [s]
    int interval = 10;            // steps between box adjustments
    [[nodiscard]] bool active() const { return stress > 0.0; }
  } pressureControl;
  // Compression to a fixed solid fraction (issue 60) when `solidFraction` > 0: a Lees-Edwards box
  // whose length along the gradient (y) shrinks linearly in time, positions scaled with it as
  // pressure control scales them, from the length it started with to the one at which its
  // particles fill `solidFraction` of it, reached at `duration` and held from then on. The start
  // of fixed-volume dense states that random insertion cannot reach (it jams near 0.38) and an
  // fcc lattice of a mixture cannot (its spacing is the largest grain's).
  struct Compression {
    double solidFraction = 0.0;  // the fraction held after `duration`
    double duration = 0.0;       // [s] from the start of the run
    int interval = 10;           // steps between box changes
    [[nodiscard]] bool active() const { return solidFraction > 0.0; }
  } compression;
  // Whether the box length along y changes during the run (pressure control or compression).
  [[nodiscard]] bool boxMovesAlongY() const { return pressureControl.active() || compression.active(); }
  // Planar mode for 2-D beds (one particle layer): no motion along this axis (0, 1, 2) and
  // rotation about it only; -1 for full 3-D.
  int planarAxis = -1;
  double dt = 0.0;
  double skin = 0.0;  // Verlet skin [m]
  contact::ContactChoice contact;  // the contact law's sub-models (contact/ContactModels.hpp)
  int species = 1;
  std::vector<PairMaterial> pairMaterial;  // species x species, row-major, symmetric
  std::vector<Wall> walls;
  int sortEveryRebuilds = 20;  // re-sort particles by cell every this many rebuilds (0: never)
  // Set by TF-DEM (not a key of the dem stage): the gas's pressure-gradient force applies
  // (BodyForces.hpp: FluidPressure), so a plain DEM run's steps do not read its array.
  bool fluidCoupled = false;

  [[nodiscard]] const PairMaterial& material(int a, int b) const {
    return pairMaterial[static_cast<std::size_t>(a * species + b)];
  }

  // Every reason this setup cannot run grains up to `largestDiameter` across: a box that is
  // empty along an axis, a periodic length that would need two images of one neighbour, shear
  // without the periodic axes it needs, a neighbour grid too large to allocate, missing
  // materials, and (when `insertedParticles` is known: no state is read from a file) a run
  // without a single particle. Empty when it can run.
  [[nodiscard]] std::vector<SetupProblem> problems(double largestDiameter,
                                                   std::optional<std::int64_t> insertedParticles = std::nullopt) const;
};

// The interaction range of the neighbour list: the largest contact distance plus the skin.
[[nodiscard]] inline double interactionRange(double largestDiameter, double skin) { return largestDiameter + skin; }

void to_json(nlohmann::json& j, const SimulationSetup& s);
void from_json(const nlohmann::json& j, SimulationSetup& s);

}  // namespace grainbridge::dem
