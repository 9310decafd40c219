#include "workflows/stages/TfdemSetup.hpp"

#include <algorithm>
#include <cmath>
#include <set>

#include "core/json/Vec3Json.hpp"
#include "core/text/NumberText.hpp"
#include "engines/fluid/FluidSetup.hpp"
#include "workflows/driver/Phase.hpp"
#include "workflows/stages/DemInitialState.hpp"
#include "workflows/stages/DragSetup.hpp"
#include "workflows/stages/FluidSchema.hpp"
#include "workflows/stages/OutputSchedule.hpp"
#include "workflows/stages/ParticleSchema.hpp"

namespace grainbridge::workflows::stages {

using nlohmann::json;

namespace {

// Whether `whole` is a whole number (>= 1) of `part`, to round-off.
bool wholeMultiple(double whole, double part) {
  const double ratio = whole / part;
  return std::llround(ratio) >= 1 && std::abs(ratio - std::round(ratio)) <= 1e-6 * ratio;
}

// The `dem` stage's params for these particles: the gas's domain as the box, plane walls of the
// `wall` material (default: `contact`) on every side it has (a planar bed's z sides need none:
// nothing moves along z), random insertion.
json demParamsOf(const json& p, bool twoD) {
  json d;
  d["box_lo"] = json::array({0.0, 0.0, 0.0});
  d["box_hi"] = p.at("lengths");
  d["periodic"] = "";
  d["gravity"] = p.at("gravity");
  d["background_damping"] = 0.0;
  d["shear_rate"] = 0.0;
  d["track_ids"] = json::array();
  d["planar"] = twoD ? std::string("z") : p.at("planar").get<std::string>();
  d["insertion"] = "random";
  d["initial_temperature"] = 0.0;
  for (const char* key : {"dt", "skin", "seed", "species", "contact", "normal_model", "damping_model",
                          "tangential_model", "pair_contacts", "insert_lo", "insert_hi"}) {
    if (p.contains(key)) d[key] = p.at(key);
  }
  const json& material = p.contains("wall") ? p.at("wall") : p.at("contact");
  json walls = json::array();
  for (int a = 0; a < (twoD ? 2 : 3); ++a) {
    for (int side = 0; side < 2; ++side) {
      json w = material;
      json point = json::array({0.0, 0.0, 0.0}), direction = json::array({0.0, 0.0, 0.0});
      if (side == 1) point[a] = p.at("lengths")[a];
      direction[a] = side == 0 ? 1.0 : -1.0;
      w["kind"] = "plane";
      w["point"] = point;
      w["direction"] = direction;
      w["radius"] = 0.0;
      w["vibration_amplitude"] = 0.0;
      w["vibration_frequency"] = 0.0;
      w["vibration_direction"] = json::array({0, 0, 1});
      w["vibration_start"] = "mid_stroke";
      walls.push_back(std::move(w));
    }
  }
  d["walls"] = std::move(walls);
  return d;
}

// A DEM set-up problem's pointer as the tfdem params name it: the box is the gas's domain, every
// wall is of the one wall material.
std::string tfdemPointer(const std::string& demPointer, const json& p) {
  if (demPointer.starts_with("/box_hi") || demPointer.starts_with("/box_lo")) return "/lengths";
  if (demPointer.starts_with("/walls")) return p.contains("wall") ? "/wall" : "/contact";
  return demPointer;
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

TfdemStageSetup makeTfdemSetup(const json& p) {
  TfdemStageSetup s;
  auto& problems = s.problems;
  auto& e = s.engine;
  const std::array<int, 3> cells = p.at("cells").get<std::array<int, 3>>();
  const Vec3 lengths = core::json::vec3FromJson(p.at("lengths"));
  const bool twoD = cells[2] == 1;
  const Vec3 gravity = core::json::vec3FromJson(p.at("gravity"));
  const double dt = p.at("dt"), fluidDt = p.at("fluid_dt");

  // The gas: grid and patches by the fluid set-up, with the one fixed step fluid_dt (so an inlet
  // faster than the Courant limit at that step is refused there, at fluid_dt).
  fluid::FluidSetup fluidSetup;
  fluidSetup.cells = cells;
  fluidSetup.lengths = lengths;
  fluidSetup.boundaries = p.at("boundaries").get<std::vector<fluid::PatchSetup>>();
  fluidSetup.timeStep.initial = fluidSetup.timeStep.minimum = fluidSetup.timeStep.maximum = fluidDt;
  fluidSetup.timeStep.courant = p.at("courant");
  fluidSetup.fixedStepKey = "fluid_dt";
  const std::size_t before = problems.size();
  for (auto& problem : fluidSetup.problems(1, 1.0)) problems.push_back(std::move(problem));
  for (std::size_t k = 0; k < fluidSetup.boundaries.size(); ++k) {
    const auto& b = fluidSetup.boundaries[k];
    for (const auto& [key, list] : {std::pair{"solids_fractions", &b.solidsFractions},
                                    std::pair{"solids_inflow", &b.solidsInflow}}) {
      if (!list->empty())
        problems.emplace_back("/boundaries/" + std::to_string(k) + "/" + key,
                     "TF-DEM particles are inserted as particles and stay in the domain; a gas patch carries none");
    }
  }
  e.grid = fluidSetup.geometry();
  if (problems.size() == before) e.boundaries = fluidSetup.patches(1);
  e.gas = {p.at("gas_density").get<double>(), p.at("gas_viscosity").get<double>()};
  e.drag = dragFromParams(p, [&problems](const std::string& key, const std::string& why) { problems.emplace_back(key, why); });
  e.deposition = choice(p, "deposition", {std::pair{"centre_cell", tfdem::VolumeDeposition::CentreCell},
                                          std::pair{"exact_overlap", tfdem::VolumeDeposition::ExactOverlap}});
  e.gasReaction = choice(p, "gas_reaction", {std::pair{"cell_average", tfdem::GasReaction::CellAverage},
                                             std::pair{"summed", tfdem::GasReaction::Summed}});
  e.forces.transfer = choice(p, "drag_transfer", {std::pair{"cell_average", tfdem::DragTransfer::CellAverage},
                                                  std::pair{"per_particle", tfdem::DragTransfer::PerParticle}});
  e.forces.gasVelocity = choice(p, "gas_velocity", {std::pair{"cell", tfdem::GasVelocity::Cell},
                                                    std::pair{"interpolated", tfdem::GasVelocity::Interpolated}});
  e.solver.phaseNames = {"gas", "particles"};
  e.solver.gravity = gravity;
  e.solver.tolerance = p.at("tolerance");
  e.solver.maxIterations = p.at("max_iterations");
  e.solver.momentumRelaxation = p.at("momentum_relaxation");
  e.solver.pressureRelaxation = p.at("pressure_relaxation");
  e.solver.momentumSolve = readLinearSolve(p, "momentum");
  // The incompressible gas's pressure correction is symmetric positive definite (an outlet fixes
  // its level): the band Cholesky, half the LU's work.
  e.solver.pressureSolve.method = fluid::LinearSolve::Method::Cholesky;
  s.initialGasVelocity = core::json::vec3FromJson(p.at("initial_gas_velocity"));
  for (const auto& b : fluidSetup.boundaries) {
    if (b.kind == "pressure_outlet") {
      s.initialPressure = b.pressure;
      break;
    }
  }

  // The schedule: fluid_dt a whole number of DEM steps, the output interval of gas steps.
  if (!wholeMultiple(fluidDt, dt)) {
    problems.emplace_back("/fluid_dt", "fluid_dt = " + core::humanNumber(fluidDt) + " s is not a whole number of DEM steps dt = " +
                                  core::humanNumber(dt) + " s (a gas step is n DEM steps)");
  }
  e.substeps = static_cast<int>(std::max<long long>(1, std::llround(fluidDt / dt)));
  s.duration = p.at("duration");
  s.outputInterval = p.at("output_interval");
  s.averageFrom = p.at("average_from");
  s.settleDuration = p.at("settle_duration");
  if (!wholeMultiple(s.outputInterval, fluidDt)) {
    problems.emplace_back("/output_interval", "output_interval = " + core::humanNumber(s.outputInterval) +
                                         " s is not a whole number of gas steps fluid_dt = " +
                                         core::humanNumber(fluidDt) + " s");
  }
  if (s.outputInterval > s.duration) problems.emplace_back("/output_interval", "is longer than the run (duration)");
  if (const auto why = outputIntervalProblem(s.outputInterval, s.duration, fluidDt, "gas steps fluid_dt");
      !why.empty())
    problems.emplace_back("/output_interval", why);
  s.averageTo = p.contains("average_to") ? p.at("average_to").get<double>() : s.duration;
  if (s.averageFrom >= s.duration) problems.emplace_back("/average_from", "must be before the end of the run (duration)");
  if (s.averageTo > s.duration * (1.0 + 1e-12)) problems.emplace_back("/average_to", "is after the end of the run (duration)");
  if (s.averageTo <= s.averageFrom) problems.emplace_back("/average_to", "must be after average_from");
  // A row every output_interval: the run is a whole number of rows of a whole number of gas steps
  // each (both checked above), so the driver's evenly spaced rows fall on exactly those steps.
  s.seriesRows = std::max<std::int64_t>(1, std::llround(s.duration / s.outputInterval));
  s.steps = s.seriesRows * std::max<std::int64_t>(1, std::llround(s.outputInterval / fluidDt));
  s.settleSteps = std::llround(s.settleDuration / fluidDt);
  // Frames fall on gas steps (the run phase's steps), not on series rows.
  if (const auto why = driver::framesProblem(p.at("frames").get<std::int64_t>(), s.steps,
                                             std::to_string(s.steps) + " gas steps (duration " +
                                                 core::humanNumber(s.duration) + " s / fluid_dt " +
                                                 core::humanNumber(fluidDt) + " s)");
      !why.empty())
    problems.emplace_back("/frames", why);

  // The particles: species, contacts and walls through the `dem` stage's set-up.
  std::set<std::string> names;
  const json& species = p.at("species");
  double dMax = 0.0;
  std::int64_t count = 0;
  for (std::size_t k = 0; k < species.size(); ++k) {
    if (!names.insert(species[k].at("name").get<std::string>()).second)
      problems.emplace_back("/species/" + std::to_string(k) + "/name", "species name used twice");
    dMax = std::max(dMax, species[k].at("diameter").get<double>());
    count += species[k].at("count").get<std::int64_t>();
  }
  auto append = [&problems](std::vector<core::engine::SetupProblem> more) {
    for (auto& problem : more) problems.push_back(std::move(problem));
  };
  append(checkContactKeys(p.at("contact"), p, "/contact"));
  if (p.contains("wall")) append(checkContactKeys(p.at("wall"), p, "/wall"));
  if (p.contains("pair_contacts")) {
    for (std::size_t k = 0; k < p["pair_contacts"].size(); ++k) {
      const json& pc = p["pair_contacts"][k];
      const std::string where = "/pair_contacts/" + std::to_string(k);
      append(checkContactKeys(pc, p, where));
      for (const char* f : {"species", "with"}) {
        if (names.count(pc.at(f).get<std::string>()) == 0)
          problems.emplace_back(where + "/" + f, "no species named \"" + pc.at(f).get<std::string>() + "\"");
      }
    }
  }

  // A 2D bed is one layer of equal spheres one diameter deep, moving in x-y.
  const double d0 = species.empty() ? 0.0 : species[0].at("diameter").get<double>();
  if (twoD) {
    if (std::abs(lengths.z() - d0) > 1e-9 * d0) {
      problems.emplace_back("/lengths/2",
                            "a 2D bed (cells along z is 1) is one particle diameter deep: lengths z must be d = " +
                                core::humanNumber(d0) + " m, found " + core::humanNumber(lengths.z()) + " m");
    }
    for (std::size_t k = 1; k < species.size(); ++k) {
      if (species[k].at("diameter").get<double>() != d0)
        problems.emplace_back("/species/" + std::to_string(k) + "/diameter",
                              "a 2D bed is one layer of equal spheres: every species needs the first's diameter " +
                                  core::humanNumber(d0) + " m");
    }
    const std::string planar = p.at("planar");
    if (!planar.empty() && planar != "z")
      problems.emplace_back("/planar",
                            "a 2D bed moves in x-y: planar must be \"z\" (or left out), found \"" + planar + "\"");
    if (gravity.z() != 0.0)
      problems.emplace_back("/gravity/2", "a 2D bed moves in x-y: gravity must have no z part, found " +
                                              core::humanNumber(gravity.z()) + " m/s2");
  }
  // A cell must hold what it is given: a particle deposited whole on the cell of its centre
  // fills a cell of edge below 2 d past its volume in a dense bed (eps_g <= 0); with the exact
  // overlap a particle spreads over the cells it cuts, which needs an edge of at least d.
  const bool centreCell = e.deposition == tfdem::VolumeDeposition::CentreCell;
  for (int a = 0; a < (twoD ? 2 : 3); ++a) {
    const double h = lengths[a] / cells[static_cast<std::size_t>(a)];
    const double least = (centreCell ? 2.0 : 1.0) * dMax;
    if (h < least) {
      problems.emplace_back("/cells/" + std::to_string(a),
                            "the cell edge " + core::humanNumber(h) + " m is below " + (centreCell ? "2 d" : "d") +
                                " = " + core::humanNumber(least) + " m with deposition " +
                                p.at("deposition").get<std::string>() +
                                (centreCell ? ": a cell could hold more particle volume than its own (eps_g <= 0)"
                                            : ": a particle would cut more than two cells along an axis") +
                                "; use fewer cells" + (centreCell ? " or exact_overlap" : ""));
    }
  }
  // The insertion region inside the domain.
  for (const char* key : {"insert_lo", "insert_hi"}) {
    if (!p.contains(key)) continue;
    for (int a = 0; a < 3; ++a) {
      const double x = p.at(key)[static_cast<std::size_t>(a)];
      if (x < 0.0 || x > lengths[a] * (1.0 + 1e-12)) {
        problems.emplace_back(
            "/" + std::string(key) + "/" + std::to_string(a),
            core::humanNumber(x) + " m is outside the domain [0, " + core::humanNumber(lengths[a]) + "] m");
      }
    }
  }
  s.demParams = demParamsOf(p, twoD);
  s.dem = makeDemSetup(s.demParams);
  for (auto& t : s.dem.timings) t.pointer = tfdemPointer(t.pointer, p);
  for (const auto& problem : s.dem.engine.problems(dMax, count))
    problems.emplace_back(tfdemPointer(problem.pointer, p), problem.message);
  // TF-DEM inserts its particles at random: a count that cannot fit fails the run at its start.
  if (const auto problem = randomInsertionProblem(s.demParams, s.dem))
    problems.emplace_back(problem->pointer, problem->message);
  append(checkContactTimes(s.dem, dt, ""));
  e.particles = s.dem.engine;
  e.materials = s.dem.materials;

  // Pressure taps and the bed's heights along gravity.
  s.vertical = fluid::verticalAxis(gravity);
  s.bottom = s.vertical.up > 0.0 ? 0.0 : lengths[s.vertical.axis];
  std::vector<core::engine::SetupProblem> tapProblems;
  s.taps = readTaps(p, lengths[s.vertical.axis], tapProblems);
  // A 2D bed's gravity out of x-y is refused above; its "height" would be the depth, and the taps'
  // message about it false.
  if (!(twoD && gravity.z() != 0.0)) {
    append(std::move(tapProblems));
  }
  return s;
}

}  // namespace grainbridge::workflows::stages
