#include "workflows/stages/DemStage.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <sstream>

#include "core/Error.hpp"
#include "core/Log.hpp"
#include "core/text/NumberText.hpp"
#include "engines/dem/DemEngine.hpp"
#include "engines/dem/contact/Conversions.hpp"
#include "engines/particle_engines/ParticleEngines.hpp"
#include "workflows/driver/TimeLoopDriver.hpp"
#include "workflows/stages/DemInitialState.hpp"
#include "workflows/stages/DemSeriesColumns.hpp"
#include "workflows/stages/DemSetup.hpp"
#include "workflows/stages/ParticleSchema.hpp"

namespace grainbridge::workflows::stages {

using core::units::Dimension;
using nlohmann::json;
using params::ParamSchema;
using params::ParamSpec;

namespace {

// Steps of the run proper: the duration in whole steps (a last partial step is a whole one).
std::int64_t runSteps(const json& p) {
  return static_cast<std::int64_t>(std::ceil(p.at("duration").get<double>() / p.at("dt").get<double>() - 1e-9));
}

std::shared_ptr<ParamSchema> wallSchema() {
  auto s = std::make_shared<ParamSchema>();
  s->add(ParamSpec::string("kind")
             .required()
             .options({"plane", "cylinder"})
             .doc("plane, or cylinder with particles inside"))
      .add(ParamSpec::quantityList("point", Dimension::lengthDim(), 3)
               .required()
               .doc("a point on the plane, or on the cylinder axis"))
      .add(ParamSpec::quantityList("direction", Dimension::none(), 3)
               .required()
               .doc("plane normal pointing into the domain, or cylinder axis"))
      .add(
          ParamSpec::quantity("radius", Dimension::lengthDim()).defaultValue(0.0).min(0.0).doc("cylinder inner radius"))
      .add(ParamSpec::quantity("vibration_amplitude", Dimension::lengthDim())
               .defaultValue(0.0)
               .min(0.0)
               .doc("A of A sin(2 pi f t), or of A (1 - cos 2 pi f t) with vibration_start at_rest"))
      .add(ParamSpec::quantity("vibration_frequency", Dimension::frequency())
               .defaultValue(0.0)
               .min(0.0)
               .doc("f (ordinary frequency)"))
      .add(ParamSpec::quantityList("vibration_direction", Dimension::none(), 3)
               .defaultValue(json::array({0, 0, 1}))
               .doc("direction of vibration"))
      .add(ParamSpec::string("vibration_start")
               .defaultValue("mid_stroke")
               .options({"mid_stroke", "at_rest"})
               .doc("mid_stroke: A sin(2 pi f t), through the rest position at full speed at t = 0; at_rest: "
                    "A (1 - cos 2 pi f t), from rest (LAMMPS's wiggle)"));
  addContactParams(*s);
  return s;
}

std::shared_ptr<ParamSchema> placeSchema() {
  auto s = std::make_shared<ParamSchema>();
  s->add(ParamSpec::string("species").required().doc("species of the placed particle (counted in its count)"))
      .add(ParamSpec::quantityList("position", Dimension::lengthDim(), 3).required().doc("centre"));
  return s;
}

// Section 6.2's two-step preparation: shake the whole container at high frequency with some
// particles held in place, then let the bed relax, then release them.
std::shared_ptr<ParamSchema> pressureControlSchema() {
  auto s = std::make_shared<ParamSchema>();
  s->add(ParamSpec::quantity("stress", Dimension::pressure())
             .required()
             .doc("target normal stress p_yy along the gradient (Eq. 2.3)"))
      .add(ParamSpec::quantity("relaxation_time", Dimension::timeDim())
               .required()
               .doc("time constant of the box's relaxation towards the target"))
      .add(ParamSpec::integer("interval").defaultValue(10).doc("steps between box adjustments"));
  return s;
}

std::shared_ptr<ParamSchema> compressionSchema() {
  auto s = std::make_shared<ParamSchema>();
  s->add(ParamSpec::number("from_solid_fraction")
             .defaultValue(0.3)
             .doc("the solid fraction the grains are inserted at, in box_hi's box made longer along y"))
      .add(ParamSpec::quantity("duration", Dimension::timeDim())
               .required()
               .doc("time from the run's start over which the box shrinks linearly to box_hi"))
      .add(ParamSpec::integer("interval").defaultValue(10).doc("steps between box changes"));
  return s;
}

std::shared_ptr<ParamSchema> preparationSchema() {
  auto s = std::make_shared<ParamSchema>();
  s->add(
       ParamSpec::string("hold_species").defaultValue("").doc("species held fixed (infinite mass) during preparation"))
      .add(ParamSpec::quantity("shake_amplitude", Dimension::lengthDim())
               .required()
               .min(0.0)
               .doc("amplitude of the preparation shaking (all walls, along z)"))
      .add(ParamSpec::quantity("shake_frequency", Dimension::frequency())
               .required()
               .min(0.0)
               .doc("frequency of the preparation shaking"))
      .add(ParamSpec::quantity("shake_duration", Dimension::timeDim()).required().min(0.0).doc("time shaken"))
      .add(ParamSpec::quantity("relax_duration", Dimension::timeDim())
               .required()
               .min(0.0)
               .doc("time left to relax without shaking"));
  return s;
}

std::shared_ptr<ParamSchema> lammpsTypeSchema() {
  auto s = std::make_shared<ParamSchema>();
  s->add(ParamSpec::integer("type").required().min(1).doc("LAMMPS atom type"))
      .add(ParamSpec::string("species").required().doc("species its atoms become"))
      .add(ParamSpec::boolean("frozen").defaultValue(false).doc("hold these atoms fixed (a frozen rough base)"));
  return s;
}

std::vector<double> speciesRadii(const DemSetup& setup) {
  std::vector<double> radii;
  for (const auto& s : setup.species) radii.push_back(s.radius);
  return radii;
}

}  // namespace

DemStage::DemStage() {
  schema_.add(ParamSpec::quantityList("box_lo", Dimension::lengthDim(), 3).required().doc("lower corner of the domain"))
      .add(ParamSpec::quantityList("box_hi", Dimension::lengthDim(), 3).required().doc("upper corner of the domain"))
      .add(ParamSpec::string("periodic").defaultValue("").doc("periodic axes, e.g. \"xy\""))
      .add(ParamSpec::quantityList("gravity", Dimension::acceleration(), 3)
               .defaultValue(json::array({0, 0, -9.81}))
               .doc("gravitational acceleration; default along -z, where a dem bed stands (mfm and tfdem: along "
                    "-y, the vertical of their 2D x-y grids)"))
      .add(ParamSpec::quantity("dt", Dimension::timeDim())
               .required()
               .positive()
               .doc("time step (at most t_c/10; about t_c/50 recommended)"))
      .add(ParamSpec::quantity("duration", Dimension::timeDim()).required().positive().doc("simulated time"))
      .add(ParamSpec::integer("frames").defaultValue(10).min(0).doc(
          "particle + contact frames after the initial one, evenly spaced"))
      .add(ParamSpec::integer("series_points").defaultValue(200).min(1).doc("rows of series.csv, evenly spaced"))
      .add(skinParam())
      .add(ParamSpec::string("engine")
               .defaultValue("grainbridge")
               .options(particle_engines::particleEngineNames())
               .doc("who runs the steps: grainbridge's own engine, or LAMMPS's GRANULAR package through "
                    "liblammps on the instance's ranks (docs/dem.md lists what it refuses)"));
  addContactModelParams(schema_);
  schema_
      .add(ParamSpec::quantity("shear_rate", Dimension::frequency())
               .defaultValue(0.0)
               .doc("Lees-Edwards simple shear rate: u_x = shear_rate (y - y_mid), needs periodic \"xy\""))
      .add(ParamSpec::object("pressure_control", pressureControlSchema())
               .doc("hold p_yy at a target by relaxing the box length along y (sheared box periodic in xyz, no "
                    "walls; docs/dem.md)"))
      .add(ParamSpec::object("compression", compressionSchema())
               .doc("insert dilute in a box longer along y, shrink it to box_hi, then hold it: a fixed-volume "
                    "sheared box above the 0.38 random insertion reaches (periodic in xyz, no walls; docs/dem.md)"))
      .add(ParamSpec::quantity("background_damping", Dimension{0, 1, -1})
               .defaultValue(0.0)
               .min(0.0)
               .doc("b of Eq. 6.7 (force -b v)"))
      .add(seedParam());
  addSpeciesParams(schema_);  // species, contact, pair_contacts: tfdem's particles declare the same
  schema_.add(ParamSpec::objectList("walls", wallSchema()).doc("rigid walls (infinite mass), each with its own material"))
      .add(ParamSpec::string("planar")
               .defaultValue("")
               .options({"", "x", "y", "z"})
               .doc("2-D bed: no motion along this axis, rotation about it only"))
      .add(ParamSpec::number("max_initial_overlap")
               .defaultValue(0.01)
               .min(0.0)
               .doc("largest overlap of a state read from a file, in smaller diameters"))
      .add(ParamSpec::inputFile("initial_frame")
               .doc("start from a saved particle frame (frames/particles_*.h5); species by index"))
      .add(ParamSpec::inputFile("lammps_data")
               .doc("start from a LAMMPS data file (atom_style sphere) instead of random insertion"))
      .add(ParamSpec::objectList("lammps_types", lammpsTypeSchema()).doc("LAMMPS atom type -> species (and frozen)"))
      .add(ParamSpec::objectList("place", placeSchema())
               .doc("particles placed at given positions before random insertion"))
      .add(ParamSpec::object("preparation", preparationSchema())
               .doc("two-step preparation before the run (Section 6.2); the run's clock starts after it"))
      .add(ParamSpec::string("insertion")
               .defaultValue("random")
               .options({"random", "fcc_lattice"})
               .doc("random non-overlapping insertion, or an fcc lattice with random vacancies (dense states "
                    "above about 0.38 solid fraction, where random insertion jams)"))
      .add(ParamSpec::quantity("initial_temperature", Dimension::granularTemperature())
               .defaultValue("0 m2/s2")
               .min(0.0)
               .doc("granular temperature T = <C^2>/3 of Maxwellian velocity fluctuations (zero total momentum) "
                    "given to inserted particles on top of the streaming profile; an unperturbed sheared "
                    "lattice below about 0.3 solid fraction slides without a collision"))
      .add(ParamSpec::quantityList("insert_lo", Dimension::lengthDim(), 3)
               .doc("insertion region lower corner (default: the box)"))
      .add(ParamSpec::quantityList("insert_hi", Dimension::lengthDim(), 3)
               .doc("insertion region upper corner (default: the box)"))
      .add(ParamSpec::integerList("track_ids", 0)
               .defaultValue(json::array())
               .min(0)
               .doc("particle ids whose height (z) series.csv records as z_id<N>"))
      .add(ParamSpec::quantity("checkpoint_interval", Dimension::timeDim())
               .defaultValue("600 s")
               .positive()
               .doesNotAffectResults()
               .doc("wall-clock time between checkpoints (one is also written on SIGTERM)"))
      .add(ParamSpec::boolean("progress").defaultValue(true).doesNotAffectResults().doc("show progress"))
      .atMostOneOf({"lammps_data", "initial_frame"}, "the initial state read from a file")
      .goTogether({"lammps_data", "lammps_types"}, "the atoms and the species their types become");
}

void DemStage::checkParams(const json& p, const std::string& ptr, core::json::Diagnostics& d) const {
  const std::string periodic = p.at("periodic");
  for (char c : periodic) {
    if (c != 'x' && c != 'y' && c != 'z')
      d.add(ptr + "/periodic", "expected letters from \"xyz\", found \"" + periodic + "\"");
  }
  // The run proper's steps; the preparation writes no frame.
  const std::int64_t steps = runSteps(p);
  if (const auto why = driver::framesProblem(p.at("frames").get<std::int64_t>(), steps,
                                             std::to_string(steps) + " steps (duration " +
                                                 core::humanNumber(p.at("duration").get<double>()) + " s / dt " +
                                                 core::humanNumber(p.at("dt").get<double>()) + " s)");
      !why.empty())
    d.add(ptr + "/frames", why);
  if ((p.contains("lammps_data") || p.contains("initial_frame")) && p.at("initial_temperature").get<double>() > 0.0) {
    d.add(ptr + "/initial_temperature",
          "applies to inserted particles; a state from lammps_data or initial_frame keeps its own velocities");
  }
  // The contact checks list SetupProblems (the one problem type); each is reported where it is found.
  auto report = [&d, &ptr](std::vector<core::engine::SetupProblem> problems) {
    for (auto& problem : problems) d.add(ptr + problem.pointer, std::move(problem.message));
  };
  report(checkSpeciesParams(p));
  std::set<std::string> names;
  for (const auto& s : p.at("species")) names.insert(s.at("name").get<std::string>());
  std::map<std::string, std::int64_t> placedOf;
  if (p.contains("place")) {
    for (std::size_t k = 0; k < p["place"].size(); ++k) {
      const std::string sp = p["place"][k].at("species");
      if (names.count(sp) == 0)
        d.add(ptr + "/place/" + std::to_string(k) + "/species", "no species named \"" + sp + "\"");
      ++placedOf[sp];
    }
    for (const auto& s : p.at("species")) {
      if (placedOf[s.at("name")] > s.at("count").get<std::int64_t>())
        d.add(ptr + "/place",
              "more particles of species \"" + s.at("name").get<std::string>() + "\" placed than its count");
    }
  }
  if (p.contains("lammps_types")) {
    for (std::size_t k = 0; k < p["lammps_types"].size(); ++k) {
      const std::string sp = p["lammps_types"][k].at("species");
      if (names.count(sp) == 0)
        d.add(ptr + "/lammps_types/" + std::to_string(k) + "/species", "no species named \"" + sp + "\"");
    }
  }
  std::int64_t particleCount = 0;
  for (const auto& s : p.at("species")) particleCount += s.at("count").get<std::int64_t>();
  const bool fromFile = p.contains("lammps_data") || p.contains("initial_frame");
  for (std::size_t k = 0; k < p.at("track_ids").size(); ++k) {
    // An integer >= 0 by declaration. Inserted particles get ids 0..count-1; a state from a file
    // brings its own ids, checked at the start of the run.
    const auto id = p["track_ids"][k].get<std::int64_t>();
    if (!fromFile && id >= particleCount) {
      d.add(ptr + "/track_ids/" + std::to_string(k), "no particle with id " + std::to_string(id) +
                                                         " (ids run from 0 to " + std::to_string(particleCount - 1) +
                                                         ")");
    }
  }
  if (p.at("insertion") == "fcc_lattice") {
    if (p.contains("place")) d.add(ptr + "/place", "placed particles and insertion \"fcc_lattice\" exclude each other");
    if (p.contains("walls")) {
      for (const auto& w : p["walls"]) {
        if (w.at("kind") == "cylinder") d.add(ptr + "/insertion", "an fcc lattice fills a box, not a cylinder");
      }
    }
  }
  if (p.contains("compression")) {
    const std::string where = ptr + "/compression";
    if (p.contains("preparation")) d.add(where, "compression and a preparation exclude each other");
    if (fromFile) d.add(where, "compression starts from inserted grains, not from lammps_data or initial_frame");
    if (!(p["compression"].at("duration").get<double>() < p.at("duration").get<double>())) {
      d.add(where + "/duration", "the compression takes " +
                                     core::humanNumber(p["compression"].at("duration").get<double>()) +
                                     " s of a run of " + core::humanNumber(p.at("duration").get<double>()) +
                                     " s: it must end before the run does, or no frame is of the held box");
    }
    const double from = p["compression"].at("from_solid_fraction");
    const double held = speciesSolidFraction(p);
    if (!(from > 0.0)) {
      d.add(where + "/from_solid_fraction", "must be positive, found " + core::humanNumber(from));
    } else if (!(held > from)) {
      d.add(where + "/from_solid_fraction", "the species fill " + core::humanNumber(held) +
                                                " of box_hi's box, no more than the " + core::humanNumber(from) +
                                                " they are inserted at: nothing to compress");
    }
  }
  if (p.contains("preparation")) {
    const std::string hold = p["preparation"].at("hold_species");
    if (!hold.empty() && names.count(hold) == 0)
      d.add(ptr + "/preparation/hold_species", "no species named \"" + hold + "\"");
  }
  if (p.contains("walls")) {
    for (std::size_t w = 0; w < p["walls"].size(); ++w) {
      const json& wj = p["walls"][w];
      const std::string where = ptr + "/walls/" + std::to_string(w);
      report(checkContactKeys(wj, p, "/walls/" + std::to_string(w)));
      const auto& dir = wj.at("direction");
      if (std::hypot(dir[0].get<double>(), dir[1].get<double>(), dir[2].get<double>()) == 0.0)
        d.add(where + "/direction", "direction must not be zero");
      if (wj.at("kind") == "cylinder" && !(wj.at("radius").get<double>() > 0.0))
        d.add(where + "/radius", "a cylinder needs a positive radius");
    }
  }
  const auto& engine = particle_engines::particleEngine(p.at("engine").get<std::string>());
  if (const std::string why = engine.unavailable(); !why.empty()) d.add(ptr + "/engine", why);
  if (!engine.preparation && p.contains("preparation")) {
    d.add(ptr + "/preparation", "engine " + engine.name +
                                    ": the two-step preparation (held species, shaken container) is "
                                    "grainbridge's own; prepare the state with engine grainbridge and start from "
                                    "its frame (initial_frame)");
  }
  if (!d.empty()) return;
  const DemSetup setup = makeDemSetup(p);
  for (const auto& problem : engine.problems(setup.engine, speciesRadii(setup))) {
    // Pair coefficients come from `contact` unless pair_contacts overrides some.
    const bool fromContact = problem.pointer == "/pair_contacts" && !p.contains("pair_contacts");
    d.add(ptr + (fromContact ? "/contact" : problem.pointer), problem.message);
  }
  // The engine's own rules (box, periodic lengths, shear, neighbour grid, a run without
  // particles), written once in dem::SimulationSetup, at the pointers of the keys the engine setup
  // shares with these params. A state read from a file is not counted: an upstream stage may
  // write it after this check.
  double maxDiameter = 0.0;
  for (const auto& s : setup.species) maxDiameter = std::max(maxDiameter, 2.0 * s.radius);
  const auto inserted = fromFile ? std::nullopt : std::optional<std::int64_t>(particleCount);
  for (const auto& problem : setup.engine.problems(maxDiameter, inserted))
    d.add(ptr + problem.pointer, problem.message);
  // Spheres that cannot all be inserted at random fail the run at its start, after the stages
  // before it ran: refused here from their volume.
  if (const auto problem = randomInsertionProblem(p.get<InsertionChoice>(), setup, "box_lo/box_hi"))
    d.add(ptr + problem->pointer, problem->message + "; or use insertion \"fcc_lattice\" for a denser start");
  report(checkContactTimes(setup, p.at("dt")));
}

namespace {

void logContactTimes(const StageContext& ctx, const DemSetup& setup) {
  for (const auto& t : setup.timings) {
    spdlog::info("{}: pair {}: e_n = {:.4f}, t_c = {} s, largest safe dt (t_c/10) = {} s{}", ctx.stage(), t.pair,
                 t.restitution, core::humanNumber(t.contactTime, 4), core::humanNumber(t.contactTime / 10.0, 4),
                 t.exact ? "" : " (linear-spring estimate: a Hertzian e_n depends on the impact speed)");
    if (setup.engine.dt > t.contactTime / 20.0) {
      spdlog::warn("{}: dt = {} s is above t_c/20 for pair {} (the reference recommends about t_c/50)", ctx.stage(),
                   core::humanNumber(setup.engine.dt, 4), t.pair);
    }
  }
}

// A state read from a file whose worst overlap is beyond max_initial_overlap is refused, naming
// the pair (before the first step, rather than let the springs explode).
void refuseOverlappingState(const StageContext& ctx, const dem::Simulation& sim) {
  const json& p = ctx.params();
  const auto worst = sim.largestOverlap();
  if (worst.relative > p.at("max_initial_overlap").get<double>()) {
    throw Error("/stages/" + ctx.stage() + "/params/" + (p.contains("lammps_data") ? "lammps_data" : "initial_frame") +
                ": particles " + std::to_string(worst.i) + " and " + std::to_string(worst.j) + " overlap by " +
                std::to_string(worst.relative) + " of the smaller diameter, above max_initial_overlap = " +
                std::to_string(p.at("max_initial_overlap").get<double>()));
  }
}

// The side wall of a run in a container: its first cylinder wall, or null.
const dem::Wall* sideWall(const dem::SimulationSetup& engine) {
  for (const auto& wall : engine.walls) {
    if (wall.kind == dem::Wall::Kind::Cylinder && !wall.material.empty()) return &wall;
  }
  return nullptr;
}

// The initial particles of a fresh run: inserted, or read from a file (lammps_data,
// initial_frame); a state from a file whose particles overlap too much is refused before any
// engine starts.
bool stateFromFile(const json& p) { return p.contains("lammps_data") || p.contains("initial_frame"); }
dem::Particles initialParticles(const StageContext& ctx, const DemSetup& setup) {
  const json& p = ctx.params();
  if (!stateFromFile(p)) return insertSpecies(ctx, p.get<InsertionChoice>(), setup);
  dem::Particles particles =
      p.contains("lammps_data") ? readLammpsParticles(p, setup, ctx.units()) : readFrameParticles(p, setup);
  refuseOverlappingState(ctx, dem::Simulation(setup.engine, particles));
  return particles;
}

// A state from a file brings its own ids: the tracked ones must be among them.
void checkTrackedIds(StageContext& ctx, const DemSetup& setup, dem::ParticleEngine& engine, const dem::DemEngine* own) {
  // On several ranks (engine lammps) the frame is gathered on the first.
  if (setup.trackedIds.empty() || ctx.comm().rank() != 0) return;
  auto has = [&](std::int64_t id) {
    if (own != nullptr) return own->simulation().indexOf(id).has_value();
    const auto& ids = engine.frame().id;
    return std::find(ids.begin(), ids.end(), id) != ids.end();
  };
  for (std::size_t k = 0; k < setup.trackedIds.size(); ++k) {
    if (!has(setup.trackedIds[k])) {
      throw Error("/stages/" + ctx.stage() + "/params/track_ids/" + std::to_string(k) + ": no particle with id " +
                  std::to_string(setup.trackedIds[k]) + " in the initial state");
    }
  }
}

// The run proper after the engine is built (fresh or resumed), on either engine: the
// preparation phases (grainbridge's engine only), the run, the series and the summary.
void runLoop(StageContext& ctx, const DemSetup& setup, driver::TimeLoopDriver& loop, dem::ParticleEngine& engine,
             dem::DemEngine* own) {
  const json& p = ctx.params();
  checkTrackedIds(ctx, setup, engine, own);
  if (p.contains("preparation")) {
    GB_ASSERT(own != nullptr, "a preparation is refused on engine lammps at check");
    for (auto& phase : preparationPhases(ctx, setup, *own)) loop.addPhase(std::move(phase));
  }
  const auto steps = runSteps(p);
  driver::Phase run;
  run.name = "run";
  run.steps = steps;
  run.output = true;
  loop.addPhase(std::move(run));
  for (auto& columns : demSeriesColumns(engine, setup)) loop.addColumns(std::move(columns));
  loop.run(engine);

  const auto e = engine.energies();
  const auto& last = engine.frame();
  const std::int64_t mobile = engine.mobileCount();
  json summary = {{"particles", engine.workItems()},
                  {"steps", steps},
                  {"final_ke_translational", e.translational},
                  {"final_ke_rotational", e.rotational},
                  {"final_contacts", last.contacts.size()},
                  {"final_coordination",
                   mobile > 0 ? 2.0 * static_cast<double>(last.contacts.size()) / static_cast<double>(mobile) : 0.0}};
  // LAMMPS does not count its rebuilds for the library.
  if (engine.neighbourRebuilds() >= 0) summary["neighbour_rebuilds"] = engine.neighbourRebuilds();
  // What the state was made with, for the labels of reports, which read products and never
  // params: the seed of the random insertion (a state read from a file has none) and the
  // friction of the side wall, the first cylinder wall, where there is one.
  if (!stateFromFile(p)) summary["seed"] = p.at("seed");
  if (const auto* side = sideWall(setup.engine)) summary["side_wall_friction"] = side->material.front().mu;
  ctx.setSummary(std::move(summary));
}

}  // namespace

void DemStage::run(StageContext& ctx) const {
  const json& p = ctx.params();
  const DemSetup setup = makeDemSetup(p);
  logContactTimes(ctx, setup);

  driver::TimeLoopOptions options;
  options.frames = p.at("frames");
  options.seriesRows = p.at("series_points");
  options.checkpointEvery = std::chrono::duration<double>(p.at("checkpoint_interval").get<double>());
  options.progress = p.at("progress");
  driver::TimeLoopDriver loop(ctx, options);
  // The engine the params name (checked at load), on the instance's ranks.
  const auto& kind = particle_engines::particleEngine(p.at("engine").get<std::string>());
  const dem::ParticleEngineStart start{setup.engine,    speciesRadii(setup),
                                       runSteps(p),     ctx.comm().isMpi() ? ctx.comm().raw() : MPI_COMM_NULL,
                                       ctx.outputDir(), core::io::ArtifactStamp{ctx.key()}};
  auto engine = loop.start<dem::ParticleEngine>(
      [&] { return kind.fresh(start, initialParticles(ctx, setup)); },
      [&](const std::filesystem::path& state) { return kind.restore(start, state, ctx.key()); });
  // Every frame carries the materials its readers need (core/data/Materials), fresh or resumed.
  engine->setMaterials(setup.materials);
  // grainbridge's own engine offers more than a ParticleEngine: the preparation phases and the
  // lookup of tracked ids run on it.
  runLoop(ctx, setup, loop, *engine, dynamic_cast<dem::DemEngine*>(engine.get()));
}

// Frames at t = 0 (the initial state, after any preparation) and, with frames > 0, evenly up to
// the last step; the step count is the one run() takes, ceil(duration / dt).
std::optional<PlannedOutput> DemStage::plannedOutput(const json& p) const {
  PlannedOutput out;
  out.particleFrames = true;
  // The run's clock starts at 0 after any preparation; its last frame is its last step.
  out.lastFrameTime =
      p.at("frames").get<std::int64_t>() > 0 ? static_cast<double>(runSteps(p)) * p.at("dt").get<double>() : 0.0;
  out.leesEdwardsShearRate = p.at("shear_rate").get<double>();
  if (!p.contains("lammps_data") && !p.contains("initial_frame")) {
    std::int64_t count = 0;
    for (const auto& s : p.at("species")) count += s.at("count").get<std::int64_t>();
    out.particleCount = count;
    out.summaryKeys.push_back("seed");
  }
  for (const auto& wall : p.value("walls", json::array())) {
    if (wall.at("kind") == "cylinder") {
      out.summaryKeys.push_back("side_wall_friction");
      break;
    }
  }
  // One kind of mobile grain (frozen bases aside) is what a rheology can be made of.
  for (const auto& s : p.at("species")) {
    if (s.at("frozen").get<bool>()) continue;
    const Grains g{s.at("diameter").get<double>(), s.at("density").get<double>()};
    if (!out.grains) {
      out.grains = g;
    } else if (out.grains->diameter != g.diameter || out.grains->density != g.density) {
      out.grains.reset();
      break;
    }
  }
  return out;
}

}  // namespace grainbridge::workflows::stages
