#include "workflows/stages/TfdemStage.hpp"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <set>

#include "core/Error.hpp"
#include "core/averaging/FieldTimeAverage.hpp"
#include "core/io/FieldFrameReader.hpp"
#include "core/io/FieldFrameWriter.hpp"
#include "core/io/ParticleFrameReader.hpp"
#include "core/text/NumberText.hpp"
#include "engines/fluid/BoundaryFlow.hpp"
#include "engines/tfdem/ParticleBedMeasures.hpp"
#include "workflows/contract/NumericCsv.hpp"
#include "workflows/driver/TimeLoopDriver.hpp"
#include "workflows/stages/BedSummary.hpp"
#include "workflows/stages/DemInitialState.hpp"
#include "workflows/stages/DragSchema.hpp"
#include "workflows/stages/FluidSchema.hpp"
#include "workflows/stages/ParticleSchema.hpp"
#include "workflows/stages/SummaryAverage.hpp"
#include "workflows/stages/TfdemSeriesColumns.hpp"
#include "workflows/stages/TfdemSetup.hpp"

namespace grainbridge::workflows::stages {

using core::units::Dimension;
using nlohmann::json;
using params::ParamSpec;

namespace {

// A multi-contact ratio above this in most samples is the reference's sign that binary
// collisions do not describe the bed (line 1984, Fig. 7.11: "higher than 0.6 most of the time").
constexpr double kMultiContactMark = 0.6;

}  // namespace

TfdemStage::TfdemStage() {
  // The gas: the mfm stage's grid, patches and taps.
  // A 2D bed (cells along z 1) is one particle diameter deep, its gravity in x-y.
  addGasGridParams(schema_);
  schema_.add(ParamSpec::quantity("gas_viscosity", Dimension::viscosity())
                  .defaultValue("1.8e-5 Pa s")
                  .positive()
                  .doc("gas viscosity mu_g (air)"));
  addDragParams(schema_, grainbridge::closures::ErgunWenYuAsPrinted::name,
                "gas-particle drag: Eqs. 7.30-7.31 as printed, Gidaspow's form of them, or the multi-fluid "
                "default Syamlal-O'Brien (Eqs. 3.10-3.16; to compare with a multi-fluid run at equal drag)");
  schema_
      .add(ParamSpec::objectList("boundaries", boundarySchema())
               .required()
               .doc("gas boundary patches; sides no patch covers are no-slip walls (the particles meet plane "
                    "walls on every side)"))
      .add(ParamSpec::objectList("pressure_taps", tapSchema())
               .doc("pairs of heights whose gas pressure difference series.csv records"))
      .add(ParamSpec::quantityList("initial_gas_velocity", Dimension::velocity(), 3)
               .defaultValue(json::array({0, 0, 0}))
               .doc("the gas velocity everywhere at the start (interstitial)"))
      .add(ParamSpec::quantity("fluid_dt", Dimension::timeDim())
               .required()
               .positive()
               .doc("gas step: a whole number of DEM steps dt"))
      .add(ParamSpec::number("courant").defaultValue(0.5).positive().doc("largest inflow |v| fluid_dt / dx"))
      .add(ParamSpec::number("tolerance")
               .defaultValue(1e-4)
               .positive()
               .doc("normalised residuals of a converged gas step"))
      .add(ParamSpec::integer("max_iterations")
               .defaultValue(50)
               .min(1)
               .doc("outer iterations of a gas step; not converged: the run stops"))
      .add(ParamSpec::number("momentum_relaxation").defaultValue(0.9).min(0.0, false).max(1.0).doc("alpha_u"))
      // The particles are given and the gas incompressible: the pressure correction is a Poisson
      // problem the SIMPLE iteration can take whole (omega_P 1: 4.1 outer iterations per gas step
      // on the jet, 6 at MFiX's 0.8), and each momentum system is dominated by its transient term,
      // so Gauss-Seidel sweeps solve it for a fraction of the band LU's work (docs/tfdem.md).
      .add(ParamSpec::number("pressure_relaxation").defaultValue(1.0).min(0.0, false).max(1.0).doc("omega_P"));
  addLinearSolveParams(schema_, "momentum", "gauss_seidel", 1e-6, kPetscOptions,
                       "the gas momentum systems: Gauss-Seidel sweeps or Jacobi-preconditioned BiCGSTAB to "
                       "momentum_solver_tolerance (the band LU where they fail), or the band LU");
  schema_
      // The coupling (docs/tfdem.md).
      .add(ParamSpec::string("deposition")
               .defaultValue("centre_cell")
               .options({"centre_cell", "exact_overlap"})
               .doc("particle volume to the gas cells: all to its centre's cell (Eqs. 7.35-7.36), or by the exact "
                    "sphere-cell overlap"))
      .add(ParamSpec::string("drag_transfer")
               .defaultValue("cell_average")
               .options({"cell_average", "per_particle"})
               .doc("drag on a particle: V_p beta (v_g - v_sm) / eps_s of its cell (Eq. 7.33), or Eq. 7.29's own "
                    "coefficient"))
      .add(ParamSpec::string("gas_reaction")
               .defaultValue("cell_average")
               .options({"cell_average", "summed"})
               .doc("drag on the gas: the cell average (Eq. 7.33), or the particles' recorded drag summed per cell "
                    "and averaged over the sub-steps (Eq. 7.32)"))
      .add(ParamSpec::string("gas_velocity")
               .defaultValue("cell")
               .options({"cell", "interpolated"})
               .doc("per_particle: the gas velocity at a particle, its cell's or interpolated"));
  // The particles: the dem stage's keys.
  addSpeciesParams(schema_);
  schema_.add(ParamSpec::object("wall", contactSchema()).doc("the walls' contact coefficients (default: contact)"));
  addContactModelParams(schema_);
  schema_
      .add(ParamSpec::quantity("dt", Dimension::timeDim())
               .required()
               .positive()
               .doc("DEM time step (at most t_c/10; about t_c/50 recommended)"))
      .add(skinParam())
      .add(seedParam())
      .add(ParamSpec::quantityList("insert_lo", Dimension::lengthDim(), 3)
               .doc("insertion region lower corner (default: the domain)"))
      .add(ParamSpec::quantityList("insert_hi", Dimension::lengthDim(), 3)
               .doc("insertion region upper corner (default: the domain)"))
      .add(ParamSpec::string("planar")
               .defaultValue("")
               .options({"", "x", "y", "z"})
               .doc("no motion along this axis; a 2D bed is planar z whether given or not"))
      // The schedule.
      .add(ParamSpec::quantity("settle_duration", Dimension::timeDim())
               .defaultValue(0.0)
               .min(0.0)
               .doc("the particles settle this long without the gas and without output; then the run's clock "
                    "starts"))
      .add(ParamSpec::quantity("duration", Dimension::timeDim()).required().positive().doc("simulated time"))
      .add(ParamSpec::quantity("output_interval", Dimension::timeDim())
               .defaultValue("0.01 s")
               .positive()
               .doc("series rows: a whole number of gas steps that divides duration"))
      .add(ParamSpec::integer("frames").defaultValue(10).min(0).doc(
          "particle and gas frames after the initial one, evenly spaced"))
      .add(ParamSpec::quantity("average_from", Dimension::timeDim())
               .defaultValue(0.0)
               .min(0.0)
               .doc("start of the time-averaging window"))
      .add(ParamSpec::quantity("average_to", Dimension::timeDim())
               .positive()
               .doc("end of the time-averaging window (default: the end of the run)"))
      .add(ParamSpec::quantity("checkpoint_interval", Dimension::timeDim())
               .defaultValue("600 s")
               .positive()
               .doesNotAffectResults()
               .doc("wall-clock time between checkpoints (one is also written on SIGTERM)"))
      .add(ParamSpec::boolean("progress").defaultValue(true).doesNotAffectResults().doc("show progress"));
}

void TfdemStage::checkParams(const json& p, const std::string& ptr, core::json::Diagnostics& d) const {
  const TfdemStageSetup setup = makeTfdemSetup(p);
  for (const auto& problem : setup.problems) d.add(ptr + problem.pointer, problem.message);
}

void TfdemStage::run(StageContext& ctx) const {
  const json& p = ctx.params();
  const TfdemStageSetup setup = makeTfdemSetup(p);
  if (!setup.problems.empty()) {
    const auto& first = setup.problems.front();
    throw Error("/stages/" + ctx.stage() + "/params" + first.pointer + ": " + first.message);
  }
  std::set<std::string> logged;  // one line per species and the walls (all of one material)
  for (const auto& t : setup.dem.timings) {
    if (!logged.insert(t.pair.substr(0, t.pair.find(" "))).second) continue;
    spdlog::info("{}: pair {}: e_n = {:.4f}, t_c = {} s, dt = t_c/{:.1f}", ctx.stage(), t.pair, t.restitution,
                 core::humanNumber(t.contactTime, 4), t.contactTime / setup.engine.particles.dt);
  }
  spdlog::info("{}: gas step {} s = {} DEM steps", ctx.stage(), core::humanNumber(setup.engine.fluidDt()),
               setup.engine.substeps);

  driver::TimeLoopOptions options;
  options.frames = p.at("frames");
  options.seriesRows = setup.seriesRows;
  options.checkpointEvery = std::chrono::duration<double>(p.at("checkpoint_interval").get<double>());
  options.progress = p.at("progress");
  options.pollEvery = 16;  // a gas step is its sub-steps' DEM steps and a gas solve: milliseconds
  driver::TimeLoopDriver loop(ctx, options);
  const core::io::ArtifactStamp stamp{ctx.key()};
  auto engine = loop.start<tfdem::TfdemEngine>(
      [&] {
        const fluid::StaggeredGrid grid(setup.engine.grid);
        fluid::FlowState gas(grid, 2);
        for (std::size_t c = 0; c < grid.paddedCount(); ++c) {
          gas.pressure[c] = setup.initialPressure;
          for (int a = 0; a < 3; ++a)
            gas.phases[0].velocity[static_cast<std::size_t>(a)][c] = setup.initialGasVelocity[a];
        }
        return std::make_unique<tfdem::TfdemEngine>(setup.engine, insertSpecies(ctx, setup.insertion, setup.dem), gas,
                                                    ctx.outputDir(), stamp);
      },
      [&](const std::filesystem::path& state) {
        return tfdem::TfdemEngine::restore(setup.engine, state, ctx.key(), ctx.outputDir(), stamp);
      });
  tfdem::TfdemEngine& e = *engine;
  if (setup.settleSteps > 0) {
    driver::Phase settling;
    settling.name = "settling";
    settling.steps = setup.settleSteps;
    settling.timed = true;
    settling.configure = [&e] { e.setGasActive(false); };
    settling.leave = [&e, &setup, &ctx] {
      e.setGasActive(true);
      e.restartClock();
      spdlog::info(
          "{}: settled; mean particle height {} m", ctx.stage(),
          core::humanNumber(tfdem::meanParticleHeight(e.simulation().particles(), setup.vertical, setup.bottom), 4));
    };
    loop.addPhase(std::move(settling));
  }
  driver::Phase run;
  run.name = "run";
  run.steps = setup.steps;
  run.output = true;
  run.configure = [&e] { e.setGasActive(true); };
  loop.addPhase(std::move(run));
  loop.addColumns(std::make_unique<TfdemSeriesColumns>(e, setup));
  loop.run(e);

  // The gas's frames, beside the particles'.
  const auto gasDir = ctx.outputDir() / "gas";
  const auto gasFrames = core::io::listFieldFrames(gasDir);
  for (const auto& f : gasFrames) ctx.addArtifact(f.lexically_relative(ctx.outputDir()).string(), "field_frame");
  if (!gasFrames.empty()) ctx.addArtifact("gas/fields.xmf", "xdmf");

  json summary;
  // The window's samples, read back from series.csv and its mean fields from the frames on disk,
  // so that a run resumed from a checkpoint averages what an uninterrupted one does.
  const double slack = 1e-9 * setup.outputInterval;  // round-off in the sampling times
  const auto inWindow = [&](double t) { return t >= setup.averageFrom - slack && t <= setup.averageTo + slack; };
  std::map<std::string, std::vector<double>> window;
  {
    const auto series = contract::readNumericCsv(ctx.outputDir() / "series.csv");
    const auto& time = series.at("time");
    for (const auto& [column, values] : series) {
      auto& kept = window[column];
      for (std::size_t k = 0; k < time.size(); ++k) {
        if (inWindow(time[k])) kept.push_back(values[k]);
      }
    }
  }
  const auto& particles = e.simulation().particles();
  summary["particles"] = static_cast<std::int64_t>(particles.nOwned);
  addTapSummary(summary, setup.taps, window, window.at("time"));
  for (const char* column : {"mean_height", "mean_height_fields", "coordination", "multi_contact_ratio"})
    addAverage(summary, column, window.at(column));
  // What the gas carries: the particles' buoyant weight per unit area of the bottom.
  summary["bed_weight"] =
      tfdem::buoyantWeightPerArea(particles, setup.engine.gas.density, setup.engine.solver.gravity.norm(),
                                  fluid::bottomArea(setup.engine.grid, setup.vertical));
  // The superficial gas velocity the inlets impose, as mfm records it (a fluidization curve's abscissa).
  summary["superficial_gas_velocity"] =
      fluid::superficialGasVelocity(setup.engine.boundaries, setup.engine.grid, setup.vertical);
  const auto& ratios = window.at("multi_contact_ratio");
  if (!ratios.empty()) {
    const auto above = std::count_if(ratios.begin(), ratios.end(), [](double r) { return r > kMultiContactMark; });
    summary["multi_contact_share_above_0.6"] = static_cast<double>(above) / static_cast<double>(ratios.size());
  }
  const auto& iterations = window.at("gas_iterations");
  if (!iterations.empty()) {
    double sum = 0.0;
    for (double v : iterations) sum += v;
    summary["gas_iterations_mean"] = sum / static_cast<double>(iterations.size());
  }
  // The bed as the run starts (after any settling), from its first frame (so a resumed run
  // reports it too): its particles' mean height and, for a bed packed evenly from the floor up,
  // its height, twice that.
  const auto frames = core::io::listParticleFrames(ctx.outputDir());
  if (!frames.empty()) {
    const auto first = core::io::readParticleFrame(frames.front());
    const double start = tfdem::meanParticleHeight(first.position, setup.vertical, setup.bottom);
    summary["start_mean_height"] = start;
    summary["start_bed_height"] = 2.0 * start;
  }
  // The window's time-averaged gas and deposited particle fields, over its gas frames, beside the
  // frames (mean/fields.xmf).
  core::averaging::FieldTimeAverage fields;
  for (const auto& f : gasFrames) {
    auto frame = core::io::readFieldFrame(f);
    if (inWindow(frame.time)) fields.add(frame);
  }
  summary["window_frames"] = fields.frames();
  if (fields.frames() > 0) {
    core::io::FieldFrameWriter mean(ctx.outputDir() / "mean", stamp);
    const auto path = mean.write(fields.mean());
    ctx.addArtifact(path.lexically_relative(ctx.outputDir()).string(), "mean_field_frame");
    ctx.addArtifact("mean/fields.xmf", "xdmf");
  }
  ctx.setSummary(summary);
}

std::optional<PlannedOutput> TfdemStage::plannedOutput(const json& p) const {
  PlannedOutput out;
  out.particleFrames = true;
  const TfdemStageSetup setup = makeTfdemSetup(p);  // the run's own step count
  out.lastFrameTime =
      p.at("frames").get<std::int64_t>() > 0 ? static_cast<double>(setup.steps) * setup.engine.fluidDt() : 0.0;
  out.leesEdwardsShearRate = 0.0;
  std::int64_t count = 0;
  for (const auto& s : p.at("species")) count += s.at("count").get<std::int64_t>();
  out.particleCount = count;
  addTapPlannedOutput(out, p);
  auto& keys = out.summaryKeys;
  for (const char* k : {"mean_height", "mean_height_fields", "bed_weight", "superficial_gas_velocity"})
    keys.push_back(k);
  for (const char* c : {"mean_height", "mean_height_fields", "contacts", "coordination", "multi_contact_ratio"})
    out.seriesColumns.push_back(c);
  // The gas frames (with the deposited particle fraction) at every particle frame, and the
  // window's mean fields over them (average_from before the end is the stage's own rule).
  out.fieldFrames = p.at("frames").get<std::int64_t>() > 0;
  out.meanFieldFrames = out.fieldFrames;
  return out;
}

}  // namespace grainbridge::workflows::stages
