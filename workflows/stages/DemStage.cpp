#include "workflows/stages/DemStage.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <sstream>

#include "core/Error.hpp"
#include "core/FailPoint.hpp"
#include "core/Files.hpp"
#include "core/Log.hpp"
#include "core/Progress.hpp"
#include "core/io/ParticleFrameWriter.hpp"
#include "engines/dem/Checkpoint.hpp"
#include "engines/dem/DomainStress.hpp"
#include "workflows/stages/DemInitialState.hpp"
#include "workflows/stages/DemSetup.hpp"

namespace grainbridge::workflows::stages {

using core::units::Dimension;
using nlohmann::json;
using params::ParamSchema;
using params::ParamSpec;

namespace {

// The contact coefficients shared by particle pairs and walls (Eqs. 6.5-6.6, Table 6.1).
void addContactParams(ParamSchema& s) {
  s.add(ParamSpec::quantity("kn", Dimension::stiffness())
            .required()
            .positive()
            .doc("normal spring constant k_n (Eq. 6.5)"))
      .add(ParamSpec::quantity("kt", Dimension::stiffness())
               .min(0.0)
               .doc("tangential spring constant k_t (default 2/7 k_n)"))
      .add(ParamSpec::quantity("gamma_n", Dimension::frequency())
               .min(0.0)
               .doc("normal damping gamma_n, times m_eff in Eq. 6.5 (or give restitution)"))
      .add(ParamSpec::number("restitution")
               .min(0.0, false)
               .max(1.0)
               .doc("normal restitution e_n: gamma_n from Eqs. 6.9-6.10 with each pair's m_eff"))
      .add(ParamSpec::quantity("gamma_t", Dimension::frequency())
               .defaultValue(0.0)
               .min(0.0)
               .doc("tangential damping gamma_t (Eq. 6.6)"))
      .add(ParamSpec::number("mu").defaultValue(0.5).min(0.0).doc("Coulomb friction coefficient"))
      .exactlyOneOf({"gamma_n", "restitution"}, "the normal damping");
}

std::shared_ptr<ParamSchema> speciesSchema() {
  auto s = std::make_shared<ParamSchema>();
  s->add(ParamSpec::string("name").required().doc("species name"))
      .add(ParamSpec::quantity("diameter", Dimension::lengthDim()).required().positive().doc("sphere diameter"))
      .add(ParamSpec::quantity("density", Dimension::density()).required().positive().doc("material density"))
      .add(ParamSpec::integer("count").defaultValue(0).min(0).doc(
          "number of spheres inserted at random (0 with lammps_data)"))
      .add(ParamSpec::boolean("frozen").defaultValue(false).doc("fixed in place with infinite mass (rough bases)"));
  return s;
}

std::shared_ptr<ParamSchema> contactSchema() {
  auto s = std::make_shared<ParamSchema>();
  addContactParams(*s);
  return s;
}

// Coefficients for one species pair, replacing `contact` for it.
std::shared_ptr<ParamSchema> pairContactSchema() {
  auto s = std::make_shared<ParamSchema>();
  s->add(ParamSpec::string("species").required().doc("one species of the pair"))
      .add(ParamSpec::string("with").required().doc("the other species (may be the same)"));
  addContactParams(*s);
  return s;
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
               .doc("A of A sin(2 pi f t)"))
      .add(ParamSpec::quantity("vibration_frequency", Dimension::frequency())
               .defaultValue(0.0)
               .min(0.0)
               .doc("f (ordinary frequency)"))
      .add(ParamSpec::quantityList("vibration_direction", Dimension::none(), 3)
               .defaultValue(json::array({0, 0, 1}))
               .doc("direction of vibration"));
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

}  // namespace

DemStage::DemStage() {
  schema_.add(ParamSpec::quantityList("box_lo", Dimension::lengthDim(), 3).required().doc("lower corner of the domain"))
      .add(ParamSpec::quantityList("box_hi", Dimension::lengthDim(), 3).required().doc("upper corner of the domain"))
      .add(ParamSpec::string("periodic").defaultValue("").doc("periodic axes, e.g. \"xy\""))
      .add(ParamSpec::quantityList("gravity", Dimension::acceleration(), 3)
               .defaultValue(json::array({0, 0, -9.81}))
               .doc("gravitational acceleration"))
      .add(ParamSpec::quantity("dt", Dimension::timeDim())
               .required()
               .positive()
               .doc("time step (at most t_c/10; about t_c/50 recommended)"))
      .add(ParamSpec::quantity("duration", Dimension::timeDim()).required().positive().doc("simulated time"))
      .add(ParamSpec::integer("frames").defaultValue(10).min(0).doc(
          "particle + contact frames after the initial one, evenly spaced"))
      .add(ParamSpec::integer("series_points").defaultValue(200).min(1).doc("rows of series.csv, evenly spaced"))
      .add(ParamSpec::number("skin").defaultValue(0.3).min(0.0).doc("Verlet skin, in largest diameters"))
      .add(ParamSpec::string("normal_model")
               .defaultValue("linear")
               .options({"linear", "hertz"})
               .doc("f(delta/d) of Eq. 6.5: 1 or sqrt(delta/d)"))
      .add(ParamSpec::quantity("shear_rate", Dimension::frequency())
               .defaultValue(0.0)
               .doc("Lees-Edwards simple shear rate: u_x = shear_rate (y - y_mid), needs periodic \"xy\""))
      .add(ParamSpec::quantity("background_damping", Dimension{0, 1, -1})
               .defaultValue(0.0)
               .min(0.0)
               .doc("b of Eq. 6.7 (force -b v)"))
      .add(ParamSpec::integer("seed").defaultValue(1).min(0).doc("random seed of the insertion"))
      .add(ParamSpec::objectList("species", speciesSchema()).required().doc("particle species"))
      .add(ParamSpec::object("contact", contactSchema()).required().doc("particle-particle contact coefficients"))
      .add(ParamSpec::objectList("pair_contacts", pairContactSchema())
               .doc("coefficients of particular species pairs (others use contact)"))
      .add(ParamSpec::objectList("walls", wallSchema()).doc("rigid walls (infinite mass), each with its own material"))
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
  for (int a = 0; a < 3; ++a) {
    if (!(p.at("box_hi")[a].get<double>() > p.at("box_lo")[a].get<double>())) {
      d.add(ptr + "/box_hi/" + std::to_string(a), "box_hi must exceed box_lo on every axis");
    }
  }
  if (p.at("shear_rate").get<double>() != 0.0 &&
      (periodic.find('x') == std::string::npos || periodic.find('y') == std::string::npos)) {
    d.add(ptr + "/shear_rate", "Lees-Edwards shear needs periodic \"x\" (flow) and \"y\" (gradient)");
  }
  if ((p.contains("lammps_data") || p.contains("initial_frame")) && p.at("initial_temperature").get<double>() > 0.0) {
    d.add(ptr + "/initial_temperature",
          "applies to inserted particles; a state from lammps_data or initial_frame keeps its own velocities");
  }
  std::set<std::string> names;
  for (std::size_t i = 0; i < p.at("species").size(); ++i) {
    if (!names.insert(p["species"][i].at("name").get<std::string>()).second)
      d.add(ptr + "/species/" + std::to_string(i) + "/name", "species name used twice");
  }
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
  if (p.contains("pair_contacts")) {
    for (std::size_t k = 0; k < p["pair_contacts"].size(); ++k) {
      const json& pc = p["pair_contacts"][k];
      const std::string where = ptr + "/pair_contacts/" + std::to_string(k);
      for (const char* f : {"species", "with"}) {
        if (names.count(pc.at(f).get<std::string>()) == 0)
          d.add(where + "/" + f, "no species named \"" + pc.at(f).get<std::string>() + "\"");
      }
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
  if (p.contains("preparation")) {
    const std::string hold = p["preparation"].at("hold_species");
    if (!hold.empty() && names.count(hold) == 0)
      d.add(ptr + "/preparation/hold_species", "no species named \"" + hold + "\"");
  }
  if (p.contains("walls")) {
    for (std::size_t w = 0; w < p["walls"].size(); ++w) {
      const json& wj = p["walls"][w];
      const std::string where = ptr + "/walls/" + std::to_string(w);
      const auto& dir = wj.at("direction");
      if (std::hypot(dir[0].get<double>(), dir[1].get<double>(), dir[2].get<double>()) == 0.0)
        d.add(where + "/direction", "direction must not be zero");
      if (wj.at("kind") == "cylinder" && !(wj.at("radius").get<double>() > 0.0))
        d.add(where + "/radius", "a cylinder needs a positive radius");
    }
  }
  if (!d.empty()) return;
  const DemSetup setup = makeDemSetup(p);
  // One periodic image per neighbour: a periodic length must exceed twice the interaction
  // range (largest diameter + skin).
  double maxDiameter = 0.0;
  for (const auto& s : setup.species) maxDiameter = std::max(maxDiameter, 2.0 * s.radius);
  const double range = maxDiameter + setup.engine.skin;
  for (int a = 0; a < 3; ++a) {
    const double length = setup.engine.hi[a] - setup.engine.lo[a];
    if (setup.engine.periodic[static_cast<std::size_t>(a)] && length < 2.0 * range) {
      std::ostringstream msg;
      msg << "the periodic length along "
          << "xyz"[a] << " is " << length << " m, less than twice the interaction range " << range
          << " m (largest diameter + skin)";
      d.add(ptr + "/box_hi/" + std::to_string(a), msg.str());
    }
  }
  // Every pair must rebound (not overdamped) and be resolved in time: dt <= t_c/10.
  const double dt = p.at("dt");
  for (const auto& t : setup.timings) {
    if (!std::isfinite(t.contactTime)) {
      d.add(ptr + t.pointer, "pair " + t.pair +
                                 " is overdamped (gamma_n^2/4 >= k_n/m_eff): no rebound and no contact time (Eq. "
                                 "6.10); lower gamma_n or raise k_n");
    } else if (dt > t.contactTime / 10.0) {
      std::ostringstream msg;
      msg << "dt = " << dt << " s is above t_c/10 = " << t.contactTime / 10.0 << " s of pair " << t.pair
          << " (t_c from Eq. 6.10); the reference recommends about t_c/50";
      d.add(ptr + "/dt", msg.str());
    }
  }
}

namespace {

std::string csvHeader(const DemSetup& s) {
  std::string h = "time,step,ke_translational,ke_rotational,contacts,coordination";
  for (const char* c : {"xx", "yy", "zz", "xy", "xz", "yz"}) h += std::string(",stress_") + c;
  for (std::size_t w = 0; w < s.engine.walls.size(); ++w) {
    for (const char* c : {"x", "y", "z"}) h += ",wall" + std::to_string(w) + "_f" + c;
  }
  for (const auto& sp : s.species) h += ",com_z_" + sp.name;
  for (const auto& sp : s.species) h += ",top_z_" + sp.name;  // highest z + a: the free surface
  for (const auto id : s.trackedIds) h += ",z_id" + std::to_string(id);
  return h + "\n";
}

}  // namespace

void DemStage::run(StageContext& ctx) const {
  const json& p = ctx.params();
  const DemSetup setup = makeDemSetup(p);
  for (const auto& t : setup.timings) {
    spdlog::info("{}: pair {}: e_n = {:.4f}, t_c = {:.4g} s, largest safe dt (t_c/10) = {:.4g} s", ctx.stage(), t.pair,
                 t.restitution, t.contactTime, t.contactTime / 10.0);
    if (setup.engine.dt > t.contactTime / 20.0) {
      spdlog::warn("{}: dt = {:.4g} s is above t_c/20 for pair {} (the reference recommends about t_c/50)", ctx.stage(),
                   setup.engine.dt, t.pair);
    }
  }

  const std::filesystem::path checkpointFile = ctx.checkpointDir() / "engine.h5";
  const std::filesystem::path checkpointSeries = ctx.checkpointDir() / "series.csv";
  // A checkpoint taken during the preparation lives in its own file: its step counter counts
  // preparation steps, and the run proper has not started.
  const std::filesystem::path preparationCheckpointFile = ctx.checkpointDir() / "preparation.h5";
  const auto checkpointEvery = std::chrono::duration<double>(p.at("checkpoint_interval").get<double>());
  std::optional<dem::Simulation> simulation;
  std::ostringstream series;
  series.precision(17);
  if (std::filesystem::exists(checkpointFile)) {
    // Resume: the state continues bit for bit, and the series rows written so far come back.
    simulation.emplace(setup.engine, dem::readCheckpoint(checkpointFile, ctx.key()));
    series << core::readFile(checkpointSeries);
    spdlog::info("{}: resuming from the checkpoint at step {}", ctx.stage(), simulation->stepCount());
  } else {
    if (std::filesystem::exists(preparationCheckpointFile)) {
      simulation.emplace(setup.engine, dem::readCheckpoint(preparationCheckpointFile, ctx.key()));
    } else {
      const bool fromFile = p.contains("lammps_data") || p.contains("initial_frame");
      simulation.emplace(setup.engine, p.contains("lammps_data")     ? readLammpsParticles(p, setup)
                                       : p.contains("initial_frame") ? readFrameParticles(p, setup)
                                                                     : insertSpecies(ctx, setup));
      if (fromFile) {
        // A state from a file may overlap: refuse it before the first step rather than let the
        // springs explode.
        const auto worst = simulation->largestOverlap();
        if (worst.relative > p.at("max_initial_overlap").get<double>()) {
          throw Error("/stages/" + ctx.stage() + "/params/" +
                      (p.contains("lammps_data") ? "lammps_data" : "initial_frame") + ": particles " +
                      std::to_string(worst.i) + " and " + std::to_string(worst.j) + " overlap by " +
                      std::to_string(worst.relative) + " of the smaller diameter, above max_initial_overlap = " +
                      std::to_string(p.at("max_initial_overlap").get<double>()));
        }
      }
    }
    if (p.contains("preparation")) {
      PreparationCheckpoints checkpoints;
      checkpoints.every = checkpointEvery;
      checkpoints.save = [&] {
        std::filesystem::create_directories(ctx.checkpointDir());
        dem::writeCheckpoint(preparationCheckpointFile, simulation->captureState(), ctx.key());
        core::failPoint("dem.preparation_checkpoint");
      };
      prepare(ctx, setup, *simulation, checkpoints);
    }
    series << csvHeader(setup);
  }
  dem::Simulation& sim = *simulation;
  for (std::size_t k = 0; k < setup.trackedIds.size(); ++k) {
    const auto& ids = sim.particles().id;
    if (std::find(ids.begin(), ids.begin() + static_cast<std::ptrdiff_t>(sim.particles().nOwned),
                  setup.trackedIds[k]) == ids.begin() + static_cast<std::ptrdiff_t>(sim.particles().nOwned)) {
      throw Error("/stages/" + ctx.stage() + "/params/track_ids/" + std::to_string(k) + ": no particle with id " +
                  std::to_string(setup.trackedIds[k]) + " in the initial state");
    }
  }
  const auto totalSteps = static_cast<std::int64_t>(std::ceil(p.at("duration").get<double>() / setup.engine.dt - 1e-9));
  const auto frames = p.at("frames").get<std::int64_t>();
  const auto seriesPoints = p.at("series_points").get<std::int64_t>();
  // True on `count` evenly spaced steps of 1..totalSteps (the last one included).
  auto isMultiple = [totalSteps](std::int64_t step, std::int64_t count) {
    return count > 0 && step * count / totalSteps != (step - 1) * count / totalSteps;
  };

  core::io::ParticleFrameWriter writer(ctx.outputDir(), core::io::ArtifactStamp{ctx.key()});
  const Vec3 box = setup.engine.hi - setup.engine.lo;
  const double volume = box.prod();
  std::int64_t mobile = 0;
  for (const auto& s : setup.species) mobile += s.frozen ? 0 : s.count;

  auto writeSeriesRow = [&](const core::data::ParticleFrame& f) {
    const auto e = sim.energies();
    const Mat3 sigma = dem::wholeDomainStress(f, volume);
    series << sim.time() << ',' << sim.stepCount() << ',' << e.translational << ',' << e.rotational << ','
           << f.contacts.size() << ','
           << (mobile > 0 ? 2.0 * static_cast<double>(f.contacts.size()) / static_cast<double>(mobile) : 0.0);
    for (auto [a, b] : {std::pair{0, 0}, {1, 1}, {2, 2}, {0, 1}, {0, 2}, {1, 2}}) series << ',' << sigma(a, b);
    for (const auto& fw : sim.wallForces()) series << ',' << fw[0] << ',' << fw[1] << ',' << fw[2];
    std::vector<double> z(setup.species.size(), 0.0);
    std::vector<double> m(setup.species.size(), 0.0);
    for (std::size_t i = 0; i < f.size(); ++i) {
      z[static_cast<std::size_t>(f.species[i])] += f.mass[i] * f.position[i][2];
      m[static_cast<std::size_t>(f.species[i])] += f.mass[i];
    }
    for (std::size_t s = 0; s < z.size(); ++s) series << ',' << (m[s] > 0 ? z[s] / m[s] : 0.0);
    std::vector<double> top(setup.species.size(), -std::numeric_limits<double>::infinity());
    for (std::size_t i = 0; i < f.size(); ++i) {
      auto& t = top[static_cast<std::size_t>(f.species[i])];
      t = std::max(t, f.position[i][2] + f.radius[i]);
    }
    for (double t : top) series << ',' << t;
    for (const auto id : setup.trackedIds) {
      const auto it = std::find(f.id.begin(), f.id.end(), id);
      series << ',' << f.position[static_cast<std::size_t>(it - f.id.begin())][2];
    }
    series << '\n';
  };

  auto checkpoint = [&] {
    std::filesystem::create_directories(ctx.checkpointDir());
    core::writeFileAtomically(checkpointSeries, series.str());
    dem::writeCheckpoint(checkpointFile, sim.captureState(), ctx.key());
  };
  if (sim.stepCount() == 0) writer.write(sim.frame());  // the initial state, with its first contacts
  std::optional<core::Progress> progress;
  if (p.at("progress").get<bool>()) {
    progress.emplace(ctx.stage(), static_cast<double>(totalSteps), "steps", 10.0, static_cast<double>(sim.stepCount()));
  }
  auto lastCheckpoint = std::chrono::steady_clock::now();
  const std::int64_t firstStep = sim.stepCount() + 1;
  const auto loopStart = std::chrono::steady_clock::now();
  for (std::int64_t s = firstStep; s <= totalSteps; ++s) {
    const bool frameStep = isMultiple(s, frames);
    const bool seriesStep = isMultiple(s, seriesPoints) || s == totalSteps;
    try {
      sim.step(frameStep || seriesStep);
    } catch (const Error& e) {
      // A particle left the domain or went non-finite: keep the last good state on disk next to
      // the periodic frames (for a non-finite state, the last periodic frame is the good one).
      bool finite = true;
      for (std::size_t i = 0; i < sim.particles().nOwned && finite; ++i) {
        finite = sim.particles().x[i].allFinite() && sim.particles().v[i].allFinite();
      }
      if (finite) writer.write(sim.frame());
      throw Error(std::string(e.what()) + "; frames up to step " + std::to_string(finite ? sim.stepCount() : s - 1) +
                  " are kept in " + ctx.outputDir().string());
    }
    if (frameStep || seriesStep) {
      const auto f = sim.frame();
      if (seriesStep) writeSeriesRow(f);
      if (frameStep) writer.write(f);
    }
    if ((s & 255) == 0) {
      if (ctx.stopRequested()) {
        checkpoint();  // a batch system's SIGTERM: save, then stop cleanly
        spdlog::warn("{}: stopped at step {} of {}; checkpoint written, the next run resumes here", ctx.stage(), s,
                     totalSteps);
        throw StageInterrupted{};
      }
      if (std::chrono::steady_clock::now() - lastCheckpoint > checkpointEvery) {
        checkpoint();
        lastCheckpoint = std::chrono::steady_clock::now();
      }
      if (progress) progress->update(static_cast<double>(s));
    }
  }
  if (progress) progress->finish();
  {
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - loopStart).count();
    const double steps = static_cast<double>(totalSteps - firstStep + 1);
    spdlog::info(
        "{}: {} steps of {} particles in {:.3f} s: {:.4g} particle-steps/s, {:.3f} contacts per particle (2 x particle "
        "pairs / N, walls not counted)",
        ctx.stage(), totalSteps - firstStep + 1, sim.particles().nOwned, seconds,
        steps * static_cast<double>(sim.particles().nOwned) / seconds,
        2.0 * static_cast<double>(sim.contactCount()) / static_cast<double>(sim.particles().nOwned));
  }

  core::writeFileAtomically(ctx.outputDir() / "series.csv", series.str());
  std::filesystem::remove_all(ctx.checkpointDir());  // complete: the checkpoint has served
  for (const auto& f : core::io::listParticleFrames(ctx.outputDir())) {
    ctx.addArtifact(f.lexically_relative(ctx.outputDir()).string(), "particle_frame");
  }
  ctx.addArtifact("particles.xmf", "xdmf");
  ctx.addArtifact("series.csv", "series_csv");
  const auto e = sim.energies();
  const auto last = sim.frame();
  ctx.setSummary({{"particles", static_cast<std::int64_t>(sim.particles().nOwned)},
                  {"steps", totalSteps},
                  {"final_ke_translational", e.translational},
                  {"final_ke_rotational", e.rotational},
                  {"final_contacts", last.contacts.size()},
                  {"final_coordination",
                   mobile > 0 ? 2.0 * static_cast<double>(last.contacts.size()) / static_cast<double>(mobile) : 0.0},
                  {"neighbour_rebuilds", sim.rebuilds()}});
}

// Frames at t = 0 (the initial state, after any preparation) and, with frames > 0, evenly up to
// the last step; the step count is the one run() takes, ceil(duration / dt).
std::optional<PlannedOutput> DemStage::plannedOutput(const json& p) const {
  PlannedOutput out;
  out.particleFrames = true;
  const double dt = p.at("dt");
  const auto totalSteps = static_cast<std::int64_t>(std::ceil(p.at("duration").get<double>() / dt - 1e-9));
  out.lastFrameTime = p.at("frames").get<std::int64_t>() > 0 ? static_cast<double>(totalSteps) * dt : 0.0;
  out.leesEdwardsShearRate = p.at("shear_rate").get<double>();
  if (!p.contains("lammps_data") && !p.contains("initial_frame")) {
    std::int64_t count = 0;
    for (const auto& s : p.at("species")) count += s.at("count").get<std::int64_t>();
    out.particleCount = count;
  }
  return out;
}

}  // namespace grainbridge::workflows::stages
