#include "workflows/stages/MfmSetup.hpp"

#include <algorithm>

#include "core/text/NumberText.hpp"
#include "engines/fluid/BedMeasures.hpp"
#include "workflows/driver/Phase.hpp"

namespace grainbridge::workflows::stages {

using nlohmann::json;

namespace {

void append(std::vector<core::engine::SetupProblem>& to, std::vector<core::engine::SetupProblem> more) {
  for (auto& problem : more) to.push_back(std::move(problem));
}

}  // namespace

std::int64_t mfmSteps(const json& p) {
  return std::max<std::int64_t>(1,
                                std::llround(p.at("duration").get<double>() / p.at("output_interval").get<double>()));
}

std::string tableQuantity(const std::string& q) {
  return q == "pressure" ? "p_theta" : q == "shear_viscosity" ? "eta_theta" : "j_theta";
}

std::string rheologyGrainsProblem(const json& p, const Grains& grains) {
  const json& solids = p.at("solids").front();
  mfm::SolidsPhase phase;
  phase.name = solids.at("name").get<std::string>();
  phase.diameter = solids.at("diameter");
  phase.density = solids.at("density");
  return mfm::rheologyGrainsProblem(phase, p.value("rheology", std::string()), grains.diameter, grains.density);
}

namespace {

// The schedule: one engine step is one output interval, frames fall on steps, a row every
// interval and the run ending on one.
RunSchedule readSchedule(const json& p, std::vector<core::engine::SetupProblem>& problems) {
  const RunSchedule schedule = readRunSchedule(p, problems);
  const std::int64_t outputs = mfmSteps(p);
  const double interval = schedule.outputInterval, duration = schedule.duration;
  if (const auto why =
          driver::framesProblem(p.at("frames").get<std::int64_t>(), outputs,
                                std::to_string(outputs) + " output intervals (duration " + core::humanNumber(duration) +
                                    " s / output_interval " + core::humanNumber(interval) + " s)");
      !why.empty())
    problems.push_back({"/frames", why});
  if (const auto why = outputIntervalProblem(interval, duration); !why.empty())
    problems.push_back({"/output_interval", why});
  return schedule;
}

}  // namespace

MfmSetup makeMfmSetup(const json& p, const std::vector<core::LoadedClosureTable>* closureTables,
                      const std::vector<core::LoadedRheology>* rheologies) {
  MfmSetup s;
  auto& problems = s.problems;
  // The engine's set-up and its rules; then the DEM data it reads, when given and usable.
  s.engine = p.get<mfm::MultiFluidSetup>();
  problems = s.engine.problems();
  if (closureTables != nullptr && problems.empty()) append(problems, mfm::useClosureTables(s.engine, *closureTables));
  if (rheologies != nullptr && problems.empty()) append(problems, mfm::useRheology(s.engine, *rheologies));

  s.schedule = readSchedule(p, problems);
  const std::size_t M = s.engine.model.solids.size();
  s.initial = p.get<mfm::InitialState>();
  append(problems, s.initial.problems(s.engine.geometry, M, s.engine.packedFraction()));

  // Pressure taps, heights along gravity. A 2D grid's vertical lies in x-y: gravity out of the
  // plane would act on no solved velocity, and would make the grid's depth the taps' "height".
  const Vec3& gravity = s.engine.settings.gravity;
  if (s.engine.fluid.twoD() && gravity.z() != 0.0) {
    problems.push_back({"/gravity/2", "a 2D grid (cells z 1) lies in x-y: gravity must have no z part, found " +
                                          core::humanNumber(gravity.z()) + " m/s2"});
  } else {
    s.taps = readTaps(p, s.engine.fluid.lengths[fluid::verticalAxis(gravity).axis], problems);
  }

  // The segregation percentage of a binary bed (Eqs. 5.23-5.25), x_small from the initial regions.
  if (p.contains("segregation")) {
    const json& seg = p.at("segregation");
    auto found = mfm::segregationOf({seg.at("small"), seg.at("large")}, s.engine, s.initial, problems.empty());
    s.segregation = found.segregation;
    append(problems, std::move(found.problems));
    s.warnings = std::move(found.warnings);
  }
  return s;
}

}  // namespace grainbridge::workflows::stages
