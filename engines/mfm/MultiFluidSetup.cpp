#include "engines/mfm/MultiFluidSetup.hpp"

#include <algorithm>

#include "core/Error.hpp"
#include "core/SameValue.hpp"
#include "core/json/Vec3Json.hpp"
#include "core/text/NumberText.hpp"
#include "engines/closures/DragFromJson.hpp"
#include "engines/closures/InertialRheology.hpp"

namespace grainbridge::mfm {

using nlohmann::json;

namespace {

// The solids pressure's packing limit eps_p (Eq. 3.68): packed_solids_fraction, by default the
// plastic regime's onset 1 - eps_g*.
double packedFractionOf(const json& p) {
  return p.contains("packed_solids_fraction") ? p.at("packed_solids_fraction").get<double>()
                                              : 1.0 - p.at("critical_void_fraction").get<double>();
}

SolidsPhase solidsPhaseOf(const json& sp) {
  SolidsPhase phase;
  phase.name = sp.at("name").get<std::string>();
  phase.diameter = sp.at("diameter");
  phase.density = sp.at("density");
  phase.restitution = sp.at("restitution");
  phase.wallRestitution = sp.contains("wall_restitution") ? sp.at("wall_restitution").get<double>() : phase.restitution;
  phase.friction = sp.at("friction");
  phase.wallFriction = sp.at("wall_friction");
  phase.tangentialRestitution = sp.at("tangential_restitution");
  phase.maxPacking = sp.at("max_packing");
  return phase;
}

bool isLun(closures::KineticModelName model) {
  return model == closures::KineticModelName::Lun1984 || model == closures::KineticModelName::Lun1984Mfix;
}

}  // namespace

void from_json(const json& p, MultiFluidSetup& s) {
  // The grid, its boundary patches and the time step: the fluid set-up (engines/fluid).
  s.fluid = p.get<fluid::FluidSetup>();
  s.geometry = s.fluid.geometry();
  s.limits = s.fluid.timeStep;

  // The phases and their closures.
  auto& model = s.model;
  model.gas.density = p.at("gas_density");
  model.gas.viscosity = p.at("gas_viscosity");
  model.gas.ideal = p.at("gas_model").get<std::string>() == "ideal";
  model.gas.molarMass = p.at("gas_molar_mass");
  model.gas.temperature = p.at("gas_temperature");
  for (const auto& sp : p.at("solids")) model.solids.push_back(solidsPhaseOf(sp));
  const std::size_t M = model.solids.size();
  for (const json& entry : p.value("solids_pairs", json::array())) {
    s.pairRequests.push_back(
        {entry.at("phases").get<std::vector<std::string>>(), entry.at("friction").get<double>(),
         entry.contains("restitution") ? std::optional<double>(entry.at("restitution")) : std::nullopt});
  }
  model.solidsPairs = solidsPairsFor(model.solids, s.pairRequests).pairs;
  model.drag = closures::dragFromJson(p);
  const std::string kineticModel = p.at("kinetic_model");
  model.kinetic.params.viscosityForm = kineticModel == "syamlal_algebraic_mfix"
                                           ? closures::SyamlalViscosityForm::Mfix
                                           : closures::SyamlalViscosityForm::Printed;
  model.closure = closures::ClosureModel::kineticTheory(closures::kineticModelFromString(kineticModel));
  model.granularEnergy =
      p.at("granular_energy").get<std::string>() == "pde" ? GranularEnergyForm::Pde : GranularEnergyForm::Algebraic;
  model.rotation = p.at("rotation_model");
  if (p.at("closure").get<std::string>() == "table") {
    TableClosureChoice table;
    table.tables = p.value("closure_table", std::string());
    if (p.contains("out_of_range"))
      table.outOfRange = closures::outOfRangePolicyFromString(p.at("out_of_range").get<std::string>());
    table.quantities = p.at("table_quantities").get<std::vector<std::string>>();
    s.table = std::move(table);
  }
  const std::string radial = p.value("radial_distribution", M > 1 ? "lebowitz" : "carnahan_starling");
  model.radialDistribution =
      radial == "lebowitz" ? RadialDistributionModel::Lebowitz : RadialDistributionModel::CarnahanStarling;
  model.plasticTheta =
      p.at("plastic_theta").get<std::string>() == "pinned" ? PlasticTheta::Pinned : PlasticTheta::Solved;
  model.plasticPressure =
      p.at("plastic_pressure").get<std::string>() == "per_phase" ? PlasticPressure::PerPhase : PlasticPressure::Shared;
  model.plastic.params.criticalVoidFraction = p.at("critical_void_fraction").get<double>();
  model.mixtureKineticTheory = p.at("mixture_kinetic_theory").get<std::string>() == "per_phase"
                                   ? MixtureKineticTheory::PerPhase
                                   : MixtureKineticTheory::Summed;
  model.packingLimit = closures::packingLimitFromString(p.at("packing_limit").get<std::string>());
  s.packedFractionGiven = p.contains("packed_solids_fraction");
  model.plastic.params.internalFrictionAngle = p.at("friction_angle").get<double>();
  s.plasticViscosity.inertial = p.at("plastic").get<std::string>() == "mu_i";
  s.plasticViscosity.rheology = p.value("rheology", std::string());
  s.plasticViscosity.fitted = p.at("rheology_form").get<std::string>() == "fit";
  const double packed = packedFractionOf(p);
  if (p.at("solids_walls").get<std::string>() == "johnson_jackson")
    model.wall = closures::JohnsonJackson::Params{p.at("specularity").get<double>(), packed, 1.0, {}};

  // The solver.
  auto& settings = s.settings;
  settings.phaseNames = {"gas"};
  for (const auto& solids : model.solids) settings.phaseNames.push_back(solids.name);
  settings.gravity = core::json::vec3FromJson(p.at("gravity"));
  settings.packedFraction = packed;
  settings.tolerance = p.at("tolerance");
  settings.maxIterations = p.at("max_iterations");
  settings.stallWindow = p.at("detect_stall").get<bool>() ? 5 : 0;  // MFiX's window of 5 iterations
  settings.momentumRelaxation = p.at("momentum_relaxation");
  settings.pressureRelaxation = p.at("pressure_relaxation");
  settings.fractionRelaxation = p.at("fraction_relaxation");
  settings.diluteFraction = p.at("dilute_fraction");
  model.diluteFraction = settings.diluteFraction;  // the granular energy's dilute cells too
  // The linear solves: the band LU by default; iterative ones for 3D grids (StencilSystem.hpp).
  settings.momentumSolve = fluid::linearSolveFromJson(p, "momentum");
  settings.pressureSolve = fluid::linearSolveFromJson(p, "pressure");
  settings.fractionSolve = fluid::linearSolveFromJson(p, "fraction");
  s.interval = p.at("output_interval");
  // The patches in the grid's terms, when the fluid set-up can make them (problems() says why not).
  if (s.fluid.problems(M, s.packedFraction()).empty()) s.patches = s.fluid.patches(M);
}

std::vector<SetupProblem> MultiFluidSetup::problems() const {
  std::vector<SetupProblem> found = solidsPairsFor(model.solids, pairRequests).problems;
  auto problem = [&found](std::string where, std::string what) {
    found.push_back({std::move(where), std::move(what)});
  };
  for (const auto& [how, family] :
       {std::pair{&settings.momentumSolve, "momentum"}, std::pair{&settings.pressureSolve, "pressure"},
        std::pair{&settings.fractionSolve, "fraction"}}) {
    for (auto& why : fluid::linearSolveProblems(*how, family)) found.push_back(std::move(why));
  }
  const std::size_t M = model.solids.size();
  if (auto why = closures::dragProblem(model.drag)) found.push_back(std::move(*why));
  if (table) {
    if (M > 1) {
      problem("/closure",
              "closure tables are of one kind of grain (monodisperse DEM); closure \"table\" runs one "
              "solids phase, not " +
                  std::to_string(M));
    }
    if (table->tables.empty()) problem("/closure_table", "closure \"table\" needs the name of the tables");
    if (!table->outOfRange) {
      problem("/out_of_range",
              "closure \"table\" needs an explicit out-of-range policy: error, clamp or kinetic_theory");
    }
    if (table->quantities.empty()) problem("/table_quantities", "name at least one quantity the table supplies");
    if (model.granularEnergy != GranularEnergyForm::Pde)
      problem("/granular_energy", "a closure table is read at the granular-energy equation's theta: needs pde");
  }
  // g0 at contact: Carnahan-Starling's is of one phase's own fraction; a mixture's is Lebowitz's.
  if (M > 1 && model.radialDistribution == RadialDistributionModel::CarnahanStarling) {
    problem("/radial_distribution",
            "carnahan_starling is the g0 of one solids phase; " + std::to_string(M) + " phases need lebowitz");
  }
  // The algebraic balance (MFiX's gt_algebraic) has no theta to pin, no wall flux and no place for
  // the rotation model's dissipation; it is written for the Syamlal coefficients.
  if (model.granularEnergy == GranularEnergyForm::Algebraic) {
    const auto kinetic = model.closure.kineticModel();
    if (isLun(kinetic))
      problem("/granular_energy", "the algebraic balance is written for the syamlal kinetic models; " +
                                      std::string(closures::toString(kinetic)) + " needs pde");
    if (model.rotation) problem("/rotation_model", "the rotation model needs granular_energy pde");
    if (model.plasticTheta == PlasticTheta::Pinned)
      problem("/plastic_theta", "pins the granular-energy equation's theta: needs granular_energy pde");
    if (model.wall) problem("/solids_walls", "Johnson-Jackson walls need granular_energy pde");
  }
  if (const auto why = model.plastic.params.problem(); !why.empty()) problem("/friction_angle", why);
  // The packing limit by composition (MixturePacking.hpp).
  if (model.packingLimit == closures::PackingLimit::Gera && M > 2)
    problem("/packing_limit", "gera is Fedors and Landel's binary formula: it takes two solids phases, not " +
                                  std::to_string(M) + " (yu_standish takes any number)");
  if (model.packingLimit != closures::PackingLimit::Fixed && M > 1 && packedFractionGiven)
    problem("/packed_solids_fraction",
            "is one packed fraction for every cell, but packing_limit " +
                std::string(closures::toString(model.packingLimit)) +
                " packs each cell by its composition (Eq. 3.68 then takes 1 - eps_g* of the cell): leave it out");
  if (model.mixtureKineticTheory == MixtureKineticTheory::PerPhase && model.granularEnergy != GranularEnergyForm::Pde)
    problem("/mixture_kinetic_theory",
            "per_phase is a form of the granular-energy equation's kinetic theory: needs "
            "granular_energy pde");
  if (!plasticViscosity.inertial) {
    if (!plasticViscosity.rheology.empty()) problem("/rheology", "is read by plastic \"mu_i\" only");
  } else {
    if (M != 1) {
      problem("/plastic",
              "mu_i takes the mu(I) of one kind of grain: it runs one solids phase, not " + std::to_string(M));
    }
    if (plasticViscosity.rheology.empty()) {
      problem("/rheology", "plastic \"mu_i\" needs the name of the mu(I) rheology (a tabulate stage's table)");
    }
  }
  // Boundaries (sides, jets on cell faces, inflow states, a fixed step's CFL limit) and the time
  // step, checked by the fluid set-up.
  for (auto& why : fluid.problems(M, packedFraction())) found.push_back(std::move(why));
  return found;
}

fluid::FluidSetup::PackedFraction MultiFluidSetup::packedFraction() const {
  const double packed = settings.packedFraction;
  const auto constant = [packed](std::span<const double>) { return packed; };
  std::shared_ptr<const closures::MixturePacking> packing;
  try {
    packing = std::make_shared<const closures::MixturePacking>(mixturePackingOf(model));
  } catch (const Error&) {
    return constant;  // the packing's own keys are at fault (problems() says which)
  }
  if (!packing->byComposition()) return constant;  // fixed, or one solids phase
  return [packing](std::span<const double> fractions) { return 1.0 - packing->criticalVoidFraction(fractions); };
}

std::vector<SetupProblem> useClosureTables(MultiFluidSetup& s, const std::vector<core::LoadedClosureTable>& tables) {
  std::vector<SetupProblem> found;
  if (!s.table) return found;
  auto& model = s.model;
  const auto policy = s.table->outOfRange.value_or(closures::OutOfRangePolicy::Error);
  const auto fallback = model.closure.kineticModel();
  std::optional<closures::TabulatedClosure> pressure, viscosity, dissipation;
  for (const auto& loaded : tables) {
    const core::ClosureTable& table = loaded.table;
    if (model.rotation && loaded.friction > 0.0) {
      found.push_back({"/rotation_model", "closure table \"" + loaded.name + "\" (" + table.quantity() +
                                              ") was made from grains with friction " +
                                              core::humanNumber(loaded.friction) +
                                              ": the rotation model would count their friction a second time"});
    }
    closures::TabulatedClosure closure(table, policy, fallback);
    if (table.quantity() == "p_theta") pressure.emplace(closure);
    if (table.quantity() == "eta_theta") viscosity.emplace(closure);
    if (table.quantity() == "j_theta") dissipation.emplace(closure);
  }
  model.closure = closures::ClosureModel::tabulated(fallback, pressure, viscosity, dissipation);
  return found;
}

std::string rheologyGrainsProblem(const SolidsPhase& solids, const std::string& name, double diameter, double density) {
  if (core::sameValue(solids.diameter, diameter) && core::sameValue(solids.density, density)) return {};
  return "the rheology \"" + name + "\" was measured on grains of diameter " + core::humanNumber(diameter) +
         " m and density " + core::humanNumber(density) + " kg/m3, but solids phase \"" + solids.name + "\" has " +
         core::humanNumber(solids.diameter) + " m and " + core::humanNumber(solids.density) +
         " kg/m3: its inertial numbers would be of other grains";
}

std::vector<SetupProblem> useRheology(MultiFluidSetup& s, const std::vector<core::LoadedRheology>& rheologies) {
  std::vector<SetupProblem> found;
  if (!s.plasticViscosity.inertial) return found;
  auto problem = [&found](std::string what) { found.push_back({"/rheology", std::move(what)}); };
  const std::string& name = s.plasticViscosity.rheology;
  const auto loaded =
      std::find_if(rheologies.begin(), rheologies.end(), [&](const core::LoadedRheology& r) { return r.name == name; });
  if (loaded == rheologies.end()) {
    problem("the mu(I) rheology \"" + name + "\" was not loaded");
    return found;
  }
  const SolidsPhase& phase = s.model.solids.front();
  if (const auto why = rheologyGrainsProblem(phase, name, loaded->diameter, loaded->density); !why.empty()) {
    problem(why);
    return found;
  }
  const core::LoadedRheology::Row* row = loaded->atRestitution(phase.restitution);
  if (row == nullptr) {
    std::string known;
    for (const auto& r : loaded->rows)
      known += (known.empty() ? "" : ", ") + (r.restitution ? core::humanNumber(*r.restitution) : std::string("none"));
    problem("the mu(I) rheology \"" + name + "\" has no row at the solids' restitution " +
            core::humanNumber(phase.restitution) + " (it has: " + known + ")");
    return found;
  }
  const closures::InertialRheology::Grains grains{loaded->diameter, loaded->density};
  try {
    if (s.plasticViscosity.fitted) {
      if (!row->fit) {
        found.push_back({"/rheology_form", "the mu(I) rheology \"" + name + "\" at restitution " +
                                               core::humanNumber(phase.restitution) +
                                               " has no fit (its points did not determine one): use rheology_form "
                                               "\"table\""});
        return found;
      }
      s.model.plastic.params.rheology = closures::InertialRheology::fitted(
          grains, {row->fit->staticRatio, row->fit->limitRatio, row->fit->inertialNumberScale});
    } else {
      s.model.plastic.params.rheology =
          closures::InertialRheology::tabulated(grains, row->inertialNumbers, row->stressRatios);
    }
  } catch (const Error& e) {
    problem("the mu(I) rheology \"" + name + "\": " + e.what());
  }
  return found;
}

}  // namespace grainbridge::mfm
