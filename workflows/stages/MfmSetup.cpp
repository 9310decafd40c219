#include "workflows/stages/MfmSetup.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <optional>

#include "core/Error.hpp"
#include "core/SameValue.hpp"
#include "core/json/Vec3Json.hpp"
#include "core/text/NumberText.hpp"
#include "engines/closures/InertialRheology.hpp"
#include "engines/closures/TabulatedClosure.hpp"
#include "engines/fluid/BedMeasures.hpp"
#include "engines/fluid/FluidSetup.hpp"
#include "engines/mfm/InitialBed.hpp"
#include "engines/mfm/SolidsPairs.hpp"
#include "workflows/driver/Phase.hpp"
#include "workflows/stages/DragSetup.hpp"
#include "workflows/stages/OutputSchedule.hpp"

namespace grainbridge::workflows::stages {

using nlohmann::json;

namespace {

// Each problem of an engine's set-up struct, at its pointer below /params.
void addProblems(MfmSetup& s, const std::vector<core::engine::SetupProblem>& problems) {
  for (const auto& problem : problems) s.problems.emplace_back(problem.pointer, problem.message);
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
  const double diameter = solids.at("diameter"), density = solids.at("density");
  if (core::sameValue(diameter, grains.diameter) && core::sameValue(density, grains.density)) return {};
  return "the rheology \"" + p.value("rheology", std::string()) + "\" was measured on grains of diameter " +
         core::humanNumber(grains.diameter) + " m and density " + core::humanNumber(grains.density) +
         " kg/m3, but solids phase \"" + solids.at("name").get<std::string>() + "\" has " +
         core::humanNumber(diameter) + " m and " + core::humanNumber(density) +
         " kg/m3: its inertial numbers would be of other grains";
}

namespace {

// The plastic viscosity (PlasticRegime.hpp): Schaeffer's, or mu(I) from the DEM rheology named
// in `rheology`, at the solids phase's restitution, as its fit or its points.
void setPlasticViscosity(const json& p, const std::vector<core::LoadedRheology>* rheologies, MfmSetup& s,
                         const std::function<void(std::string, std::string)>& problem) {
  if (p.at("plastic").get<std::string>() != "mu_i") {
    if (p.contains("rheology")) problem("/rheology", "is read by plastic \"mu_i\" only");
    return;
  }
  const auto& model = s.engine.model;
  if (model.solids.size() != 1) {
    problem("/plastic", "mu_i takes the mu(I) of one kind of grain: it runs one solids phase, not " +
                            std::to_string(model.solids.size()));
  }
  if (!p.contains("rheology")) {
    problem("/rheology", "plastic \"mu_i\" needs the name of the mu(I) rheology (a tabulate stage's table)");
  }
  if (rheologies == nullptr || !s.problems.empty()) return;
  const std::string name = p.at("rheology");
  const auto loaded = std::find_if(rheologies->begin(), rheologies->end(),
                                   [&](const core::LoadedRheology& r) { return r.name == name; });
  if (loaded == rheologies->end()) {
    problem("/rheology", "the mu(I) rheology \"" + name + "\" was not loaded");
    return;
  }
  if (const auto why = rheologyGrainsProblem(p, {loaded->diameter, loaded->density}); !why.empty()) {
    problem("/rheology", why);
    return;
  }
  const mfm::SolidsPhase& phase = model.solids.front();
  const core::LoadedRheology::Row* row = loaded->atRestitution(phase.restitution);
  if (row == nullptr) {
    std::string known;
    for (const auto& r : loaded->rows)
      known += (known.empty() ? "" : ", ") + (r.restitution ? core::humanNumber(*r.restitution) : std::string("none"));
    problem("/rheology", "the mu(I) rheology \"" + name + "\" has no row at the solids' restitution " +
                             core::humanNumber(phase.restitution) + " (it has: " + known + ")");
    return;
  }
  const closures::InertialRheology::Grains grains{loaded->diameter, loaded->density};
  try {
    if (p.at("rheology_form").get<std::string>() == "fit") {
      if (!row->fit) {
        problem("/rheology_form", "the mu(I) rheology \"" + name + "\" at restitution " +
                                      core::humanNumber(phase.restitution) +
                                      " has no fit (its points did not determine one): use rheology_form \"table\"");
        return;
      }
      s.engine.model.plastic.params.rheology = closures::InertialRheology::fitted(
          grains, {row->fit->staticRatio, row->fit->limitRatio, row->fit->inertialNumberScale});
    } else {
      s.engine.model.plastic.params.rheology =
          closures::InertialRheology::tabulated(grains, row->inertialNumbers, row->stressRatios);
    }
  } catch (const Error& e) {
    problem("/rheology", "the mu(I) rheology \"" + name + "\": " + e.what());
  }
}

// s_p (Eqs. 5.23-5.25) counts the small phase's excess low in the bed as positive: with small and
// large swapped it comes out with the wrong sign and no error. Refused when `small` names the
// larger diameter; equal diameters make the roles a matter of naming only, warned.
void checkSegregationRoles(const std::vector<mfm::SolidsPhase>& solids, const std::array<std::size_t, 2>& index,
                           MfmSetup& s) {
  const mfm::SolidsPhase& small = solids[index[0]];
  const mfm::SolidsPhase& large = solids[index[1]];
  if (small.diameter > large.diameter) {
    s.problems.emplace_back("/segregation/small",
                            "names \"" + small.name + "\" (diameter " + core::humanNumber(small.diameter) +
                                " m), larger than large \"" + large.name + "\" (" +
                                core::humanNumber(large.diameter) +
                                " m): s_p (Eqs. 5.23-5.25) would have the wrong sign; swap small and large");
  } else if (small.diameter == large.diameter) {
    s.warnings.emplace_back("/segregation", "small \"" + small.name + "\" and large \"" + large.name +
                                                "\" have the same diameter " + core::humanNumber(small.diameter) +
                                                " m: s_p (Eqs. 5.23-5.25) measures the separation of two equal "
                                                "grains, its sign set by the names alone");
  }
}

}  // namespace

MfmSetup makeMfmSetup(const json& p, const std::vector<core::LoadedClosureTable>* closureTables,
                      const std::vector<core::LoadedRheology>* rheologies) {
  MfmSetup s;
  auto problem = [&s](std::string where, std::string what) {
    s.problems.emplace_back(std::move(where), std::move(what));
  };

  // The grid, its boundary patches and the time step: the fluid set-up (engines/fluid).
  const auto fluidSetup = p.get<fluid::FluidSetup>();
  s.engine.geometry = fluidSetup.geometry();
  s.engine.limits = fluidSetup.timeStep;

  // The phases and their closures.
  auto& model = s.engine.model;
  model.gas.density = p.at("gas_density");
  model.gas.viscosity = p.at("gas_viscosity");
  model.gas.ideal = p.at("gas_model").get<std::string>() == "ideal";
  model.gas.molarMass = p.at("gas_molar_mass");
  model.gas.temperature = p.at("gas_temperature");
  for (const auto& sp : p.at("solids")) {
    mfm::SolidsPhase phase;
    phase.name = sp.at("name").get<std::string>();
    phase.diameter = sp.at("diameter");
    phase.density = sp.at("density");
    phase.restitution = sp.at("restitution");
    phase.wallRestitution = sp.contains("wall_restitution") ? sp.at("wall_restitution").get<double>() : phase.restitution;
    phase.friction = sp.at("friction");
    phase.wallFriction = sp.at("wall_friction");
    phase.tangentialRestitution = sp.at("tangential_restitution");
    model.solids.push_back(std::move(phase));
  }
  const std::size_t M = model.solids.size();
  std::vector<mfm::SolidsPairRequest> requests;
  for (const json& entry : p.value("solids_pairs", json::array())) {
    requests.push_back({entry.at("phases").get<std::vector<std::string>>(), entry.at("friction").get<double>(),
                        entry.contains("restitution") ? std::optional<double>(entry.at("restitution")) : std::nullopt});
  }
  mfm::SolidsPairsResult pairs = mfm::solidsPairsFor(model.solids, requests);
  addProblems(s, pairs.problems);
  model.solidsPairs = std::move(pairs.pairs);
  model.drag = dragFromParams(p, problem);
  const std::string kineticModel = p.at("kinetic_model");
  model.kinetic.params.viscosityForm = kineticModel == "syamlal_algebraic_mfix" ? closures::SyamlalViscosityForm::Mfix
                                                                               : closures::SyamlalViscosityForm::Printed;
  model.closure = closures::ClosureModel::kineticTheory(closures::kineticModelFromString(kineticModel));
  model.granularEnergy =
      p.at("granular_energy").get<std::string>() == "pde" ? mfm::GranularEnergyForm::Pde : mfm::GranularEnergyForm::Algebraic;
  model.rotation = p.at("rotation_model");
  const bool johnsonJackson = p.at("solids_walls").get<std::string>() == "johnson_jackson";
  if (p.at("closure").get<std::string>() == "table") {
    if (M > 1) {
      problem("/closure", "closure tables are of one kind of grain (monodisperse DEM); closure \"table\" runs one "
                          "solids phase, not " + std::to_string(M));
    }
    if (!p.contains("closure_table")) problem("/closure_table", "closure \"table\" needs the name of the tables");
    if (!p.contains("out_of_range")) {
      problem("/out_of_range",
              "closure \"table\" needs an explicit out-of-range policy: error, clamp or kinetic_theory");
    }
    if (p.at("table_quantities").empty()) problem("/table_quantities", "name at least one quantity the table supplies");
    if (model.granularEnergy != mfm::GranularEnergyForm::Pde)
      problem("/granular_energy", "a closure table is read at the granular-energy equation's theta: needs pde");
    if (closureTables != nullptr && s.problems.empty()) {
      const auto policy = closures::outOfRangePolicyFromString(p.value("out_of_range", "error"));
      const auto fallback = closures::kineticModelFromString(kineticModel);
      std::optional<closures::TabulatedClosure> pressure, viscosity, dissipation;
      for (const auto& loaded : *closureTables) {
        const core::ClosureTable& table = loaded.table;
        if (model.rotation && loaded.friction > 0.0) {
          problem("/rotation_model", "closure table \"" + loaded.name + "\" (" + table.quantity() +
                                         ") was made from grains with friction " + core::humanNumber(loaded.friction) +
                                         ": the rotation model would count their friction a second time");
        }
        closures::TabulatedClosure closure(table, policy, fallback);
        if (table.quantity() == "p_theta") pressure.emplace(closure);
        if (table.quantity() == "eta_theta") viscosity.emplace(closure);
        if (table.quantity() == "j_theta") dissipation.emplace(closure);
      }
      model.closure = closures::ClosureModel::tabulated(fallback, pressure, viscosity, dissipation);
    }
  }
  const std::string radial = p.value("radial_distribution", M > 1 ? "lebowitz" : "carnahan_starling");
  model.radialDistribution = radial == "lebowitz" ? mfm::RadialDistributionModel::Lebowitz
                                                  : mfm::RadialDistributionModel::CarnahanStarling;
  if (M > 1 && model.radialDistribution == mfm::RadialDistributionModel::CarnahanStarling) {
    problem("/radial_distribution", "carnahan_starling is the g0 of one solids phase; " + std::to_string(M) +
                                        " phases need lebowitz");
  }
  model.plasticTheta =
      p.at("plastic_theta").get<std::string>() == "pinned" ? mfm::PlasticTheta::Pinned : mfm::PlasticTheta::Solved;
  if (model.granularEnergy == mfm::GranularEnergyForm::Algebraic) {
    if (kineticModel.starts_with("lun1984"))
      problem("/granular_energy",
              "the algebraic balance is written for the syamlal kinetic models; " + kineticModel + " needs pde");
    if (model.rotation) problem("/rotation_model", "the rotation model needs granular_energy pde");
    if (model.plasticTheta == mfm::PlasticTheta::Pinned)
      problem("/plastic_theta", "pins the granular-energy equation's theta: needs granular_energy pde");
    if (johnsonJackson) problem("/solids_walls", "Johnson-Jackson walls need granular_energy pde");
  }
  model.plastic.params.criticalVoidFraction = p.at("critical_void_fraction").get<double>();
  model.plastic.params.internalFrictionAngle = p.at("friction_angle").get<double>();
  if (const auto why = model.plastic.params.problem(); !why.empty()) problem("/friction_angle", why);
  setPlasticViscosity(p, rheologies, s, problem);
  const double packed = p.contains("packed_solids_fraction") ? p.at("packed_solids_fraction").get<double>()
                                                             : 1.0 - model.plastic.params.criticalVoidFraction;
  if (johnsonJackson) model.wall = closures::JohnsonJackson::Params{p.at("specularity").get<double>(), packed, 1.0, {}};

  // The solver.
  auto& settings = s.engine.settings;
  settings.phaseNames = {"gas"};
  for (const auto& solids : model.solids) settings.phaseNames.push_back(solids.name);
  settings.gravity = core::json::vec3FromJson(p.at("gravity"));
  settings.packedFraction = packed;
  settings.tolerance = p.at("tolerance");
  settings.maxIterations = p.at("max_iterations");
  settings.momentumRelaxation = p.at("momentum_relaxation");
  settings.pressureRelaxation = p.at("pressure_relaxation");
  settings.fractionRelaxation = p.at("fraction_relaxation");
  settings.diluteFraction = p.at("dilute_fraction");
  model.diluteFraction = settings.diluteFraction;  // the granular energy's dilute cells too
  // The linear solves: the band LU by default; iterative ones for 3D grids (StencilSystem.hpp).
  settings.momentumSolve = readLinearSolve(p, "momentum");
  settings.pressureSolve = readLinearSolve(p, "pressure");
  settings.fractionSolve = readLinearSolve(p, "fraction");
  s.engine.interval = p.at("output_interval");
  s.duration = p.at("duration");
  s.averageFrom = p.at("average_from");
  s.averageTo = p.contains("average_to") ? p.at("average_to").get<double>() : s.duration;
  if (s.averageFrom >= s.duration) problem("/average_from", "must be before the end of the run (duration)");
  if (s.averageTo > s.duration * (1.0 + 1e-12)) problem("/average_to", "is after the end of the run (duration)");
  if (s.averageTo <= s.averageFrom) problem("/average_to", "must be after average_from");
  if (s.engine.interval > s.duration) problem("/output_interval", "is longer than the run (duration)");
  // One engine step is one output interval, and frames fall on steps.
  const std::int64_t outputs = mfmSteps(p);
  if (const auto why = driver::framesProblem(p.at("frames").get<std::int64_t>(), outputs,
                                             std::to_string(outputs) + " output intervals (duration " +
                                                 core::humanNumber(s.duration) + " s / output_interval " +
                                                 core::humanNumber(s.engine.interval) + " s)");
      !why.empty())
    problem("/frames", why);
  // A row every interval and the run ending on one (the engine's steps land on each multiple).
  if (const auto why = outputIntervalProblem(s.engine.interval, s.duration); !why.empty())
    problem("/output_interval", why);

  // Boundaries (sides, jets on cell faces, inflow states, a fixed step's CFL limit) and the time
  // step, checked by the fluid set-up; then the initial regions, by mfm's initial state.
  const std::size_t fluidProblems = s.problems.size();
  addProblems(s, fluidSetup.problems(M, packed));
  if (s.problems.size() == fluidProblems) s.engine.patches = fluidSetup.patches(M);
  s.initial = p.get<mfm::InitialState>();
  addProblems(s, s.initial.problems(s.engine.geometry, M, packed));

  // Pressure taps, heights along gravity. A 2D grid's vertical lies in x-y: gravity out of the
  // plane would act on no solved velocity, and would make the grid's depth the taps' "height".
  const fluid::VerticalAxis vertical = fluid::verticalAxis(settings.gravity);
  if (fluidSetup.twoD() && settings.gravity.z() != 0.0) {
    problem("/gravity/2", "a 2D grid (cells z 1) lies in x-y: gravity must have no z part, found " +
                              core::humanNumber(settings.gravity.z()) + " m/s2");
  } else {
    s.taps = readTaps(p, fluidSetup.lengths[vertical.axis], s.problems);
  }

  // The segregation percentage of a binary bed (Eqs. 5.23-5.25), x_small from the initial regions.
  if (p.contains("segregation")) {
    const json& seg = p.at("segregation");
    if (M != 2) problem("/segregation", "the segregation percentage is of a binary bed; this one has " +
                                            std::to_string(M) + " solids phase(s)");
    std::array<std::size_t, 2> index{M, M};
    const std::array<const char*, 2> roles{"small", "large"};
    for (std::size_t r = 0; r < 2; ++r) {
      const std::string name = seg.at(roles[r]);
      for (std::size_t m = 0; m < M; ++m) {
        if (model.solids[m].name == name) index[r] = m;
      }
      if (index[r] == M) problem("/segregation/" + std::string(roles[r]), "no solids phase is named \"" + name + "\"");
    }
    if (index[0] < M && index[0] == index[1])
      problem("/segregation/large", "is the small phase too; name the two phases of the bed");
    if (index[0] < M && index[1] < M && index[0] != index[1]) checkSegregationRoles(model.solids, index, s);
    if (s.problems.empty()) {
      const auto volumes = mfm::initialInventory(s.engine, s.initial).solidsVolume;
      const double total = volumes[0] + volumes[1];
      if (!(volumes[index[0]] > 0.0 && volumes[index[1]] > 0.0)) {
        problem("/segregation", "the initial regions must hold both phases (small and large) to define x_small");
      } else {
        s.segregation = Segregation{index[0], index[1], volumes[index[0]] / total};
      }
    }
  }
  return s;
}

}  // namespace grainbridge::workflows::stages
