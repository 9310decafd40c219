#include "engines/tfdem/TfdemSetup.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/json/Vec3Json.hpp"
#include "core/text/NumberText.hpp"
#include "engines/closures/DragFromJson.hpp"

namespace grainbridge::tfdem {

using nlohmann::json;

namespace {

// Whether `whole` is a whole number (>= 1) of `part`, to round-off.
bool wholeMultiple(double whole, double part) {
  const double ratio = whole / part;
  return std::llround(ratio) >= 1 && std::abs(ratio - std::round(ratio)) <= 1e-6 * ratio;
}

template <class Enum>
Enum choice(const json& p, const char* key, std::initializer_list<std::pair<const char*, Enum>> options) {
  const std::string value = p.at(key);
  for (const auto& [name, e] : options) {
    if (value == name) return e;
  }
  return options.begin()->second;  // the schema admits only the names above
}

}  // namespace

void from_json(const json& p, TfdemSetup& s) {
  // The gas: grid and patches by the fluid set-up, with the one fixed step fluid_dt (so an inlet
  // faster than the Courant limit at that step is refused there, at fluid_dt).
  auto& f = s.fluid;
  f.cells = p.at("cells").get<std::array<int, 3>>();
  f.lengths = core::json::vec3FromJson(p.at("lengths"));
  f.boundaries = p.at("boundaries").get<std::vector<fluid::PatchSetup>>();
  const double fluidDt = p.at("fluid_dt");
  f.timeStep.initial = f.timeStep.minimum = f.timeStep.maximum = fluidDt;
  f.timeStep.courant = p.at("courant");
  f.fixedStepKey = "fluid_dt";
  s.grid = f.geometry();
  if (f.problems(1, 1.0).empty()) s.boundaries = f.patches(1);
  s.gas = {p.at("gas_density").get<double>(), p.at("gas_viscosity").get<double>()};
  s.drag = closures::dragFromJson(p);
  s.deposition = choice(p, "deposition",
                        {std::pair{"centre_cell", VolumeDeposition::CentreCell},
                         std::pair{"exact_overlap", VolumeDeposition::ExactOverlap}});
  s.gasReaction =
      choice(p, "gas_reaction",
             {std::pair{"cell_average", GasReaction::CellAverage}, std::pair{"summed", GasReaction::Summed}});
  s.forces.transfer = choice(
      p, "drag_transfer",
      {std::pair{"cell_average", DragTransfer::CellAverage}, std::pair{"per_particle", DragTransfer::PerParticle}});
  s.forces.gasVelocity = choice(
      p, "gas_velocity", {std::pair{"cell", GasVelocity::Cell}, std::pair{"interpolated", GasVelocity::Interpolated}});
  s.solver.phaseNames = {"gas", "particles"};
  s.solver.gravity = core::json::vec3FromJson(p.at("gravity"));
  s.solver.tolerance = p.at("tolerance");
  s.solver.maxIterations = p.at("max_iterations");
  s.solver.momentumRelaxation = p.at("momentum_relaxation");
  s.solver.pressureRelaxation = p.at("pressure_relaxation");
  s.solver.momentumSolve = fluid::linearSolveFromJson(p, "momentum");
  // The incompressible gas's pressure correction is symmetric positive definite (an outlet fixes
  // its level): the band Cholesky, half the LU's work.
  s.solver.pressureSolve.method = fluid::LinearSolve::Method::Cholesky;
  // A gas step is `substeps` DEM steps (problems() refuses a fluid_dt that is not a whole number).
  s.particles.dt = p.at("dt");
  s.substeps = static_cast<int>(std::max<long long>(1, std::llround(fluidDt / s.particles.dt)));
}

std::vector<SetupProblem> TfdemSetup::problems() const {
  std::vector<SetupProblem> found = fluid.problems(1, 1.0);
  auto problem = [&found](std::string where, std::string what) {
    found.push_back({std::move(where), std::move(what)});
  };
  for (auto& why : fluid::linearSolveProblems(solver.momentumSolve, "momentum")) found.push_back(std::move(why));
  for (std::size_t k = 0; k < fluid.boundaries.size(); ++k) {
    const auto& b = fluid.boundaries[k];
    for (const auto& [key, list] :
         {std::pair{"solids_fractions", &b.solidsFractions}, std::pair{"solids_inflow", &b.solidsInflow}}) {
      if (!list->empty())
        problem("/boundaries/" + std::to_string(k) + "/" + key,
                "TF-DEM particles are inserted as particles and stay in the domain; a gas patch carries none");
    }
  }
  if (auto why = closures::dragProblem(drag)) found.push_back(std::move(*why));
  const double fluidStep = fluid.timeStep.initial, dt = particles.dt;
  if (!wholeMultiple(fluidStep, dt)) {
    problem("/fluid_dt", "fluid_dt = " + core::humanNumber(fluidStep) + " s is not a whole number of DEM steps dt = " +
                             core::humanNumber(dt) + " s (a gas step is n DEM steps)");
  }

  const auto& species = materials.species;
  double dMax = 0.0;
  for (const auto& sp : species) dMax = std::max(dMax, sp.diameter);
  // A 2D bed is one layer of equal spheres one diameter deep, moving in x-y.
  const bool twoD = fluid.twoD();
  const Vec3& lengths = fluid.lengths;
  const Vec3& gravity = solver.gravity;
  const double d0 = species.empty() ? 0.0 : species[0].diameter;
  if (twoD) {
    if (std::abs(lengths.z() - d0) > 1e-9 * d0) {
      problem("/lengths/2", "a 2D bed (cells along z is 1) is one particle diameter deep: lengths z must be d = " +
                                core::humanNumber(d0) + " m, found " + core::humanNumber(lengths.z()) + " m");
    }
    for (std::size_t k = 1; k < species.size(); ++k) {
      if (species[k].diameter != d0)
        problem("/species/" + std::to_string(k) + "/diameter",
                "a 2D bed is one layer of equal spheres: every species needs the first's diameter " +
                    core::humanNumber(d0) + " m");
    }
    if (particles.planarAxis != 2)
      problem("/planar", "a 2D bed moves in x-y: planar must be \"z\" (or left out), found \"" +
                             std::string(1, static_cast<char>('x' + particles.planarAxis)) + "\"");
    if (gravity.z() != 0.0)
      problem("/gravity/2",
              "a 2D bed moves in x-y: gravity must have no z part, found " + core::humanNumber(gravity.z()) + " m/s2");
  }
  // A cell must hold what it is given: a particle deposited whole on the cell of its centre
  // fills a cell of edge below 2 d past its volume in a dense bed (eps_g <= 0); with the exact
  // overlap a particle spreads over the cells it cuts, which needs an edge of at least d.
  const bool centreCell = deposition == VolumeDeposition::CentreCell;
  for (int a = 0; a < (twoD ? 2 : 3); ++a) {
    const double h = lengths[a] / fluid.cells[static_cast<std::size_t>(a)];
    const double least = (centreCell ? 2.0 : 1.0) * dMax;
    if (h < least) {
      problem("/cells/" + std::to_string(a),
              "the cell edge " + core::humanNumber(h) + " m is below " + (centreCell ? "2 d" : "d") + " = " +
                  core::humanNumber(least) + " m with deposition " + (centreCell ? "centre_cell" : "exact_overlap") +
                  (centreCell ? ": a cell could hold more particle volume than its own (eps_g <= 0)"
                              : ": a particle would cut more than two cells along an axis") +
                  "; use fewer cells" + (centreCell ? " or exact_overlap" : ""));
    }
  }
  return found;
}

}  // namespace grainbridge::tfdem
