#include "workflows/stages/MfmStage.hpp"

#include <algorithm>
#include <cmath>

#include <spdlog/spdlog.h>
#include "core/Error.hpp"
#include "core/Files.hpp"
#include "core/text/NumberText.hpp"

#include "core/averaging/BlockAverage.hpp"
#include "core/io/FieldFrameWriter.hpp"
#include "engines/fluid/BedMeasures.hpp"
#include "engines/fluid/BoundaryFlow.hpp"
#include "engines/fluid/FrameMaps.hpp"
#include "engines/mfm/InitialBed.hpp"
#include "engines/mfm/MfmEngine.hpp"
#include "workflows/closures/ClosureCatalog.hpp"
#include "workflows/contract/NumericCsv.hpp"
#include "workflows/driver/TimeLoopDriver.hpp"
#include "workflows/report/BedTables.hpp"
#include "workflows/stages/BedSummary.hpp"
#include "workflows/stages/ClosureSamples.hpp"
#include "workflows/stages/DragSchema.hpp"
#include "workflows/stages/FluidSchema.hpp"
#include "workflows/stages/MfmSeriesColumns.hpp"
#include "workflows/stages/MfmSetup.hpp"
#include "workflows/stages/SummaryAverage.hpp"

namespace grainbridge::workflows::stages {

namespace catalog = workflows::closures;
using core::units::Dimension;
using nlohmann::json;
using params::ParamSchema;
using params::ParamSpec;

namespace {

std::shared_ptr<const ParamSchema> solidsSchema() {
  auto s = std::make_shared<ParamSchema>();
  s->add(ParamSpec::string("name").required().doc("phase name (field frames, series columns)"))
      .add(ParamSpec::quantity("diameter", Dimension::lengthDim()).required().positive().doc("particle diameter d_p"))
      .add(ParamSpec::quantity("density", Dimension::density()).required().positive().doc("material density rho_s"))
      .add(ParamSpec::number("restitution")
               .defaultValue(0.9)
               .min(0.0, false)
               .max(1.0)
               .doc("particle-particle restitution e (Eqs. 3.23-3.25, 5.7)"))
      .add(ParamSpec::number("wall_restitution")
               .min(0.0, false)
               .max(1.0)
               .doc("particle-wall restitution e_w of Johnson-Jackson walls (Eq. 5.9); default: restitution"))
      .add(ParamSpec::number("friction")
               .defaultValue(0.0)
               .min(0.0)
               .doc("rotation model: particle-particle Coulomb friction mu (Eqs. 5.12-5.17; Table 5.1)"))
      .add(ParamSpec::number("wall_friction")
               .defaultValue(0.0)
               .min(0.0)
               .doc("rotation model: particle-wall Coulomb friction mu_w (Eq. 5.21; Table 5.1)"))
      .add(ParamSpec::number("tangential_restitution")
               .defaultValue(0.33)
               .min(-1.0)
               .max(1.0)
               .doc("rotation model: beta0 of Eq. 5.17, both contacts (Table 5.1)"))
      .add(ParamSpec::number("max_packing")
               .defaultValue(0.6)
               .min(0.0, false)
               .max(1.0, false)
               .doc("packing_limit yu_standish or gera: the packing fraction of this kind alone (MFiX's ep_s_max, "
                    "0.6 by default)"));
  return s;
}

// A pair of solids phases and their drag, Eq. 3.18 (engines/closures/SolidsSolidsDrag).
std::shared_ptr<const ParamSchema> solidsPairSchema() {
  auto s = std::make_shared<ParamSchema>();
  s->add(ParamSpec::stringList("phases").required().doc("the two solids phases, by name"))
      .add(catalog::closureParameter("solids_drag", "friction_coefficient").renamed("friction"))
      .add(catalog::closureParameter("solids_drag", "restitution")
               .withoutDefault()
               .doc("e_lm; default: the mean of the two phases' restitution (e, not e_eff, with the rotation "
                    "model)"));
  return s;
}

// The two phases of the segregation percentage, Eqs. 5.23-5.25.
std::shared_ptr<const ParamSchema> segregationSchema() {
  auto s = std::make_shared<ParamSchema>();
  s->add(ParamSpec::string("small").required().doc("the small particles' phase, by name"))
      .add(ParamSpec::string("large").required().doc("the large particles' phase, by name"));
  return s;
}

std::shared_ptr<const ParamSchema> regionSchema() {
  auto s = std::make_shared<ParamSchema>();
  s->add(ParamSpec::quantityList("lo", Dimension::lengthDim(), 3).required().doc("lower corner (cell centres inside)"))
      .add(ParamSpec::quantityList("hi", Dimension::lengthDim(), 3).required().doc("upper corner"))
      .add(ParamSpec::quantityList("solids_fractions", Dimension::none(), 0)
               .required()
               .doc("each solids phase's fraction; the gas takes the rest"))
      .add(ParamSpec::quantityList("gas_velocity", Dimension::velocity(), 3)
               .defaultValue(json::array({0, 0, 0}))
               .doc("gas velocity (interstitial)"))
      .add(ParamSpec::quantityList("solids_velocity", Dimension::velocity(), 3)
               .defaultValue(json::array({0, 0, 0}))
               .doc("velocity of every solids phase"))
      .add(ParamSpec::number("granular_temperature")
               .defaultValue(0.0)
               .min(0.0)
               .doc("theta of every solids phase, m^2/s^2 (granular_energy pde)"));
  return s;
}

}  // namespace

MfmStage::MfmStage() {
  addGasGridParams(schema_);
  schema_
      .add(ParamSpec::string("gas_model")
               .defaultValue("incompressible")
               .options({"incompressible", "ideal"})
               .doc("incompressible (gas_density), or an ideal gas rho_g = P M / (R T) with absolute pressures"))
      .add(ParamSpec::number("gas_molar_mass").defaultValue(0.028964).positive().doc("ideal gas: M in kg/mol (air)"))
      .add(ParamSpec::number("gas_temperature").defaultValue(293.15).positive().doc("ideal gas: T in K"))
      .add(ParamSpec::quantity("gas_viscosity", Dimension::viscosity())
               .defaultValue("1.8e-5 Pa s")
               .positive()
               .doc("gas viscosity mu_g (VALIDATION.md: the reference gives none; air)"))
      .add(ParamSpec::objectList("solids", solidsSchema()).required().doc("solids phases"))
      .add(ParamSpec::objectList("solids_pairs", solidsPairSchema())
               .doc("solids-solids drag (Eq. 3.18) of pairs of solids phases; a pair not listed has C_f 0 and "
                    "e_lm the mean of the two restitutions"));
  // The drag law and its parameters' keys (drag_c, drag_d), from the drag law list: each law
  // declares its parameters once, as the closure catalog lists them.
  addDragParams(schema_, grainbridge::closures::SyamlalOBrien::name, "gas-solids drag law (Eqs. 3.10-3.16 by default)");
  schema_
      .add(ParamSpec::string("kinetic_model")
               .defaultValue("lun1984")
               .options({"lun1984", "lun1984_mfix", "syamlal_algebraic", "syamlal_algebraic_mfix"})
               .doc("kinetic theory of the viscous regime: Lun et al. 1984 with Ma-Ahmadi (Chapter 5), or "
                    "Eqs. 3.21-3.25 as printed or with MFiX's (3e+1)/2"))
      .add(ParamSpec::string("closure")
               .defaultValue("ktgf")
               .options({"ktgf", "table"})
               .doc("solids closures: kinetic theory (kinetic_model), or DEM closure tables from the workflow "
                    "database for table_quantities with kinetic_model for the rest"))
      .add(ParamSpec::string("closure_table")
               .doc("closure \"table\": the tables' name (a tabulate stage's `table`; give that stage in `from` "
                    "when this workflow makes them)"))
      .add(ParamSpec::stringList("table_quantities")
               .defaultValue(json::array({"pressure", "shear_viscosity", "dissipation"}))
               .options({"pressure", "shear_viscosity", "dissipation"})
               .doc("closure \"table\": what the tables supply (p_theta, eta_theta, j_theta); conductivity, bulk "
                    "viscosity and the gas terms always come from kinetic_model"))
      .add(ParamSpec::string("out_of_range")
               .options({"error", "clamp", "kinetic_theory"})
               .doc("closure \"table\", required: a state outside a table stops the run, takes the table's edge "
                    "value, or kinetic_model's (counted in the summary's table coverage)"));
  addClosureSampleParams(schema_);
  schema_
      .add(ParamSpec::string("granular_energy")
               .defaultValue("pde")
               .options({"pde", "algebraic"})
               .doc("theta from the granular-energy equation (Eq. 3.34), or MFiX's algebraic balance "
                    "(syamlal kinetic models only)"))
      .add(ParamSpec::object("segregation", segregationSchema())
               .doc("a binary bed's segregation percentage s_p (Eqs. 5.23-5.25): series, window mean, 1 s "
                    "block means (segregation_blocks.csv) and per-phase eps_s against height (profiles.csv)"))
      .add(ParamSpec::string("radial_distribution")
               .options({"carnahan_starling", "lebowitz"})
               .doc("g0 at contact: Carnahan-Starling (one solids phase; its default) or Lebowitz (the default and "
                    "only choice for several, with MFiX's mixture sums in the kinetic theory)"))
      .add(ParamSpec::string("plastic_theta")
               .defaultValue("solved")
               .options({"solved", "pinned"})
               .doc("theta where eps_g < critical_void_fraction: solved there too (kinetic stress adds to the "
                    "plastic one), or pinned near zero as MFiX does (the plastic stress alone)"))
      .add(ParamSpec::string("plastic_pressure")
               .defaultValue("shared")
               .options({"shared", "per_phase"})
               .doc("several solids phases: the plastic pressure and viscosity (Eqs. 3.26-3.27) of the cell's void "
                    "fraction, eps_sm P*(eps_g) (MFiX), or of each phase's own packing, eps_sm P*(1 - eps_sm), a "
                    "diagnostic that keeps one phase's packing from pushing another; one phase: the same"))
      .add(ParamSpec::string("mixture_kinetic_theory")
               .defaultValue("summed")
               .options({"summed", "per_phase"})
               .doc("several solids phases: each phase's contacts with every phase, sum_l eps_l g0_ml (MFiX since "
                    "2005), or with its own kind, eps_sm g0_mm, as Eqs. 3.21-3.25, 5.7 and 5.20 are printed "
                    "(granular_energy pde)"))
      .add(ParamSpec::string("packing_limit")
               .defaultValue("fixed")
               .options({"fixed", "yu_standish", "gera"})
               .doc("eps_g* of several solids phases: critical_void_fraction everywhere, or each cell's from its "
                    "composition and the phases' max_packing (Yu-Standish 1987; Gera's binary Fedors-Landel), as "
                    "MFiX 2003-05 did; one phase keeps critical_void_fraction"))
      .add(ParamSpec::string("solids_walls")
               .defaultValue("no_slip")
               .options({"no_slip", "johnson_jackson"})
               .doc("solids at no-slip wall patches: stick (adiabatic), or Johnson-Jackson partial slip with the "
                    "wall energy flux (Eqs. 5.8-5.10; granular_energy pde)"))
      .add(catalog::closureParameter("johnson_jackson", "specularity"))
      .add(ParamSpec::boolean("rotation_model")
               .defaultValue(false)
               .doc("particle rotation (Eqs. 5.11-5.21): e_eff from each phase's friction in the collisional and "
                    "wall dissipation only (granular_energy pde)"))
      .add(catalog::closureParameter("schaeffer", "critical_void_fraction"))
      .add(catalog::closureParameter("schaeffer", "internal_friction_angle").renamed("friction_angle"))
      .add(ParamSpec::string("plastic")
               .defaultValue("schaeffer")
               .options({"schaeffer", "mu_i"})
               .doc("frictional viscosity below critical_void_fraction: Schaeffer's P* sin(friction_angle) / "
                    "(2 sqrt(I2D)), or mu(I) P_s / (2 sqrt(I2D)) with mu(I) from a DEM rheology (`rheology`; "
                    "one solids phase)"))
      .add(ParamSpec::string("rheology")
               .doc("plastic mu_i: the mu(I) rheology, a tabulate stage's `table` (in `from` or in the database), "
                    "at the solids' restitution and of their diameter and density"))
      .add(ParamSpec::string("rheology_form")
               .defaultValue("fit")
               .options({"fit", "table"})
               .doc("plastic mu_i: the rheology's fit mu_s + (mu_2 - mu_s) / (1 + I_0 / I), or its points "
                    "(linear in I, held at the ends)"))
      .add(ParamSpec::number("packed_solids_fraction")
               .min(0.0, false)
               .max(1.0, false)
               .doc("eps_s,max: the packed solids fraction of Eq. 3.68 and the initial states' bound "
                    "(default 1 - critical_void_fraction)"))
      .add(ParamSpec::objectList("boundaries", boundarySchema())
               .required()
               .doc("boundary patches; sides no patch covers are no-slip walls"))
      .add(ParamSpec::objectList("regions", regionSchema()).doc("initial regions, later over earlier; elsewhere gas"))
      .add(ParamSpec::quantity("reference_pressure", Dimension::pressure())
               .defaultValue("101325 Pa")
               .doc("initial gas pressure at the top; below it each cell carries the mixture above"))
      .add(ParamSpec::number("perturbation")
               .defaultValue(0.0)
               .min(0.0)
               .max(0.5)
               .doc("relative random lowering of the initial solids fractions (breaks a uniform bed's symmetry)"))
      .add(ParamSpec::integer("seed").defaultValue(1).min(0).doc("seed of the perturbation"))
      .add(ParamSpec::quantity("duration", Dimension::timeDim()).required().positive().doc("simulated time"))
      .add(ParamSpec::quantity("output_interval", Dimension::timeDim())
               .defaultValue("0.01 s")
               .positive()
               .doc("series rows (and the frames' grid of times): a divisor of duration"))
      .add(
          ParamSpec::integer("frames").defaultValue(10).min(0).doc("field frames after the initial one, evenly spaced"))
      .add(ParamSpec::quantity("average_from", Dimension::timeDim())
               .defaultValue(0.0)
               .min(0.0)
               .doc("start of the time-averaging window"))
      .add(ParamSpec::quantity("average_to", Dimension::timeDim())
               .positive()
               .doc("end of the time-averaging window (default: the end of the run), as tfdem's"))
      .add(ParamSpec::objectList("pressure_taps", tapSchema())
               .doc("pairs of heights whose gas pressure difference series.csv records"))
      .add(ParamSpec::quantity("dt", Dimension::timeDim()).defaultValue("1e-4 s").positive().doc("first time step"))
      .add(ParamSpec::quantity("dt_min", Dimension::timeDim())
               .defaultValue("1e-7 s")
               .positive()
               .doc("smallest step before a non-converging run stops"))
      .add(ParamSpec::quantity("dt_max", Dimension::timeDim())
               .defaultValue("1e-3 s")
               .positive()
               .doc("largest step (dt_min = dt_max: a fixed step)"))
      .add(ParamSpec::number("courant").defaultValue(0.5).positive().doc("largest |v| dt / dx"))
      .add(
          ParamSpec::number("tolerance").defaultValue(1e-4).positive().doc("normalised residuals of a converged step"));
  addLinearSolveParams(schema_, "momentum", "direct", 1e-6, kPetscOptions,
                       "every phase's momentum systems: the band LU, or Jacobi-preconditioned BiCGSTAB or Gauss-Seidel "
                       "sweeps to momentum_solver_tolerance (the LU where they fail); iterative on 3D grids, whose "
                       "band (nx ny) makes the LU slow");
  addLinearSolveParams(schema_, "pressure", "direct", 1e-8, kPetscOptions,
                       "the gas pressure correction: the band LU, or BiCGSTAB or Gauss-Seidel to "
                       "pressure_solver_tolerance");
  addLinearSolveParams(schema_, "fraction", "direct", 1e-10, kPetscOptions,
                       "each solids phase's fraction correction (Eq. 3.69) and closing continuity solve: the LU, or "
                       "BiCGSTAB or Gauss-Seidel to fraction_solver_tolerance, whose closing solve is then finished in "
                       "flux form so the mass balance stays exact (the LU where that would leave more than a "
                       "round-off below zero); gauss_seidel on 3D grids");
  schema_
      .add(
          ParamSpec::integer("max_iterations").defaultValue(50).min(1).doc("outer iterations before a step is retried"))
      .add(ParamSpec::boolean("detect_stall")
               .defaultValue(true)
               .doc("MFiX's DETECT_STALL: retry a step at half its size as soon as its largest residual has not "
                    "fallen over 5 iterations (checked from the 15th), instead of after max_iterations"))
      .add(ParamSpec::number("momentum_relaxation").defaultValue(0.9).min(0.0, false).max(1.0).doc("alpha_u"))
      .add(ParamSpec::number("pressure_relaxation").defaultValue(0.8).min(0.0, false).max(1.0).doc("omega_P"))
      .add(ParamSpec::number("fraction_relaxation")
               .defaultValue(0.5)
               .min(0.0, false)
               .max(1.0)
               .doc("omega_eps of Eq. 3.68 (packed cells)"))
      .add(ParamSpec::number("dilute_fraction")
               .defaultValue(1e-4)
               .min(0.0)
               .doc("solids faces below this fraction have no momentum equation, and cells below it take their "
                    "neighbours' granular temperature (MFiX DIL_EP_S)"))
      .add(ParamSpec::quantity("checkpoint_interval", Dimension::timeDim())
               .defaultValue("600 s")
               .positive()
               .doesNotAffectResults()
               .doc("wall-clock time between checkpoints (one is also written on SIGTERM)"))
      .add(ParamSpec::boolean("progress").defaultValue(true).doesNotAffectResults().doc("show progress"));
}

void MfmStage::checkParams(const json& p, const std::string& ptr, core::json::Diagnostics& d) const {
  const MfmSetup setup = makeMfmSetup(p);
  for (const auto& [where, what] : setup.problems) d.add(ptr + where, what);
  // No diagnostics channel carries warnings: they go to the log while the config is checked.
  for (const auto& [where, what] : setup.warnings) spdlog::warn("{}{}: {}", ptr, where, what);
  if (asksForClosureSamples(p) && p.at("closure").get<std::string>() != "table") {
    d.add(ptr + tableErrorsNeededBy(p),
          "closure samples draw DEM closure tables within their errors: they need "
          "closure \"table\" (closure is \"" +
              p.at("closure").get<std::string>() + "\")");
  }
  // A spread needs two samples of one kind (report/ClosureSpread); refuse what would fail bed_compare.
  if (asksForClosureSamples(p) && p.at("closure_samples").get<int>() < 2 &&
      p.at("closure_samples_per_quantity").get<int>() < 2) {
    d.add(ptr + tableErrorsNeededBy(p),
          "one closure sample gives no spread: ask for at least 2 joint samples "
          "(closure_samples) or 2 per quantity (closure_samples_per_quantity)");
  }
}

std::vector<Replica> MfmStage::replicas(const json& p) const {
  if (p.at("closure").get<std::string>() != "table") return {Replica{}};
  // The samples draw the closure tables the run reads (not its mu(I) rheology).
  std::vector<std::string> quantities;
  for (const auto& ref : closureTables(p)) {
    if (ref.quantity != core::kRheologyQuantity) quantities.push_back(ref.quantity);
  }
  return closureSampleReplicas(p, quantities);
}

std::string MfmStage::tableErrorsNeededBy(const json& p) const {
  if (p.value("closure_samples", 0) > 0) return "/closure_samples";
  if (p.value("closure_samples_per_quantity", 0) > 0) return "/closure_samples_per_quantity";
  return "";
}

std::vector<ClosureTableRef> MfmStage::closureTables(const json& p) const {
  std::vector<ClosureTableRef> refs;
  if (p.at("closure").get<std::string>() == "table" && p.contains("closure_table")) {
    for (const auto& q : p.at("table_quantities")) {
      refs.push_back({p.at("closure_table").get<std::string>(), tableQuantity(q.get<std::string>()), "/closure_table"});
    }
  }
  if (p.at("plastic").get<std::string>() == "mu_i" && p.contains("rheology"))
    refs.push_back({p.at("rheology").get<std::string>(), core::kRheologyQuantity, "/rheology"});
  return refs;
}

void MfmStage::checkTableGrains(const json& p, const std::string& ptr, const ClosureTableRef& ref, const Grains& grains,
                                core::json::Diagnostics& d) const {
  if (ref.quantity != core::kRheologyQuantity) return;
  if (const auto why = rheologyGrainsProblem(p, grains); !why.empty()) d.add(ptr + ref.pointer, why);
}

void MfmStage::checkAgainstUpstream(const json& p, const std::string& ptr, const std::vector<UpstreamPlan>& upstream,
                                    core::json::Diagnostics& d) const {
  const bool table = p.at("closure").get<std::string>() == "table";
  const bool muOfI = p.at("plastic").get<std::string>() == "mu_i";
  for (const auto& up : upstream) {
    if (!up.output.closureTables) {
      d.add(ptr, "`from` " + up.stage + ": an mfm stage takes only tabulate stages (whose tables it reads)");
      continue;
    }
    const std::string& made = *up.output.closureTables;
    const bool readsTables = table && p.value("closure_table", "") == made;
    const bool readsRheology = muOfI && p.value("rheology", "") == made;
    if (!readsTables && !readsRheology) {
      d.add(ptr + "/closure_table", "`from` " + up.stage + " makes the tables \"" + made +
                                        "\", which this stage does not read (closure \"table\" with that "
                                        "closure_table, or plastic \"mu_i\" with that rheology)");
    }
    // The DEM's grains, handed on through extract and tabulate by the config loader.
    if (readsRheology && up.output.grains) {
      checkTableGrains(p, ptr, {made, core::kRheologyQuantity, "/rheology"}, *up.output.grains, d);
    }
  }
}

void MfmStage::run(StageContext& ctx) const {
  const json& p = ctx.params();
  // A closure sample runs on its draw of the tables; the nominal run on the tables themselves.
  const std::vector<core::LoadedClosureTable> tables = sampleClosureTables(p, ctx.closureTables());
  const MfmSetup setup = makeMfmSetup(p, &tables, &ctx.rheologies());
  if (!setup.problems.empty()) {
    throw Error("/stages/" + ctx.stage() + "/params" + setup.problems.front().pointer + ": " +
                setup.problems.front().message);
  }
  driver::TimeLoopOptions options;
  const auto steps = mfmSteps(p);
  options.frames = p.at("frames");
  options.seriesRows = steps;
  options.checkpointEvery = std::chrono::duration<double>(p.at("checkpoint_interval").get<double>());
  options.progress = p.at("progress");
  options.pollEvery = 1;  // one engine step is a whole output interval
  driver::TimeLoopDriver loop(ctx, options);
  const core::io::ArtifactStamp stamp{ctx.key()};
  auto engine = loop.start<mfm::MfmEngine>(
      [&] {
        return std::make_unique<mfm::MfmEngine>(
            setup.engine, [&](mfm::MultiFluidEngine& e) { mfm::initialise(e, setup.initial); }, ctx.outputDir(), stamp);
      },
      [&](const std::filesystem::path& state) {
        return mfm::MfmEngine::restore(setup.engine, state, ctx.key(), ctx.outputDir(), stamp);
      });
  engine->mutableEngine().onRetry([&ctx](const std::string& why) { spdlog::info("{}: {}", ctx.stage(), why); });
  driver::Phase run;
  run.name = "run";
  run.steps = steps;
  run.output = true;
  loop.addPhase(std::move(run));
  const auto& solids = setup.engine.model.solids;
  auto columns = std::make_unique<MfmSeriesColumns>(*engine, setup, ctx.stage());
  MfmSeriesColumns& observed = *columns;
  // The initial inventory (of a fresh start, also when this run resumes): solids volume and the
  // bed's buoyant weight per unit area of the bottom.
  const mfm::InitialInventory inventory = mfm::initialInventory(setup.engine, setup.initial);
  const std::vector<double>& initialVolumes = inventory.solidsVolume;
  const double initialWeight = inventory.buoyantWeight;
  loop.addColumns(std::move(columns));
  loop.run(*engine);

  // Time averages over the window: the summary's values with block-averaging errors, and the
  // mean fields beside the frames (mean/fields.xmf).
  json summary;
  const auto& window = observed.windowSamples();
  addTapSummary(summary, setup.taps, window, observed.windowTimes());
  for (std::size_t m = 0; m < solids.size(); ++m) {
    addAverage(summary, "mean_height_" + solids[m].name, window.at("mean_height_" + solids[m].name));
  }
  if (solids.size() == 1) {
    addAverage(summary, "mean_height", window.at("mean_height_" + solids[0].name));
  } else if (solids.size() > 1) {
    // Eq. 5.22 over all solids, sample by sample.
    std::vector<double> mixture;
    for (std::size_t k = 0; k < window.at("mean_height_" + solids[0].name).size(); ++k) {
      std::vector<double> heights, volumes;
      for (const auto& phase : solids) {
        heights.push_back(window.at("mean_height_" + phase.name)[k]);
        volumes.push_back(window.at("solids_volume_" + phase.name)[k]);
      }
      mixture.push_back(fluid::mixtureMeanHeight(heights, volumes));
    }
    addAverage(summary, "mean_height", mixture);
  }
  // The colour key of comparing stages: the closure the solids ran with.
  summary["closure"] =
      setup.engine.model.closure.kind() == "table" ? std::string("table") : p.at("kinetic_model").get<std::string>();
  const auto& stats = engine->engine().statistics();
  summary["solver_steps"] = stats.steps;
  summary["retries"] = stats.retries;
  summary["retried_iterations"] = stats.retriedIterations;
  summary["iterations_per_step"] = stats.steps > 0 ? static_cast<double>(stats.iterations) / stats.steps : 0.0;
  summary["window_samples"] = observed.fieldAverage().frames();
  // The superficial gas velocity the inlets impose (engines/fluid/BoundaryFlow): a fluidization
  // curve's abscissa, recorded so that the curve's reader needs none of this run's params.
  summary["superficial_gas_velocity"] = fluid::superficialGasVelocity(
      setup.engine.patches, setup.engine.geometry, fluid::verticalAxis(setup.engine.settings.gravity));
  // What a fluidization curve is read against: the initial bed's buoyant weight per unit area of
  // the bottom, (1 - eps) (rho_s - rho_g) g H, and the minimum fluidization velocity the drag law
  // implies at the first region holding solids (engines/mfm/InitialBed).
  if (!solids.empty()) {
    summary["bed_weight"] = initialWeight;
    if (const auto umf = mfm::dragMinimumFluidizationVelocity(setup.engine, setup.initial)) summary["drag_umf"] = *umf;
  }
  if (setup.engine.model.closure.kind() == "table") {
    // The share of the bed the tables covered, by cell-steps and by solids volume, over every
    // converged step and the cells holding solids; the rest took the out-of-range policy.
    summary["table_cell_steps"] = stats.tableCellSteps;
    summary["table_coverage_cell_steps"] =
        stats.tableCellSteps > 0 ? static_cast<double>(stats.coveredCellSteps) / stats.tableCellSteps : 0.0;
    summary["table_coverage_solids"] =
        stats.tableSolidsSteps > 0.0 ? stats.coveredSolidsSteps / stats.tableSolidsSteps : 0.0;
    for (const auto& loaded : ctx.closureTables()) summary["table_sha256_" + loaded.quantity()] = loaded.sha256;
    addClosureSampleSummary(p, summary);
  }
  // Which mu(I) the plastic regime took (plastic mu_i).
  if (const auto& rheology = setup.engine.model.plastic.params.rheology) {
    summary["plastic_rheology"] = p.at("rheology_form").get<std::string>() + ": " + rheology->describe();
    for (const auto& loaded : ctx.rheologies()) summary["rheology_sha256"] = loaded.sha256;
  }
  // The relative change of the solids inventory over the run, per phase and of all solids.
  double totalNow = 0.0, totalInitial = 0.0;
  for (std::size_t m = 0; m < solids.size(); ++m) {
    const double now = fluid::solidsVolume(engine->engine().state(), m + 1);
    totalNow += now;
    totalInitial += initialVolumes[m];
    if (initialVolumes[m] > 0.0) summary["solids_volume_change_" + solids[m].name] = now / initialVolumes[m] - 1.0;
  }
  if (totalInitial > 0.0) summary["solids_volume_change"] = totalNow / totalInitial - 1.0;
  // Each phase's mass account: (held - held0 - in + out) / max(in, held0), round-off for the
  // solids (their closing continuity solves move exactly what crosses the boundary), the
  // continuity tolerance for the gas.
  {
    const auto held = engine->engine().heldMass();
    std::vector<std::string> phases{"gas"};
    for (const auto& phase : solids) phases.push_back(phase.name);
    for (std::size_t m = 0; m < phases.size(); ++m) {
      const auto [in, out] = fluid::total(stats.boundaryMass[m]);
      const double held0 = stats.initialMass[m];
      const double scale = std::max(in, held0);
      summary["mass_in_" + phases[m]] = in;
      summary["mass_out_" + phases[m]] = out;
      summary["mass_balance_" + phases[m]] = scale > 0.0 ? (held[m] - held0 - in + out) / scale : 0.0;
    }
  }
  if (setup.segregation) {
    addAverage(summary, "segregation_percentage", window.at("segregation_percentage"));
    summary["segregation_small_share"] = setup.segregation->smallShare;
    // s_p's 1 s means over the whole run, read back from series.csv so that a resumed run's
    // blocks hold the samples before the restart too; each phase's eps_s over the width of the
    // window's mean fields against height (Fig. 5.6).
    const auto series = contract::readNumericCsv(ctx.outputDir() / "series.csv");
    core::writeFileAtomically(ctx.outputDir() / "segregation_blocks.csv",
                              report::timeBlockMeansCsv(series.at("time"), series.at("segregation_percentage"),
                                                        "segregation_percentage", 1.0));
    ctx.addArtifact("segregation_blocks.csv", "segregation_blocks_csv");
    if (observed.fieldAverage().frames() > 0) {
      std::vector<report::HeightColumn> profiles;
      std::vector<double> heights;
      for (std::size_t m = 0; m < solids.size(); ++m) {
        auto profile = fluid::solidsFractionProfile(observed.fieldAverage().mean(), m);
        heights = profile.heights;
        profiles.push_back({"ep_s_" + solids[m].name, std::move(profile.fraction)});
      }
      core::writeFileAtomically(ctx.outputDir() / "profiles.csv", report::heightProfilesCsv(heights, profiles));
      ctx.addArtifact("profiles.csv", "profiles_csv");
    }
  }
  if (observed.fieldAverage().frames() > 0) {
    core::io::FieldFrameWriter mean(ctx.outputDir() / "mean", stamp);
    const auto path = mean.write(observed.fieldAverage().mean());
    ctx.addArtifact(path.lexically_relative(ctx.outputDir()).string(), "mean_field_frame");
    ctx.addArtifact("mean/fields.xmf", "xdmf");
  }
  ctx.setSummary(summary);
}

std::optional<PlannedOutput> MfmStage::plannedOutput(const json& p) const {
  PlannedOutput out;
  out.fieldFrames = true;
  out.meanFieldFrames = p.at("average_from").get<double>() < p.at("duration").get<double>();
  addTapPlannedOutput(out, p);
  auto& keys = out.summaryKeys;
  const json solids = p.value("solids", json::array());
  if (!solids.empty()) {
    keys.push_back("mean_height");
    keys.push_back("solids_volume_change");
    keys.push_back("bed_weight");
  }
  for (const auto& phase : solids) {
    const std::string name = phase.at("name");
    keys.push_back("mean_height_" + name);
    keys.push_back("solids_volume_change_" + name);
    out.seriesColumns.push_back("mean_height_" + name);
    out.seriesColumns.push_back("solids_volume_" + name);
  }
  if (p.contains("segregation")) {
    keys.push_back("segregation_percentage");
    keys.push_back("segregation_small_share");
    out.seriesColumns.push_back("segregation_percentage");
  }
  if (!solids.empty()) out.seriesColumns.push_back("plastic_solids_share");
  if (p.value("granular_energy", "pde") == "pde") {
    for (const auto& phase : solids) out.seriesColumns.push_back("theta_" + phase.at("name").get<std::string>());
  }
  keys.push_back("closure");
  keys.push_back("superficial_gas_velocity");
  // The mass account of every phase, the gas first.
  std::vector<std::string> phases{"gas"};
  for (const auto& phase : solids) phases.push_back(phase.at("name").get<std::string>());
  for (const auto& phase : phases) {
    for (const char* k : {"mass_in_", "mass_out_", "mass_balance_"}) keys.push_back(k + phase);
  }
  std::vector<std::string> sides;
  for (const auto& patch : p.value("boundaries", json::array())) {
    sides.push_back(patch.value("kind", "") == "pressure_outlet" ? patch.value("side", "") : "");
  }
  for (auto& column : massAccountColumns(phases, sides)) out.seriesColumns.push_back(std::move(column));
  addClosureSamplePlannedOutput(p, out);
  return out;
}

}  // namespace grainbridge::workflows::stages
