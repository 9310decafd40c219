#include "workflows/stages/TfdemSetup.hpp"

#include <algorithm>
#include <cmath>

#include "core/json/Vec3Json.hpp"
#include "core/text/NumberText.hpp"
#include "workflows/driver/Phase.hpp"
#include "workflows/stages/OutputSchedule.hpp"
#include "workflows/stages/ParticleSchema.hpp"

namespace grainbridge::workflows::stages {

using nlohmann::json;

namespace {

void append(std::vector<core::engine::SetupProblem>& to, std::vector<core::engine::SetupProblem> more) {
  for (auto& problem : more) to.push_back(std::move(problem));
}

// The particles in the gas's domain: species and pair materials from the particle keys, the
// domain as the box, plane walls of the `wall` material (default: `contact`) on every side it has
// (a 2D bed's z sides need none: nothing moves along z), moving in x-y when the bed is 2D.
DemSetup particlesOf(const json& p, const tfdem::TfdemSetup& gas, const std::string& wallKey) {
  DemSetup out = makeParticleSetup(p);
  auto& e = out.engine;
  const bool twoD = gas.fluid.twoD();
  e.lo = Vec3::Zero();
  e.hi = gas.fluid.lengths;
  e.gravity = out.materials.gravity = gas.solver.gravity;
  const std::string planar = p.at("planar");
  e.planarAxis = !planar.empty() ? planar[0] - 'x' : twoD ? 2 : -1;
  const json& material = p.at(wallKey.substr(1));
  for (int a = 0; a < (twoD ? 2 : 3); ++a) {
    for (int side = 0; side < 2; ++side) {
      dem::Wall wall;
      wall.kind = dem::Wall::Kind::Plane;
      wall.origin = Vec3::Zero();
      if (side == 1) wall.origin[a] = e.hi[a];
      wall.direction = Vec3::Zero();
      wall.direction[a] = side == 0 ? 1.0 : -1.0;
      addWall(out, std::move(wall), material, wallKey);
    }
  }
  return out;
}

// A particle set-up problem's pointer as the tfdem params name it: the particles' box is the
// gas's domain, every wall is of the one wall material.
std::string particlePointer(const std::string& pointer, const std::string& wallKey) {
  if (pointer.starts_with("/box_hi") || pointer.starts_with("/box_lo")) return "/lengths";
  if (pointer.starts_with("/walls")) return wallKey;
  return pointer;
}

// Whether `whole` is a whole number (>= 1) of `part`, to round-off.
bool wholeMultiple(double whole, double part) {
  const double ratio = whole / part;
  return std::llround(ratio) >= 1 && std::abs(ratio - std::round(ratio)) <= 1e-6 * ratio;
}

// The schedule: the output interval of whole gas steps, a row every interval, frames on gas steps.
void setSchedule(const json& p, TfdemStageSetup& s) {
  auto& problems = s.problems;
  const double fluidDt = s.engine.fluid.timeStep.initial;
  const RunSchedule schedule = readRunSchedule(p, problems);
  s.duration = schedule.duration;
  s.outputInterval = schedule.outputInterval;
  s.averageFrom = schedule.averageFrom;
  s.averageTo = schedule.averageTo;
  s.settleDuration = p.at("settle_duration");
  if (!wholeMultiple(s.outputInterval, fluidDt)) {
    problems.push_back({"/output_interval",
                        "output_interval = " + core::humanNumber(s.outputInterval) +
                            " s is not a whole number of gas steps fluid_dt = " + core::humanNumber(fluidDt) + " s"});
  }
  if (const auto why = outputIntervalProblem(s.outputInterval, s.duration, fluidDt, "gas steps fluid_dt");
      !why.empty())
    problems.push_back({"/output_interval", why});
  // A row every output_interval: the run is a whole number of rows of a whole number of gas steps
  // each (both checked above), so the driver's evenly spaced rows fall on exactly those steps.
  s.seriesRows = std::max<std::int64_t>(1, std::llround(s.duration / s.outputInterval));
  s.steps = s.seriesRows * std::max<std::int64_t>(1, std::llround(s.outputInterval / fluidDt));
  s.settleSteps = std::llround(s.settleDuration / fluidDt);
  if (const auto why = driver::framesProblem(p.at("frames").get<std::int64_t>(), s.steps,
                                             std::to_string(s.steps) + " gas steps (duration " +
                                                 core::humanNumber(s.duration) + " s / fluid_dt " +
                                                 core::humanNumber(fluidDt) + " s)");
      !why.empty())
    problems.push_back({"/frames", why});
}

// The particle keys (species, contacts) as dem checks them, the wall material, the insertion
// region inside the domain, the particles' own rules (their engine's) and whether their count
// fits the region at random.
void checkParticles(const json& p, const std::string& wallKey, TfdemStageSetup& s) {
  auto& problems = s.problems;
  append(problems, checkSpeciesParams(p));
  if (p.contains("wall")) append(problems, checkContactKeys(p.at("wall"), p, "/wall"));
  // The insertion region inside the domain.
  const Vec3& lengths = s.engine.fluid.lengths;
  for (const char* key : {"insert_lo", "insert_hi"}) {
    if (!p.contains(key)) continue;
    for (int a = 0; a < 3; ++a) {
      const double x = p.at(key)[static_cast<std::size_t>(a)];
      if (x < 0.0 || x > lengths[a] * (1.0 + 1e-12)) {
        problems.push_back(
            {"/" + std::string(key) + "/" + std::to_string(a),
             core::humanNumber(x) + " m is outside the domain [0, " + core::humanNumber(lengths[a]) + "] m"});
      }
    }
  }
  double dMax = 0.0;
  std::int64_t count = 0;
  for (const auto& sp : s.dem.species) {
    dMax = std::max(dMax, 2.0 * sp.radius);
    count += sp.count;
  }
  for (auto& t : s.dem.timings) t.pointer = particlePointer(t.pointer, wallKey);
  for (const auto& problem : s.dem.engine.problems(dMax, count))
    problems.push_back({particlePointer(problem.pointer, wallKey), problem.message});
  s.insertion = p.get<InsertionChoice>();
  if (const auto problem = randomInsertionProblem(s.insertion, s.dem, "lengths")) problems.push_back(*problem);
  append(problems, checkContactTimes(s.dem, s.engine.particles.dt));
}

}  // namespace

TfdemStageSetup makeTfdemSetup(const json& p) {
  TfdemStageSetup s;
  auto& problems = s.problems;
  auto& e = s.engine;
  e = p.get<tfdem::TfdemSetup>();
  const std::string wallKey = p.contains("wall") ? "/wall" : "/contact";
  s.dem = particlesOf(p, e, wallKey);
  e.particles = s.dem.engine;
  e.materials = s.dem.materials;
  problems = e.problems();
  s.initialGasVelocity = core::json::vec3FromJson(p.at("initial_gas_velocity"));
  for (const auto& b : e.fluid.boundaries) {
    if (b.kind == "pressure_outlet") {
      s.initialPressure = b.pressure;
      break;
    }
  }
  setSchedule(p, s);
  checkParticles(p, wallKey, s);

  // Pressure taps and the bed's heights along gravity. A 2D bed's gravity out of x-y is refused
  // by the engine's set-up; its "height" would be the depth, and the taps' message about it false.
  const Vec3& gravity = e.solver.gravity;
  const Vec3& lengths = e.fluid.lengths;
  s.vertical = fluid::verticalAxis(gravity);
  s.bottom = s.vertical.up > 0.0 ? 0.0 : lengths[s.vertical.axis];
  std::vector<core::engine::SetupProblem> tapProblems;
  s.taps = readTaps(p, lengths[s.vertical.axis], tapProblems);
  if (!(e.fluid.twoD() && gravity.z() != 0.0)) append(problems, std::move(tapProblems));
  return s;
}

}  // namespace grainbridge::workflows::stages
