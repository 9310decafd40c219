#include "workflows/stages/DemInitialState.hpp"

#include <cmath>
#include <map>
#include <optional>
#include <random>

#include "core/Error.hpp"
#include "core/Log.hpp"
#include "core/io/LammpsDataReader.hpp"
#include "core/io/ParticleFrameReader.hpp"
#include "core/json/Vec3Json.hpp"
#include "core/text/NumberText.hpp"
#include "engines/dem/Insertion.hpp"
#include "engines/dem/LatticeInsertion.hpp"
#include "engines/dem/MaxwellianVelocities.hpp"

namespace grainbridge::workflows::stages {

using nlohmann::json;

namespace {

// What insertSpecies inserts: the region and spheres of the request, the species of each sphere
// to insert (speciesOf, as request.radii) and of each placed one (placedSpecies, as
// request.fixedCentres).
struct SpeciesInsertion {
  dem::InsertionRequest request;
  std::vector<int> placedSpecies;
  std::vector<int> speciesOf;
};

// The insertion region (insert_lo/hi, default the box; inside a cylinder wall if there is one),
// the placed particles as fixed spheres, and the rest of each species' count to insert.
SpeciesInsertion speciesInsertion(const InsertionChoice& choice, const DemSetup& setup) {
  SpeciesInsertion out;
  dem::InsertionRequest& request = out.request;
  request.lo = choice.lo.value_or(setup.engine.lo);
  request.hi = choice.hi.value_or(setup.engine.hi);
  request.periodic = setup.engine.periodic;
  for (const auto& w : setup.engine.walls) {
    if (w.kind == dem::Wall::Kind::Cylinder) {
      request.insideCylinder = true;
      request.cylinderCentre = w.origin;
      request.cylinderRadius = w.radius;
    }
  }
  auto speciesIndex = [&](const std::string& name) {
    for (std::size_t s = 0; s < setup.species.size(); ++s) {
      if (setup.species[s].name == name) return static_cast<int>(s);
    }
    throw Error("no species named " + name);  // checked at load
  };
  // Placed particles come first (ids 0..), then the rest of each species at random.
  std::vector<int>& placedSpecies = out.placedSpecies;
  std::vector<std::int64_t> remaining;
  for (const auto& s : setup.species) remaining.push_back(s.count);
  for (const auto& placed : choice.place) {
    const int s = speciesIndex(placed.species);
    placedSpecies.push_back(s);
    --remaining[static_cast<std::size_t>(s)];
    request.fixedCentres.push_back(placed.position);
    request.fixedRadii.push_back(setup.species[static_cast<std::size_t>(s)].radius);
  }
  for (std::size_t s = 0; s < setup.species.size(); ++s) {
    for (std::int64_t k = 0; k < remaining[s]; ++k) {
      request.radii.push_back(setup.species[s].radius);
      out.speciesOf.push_back(static_cast<int>(s));
    }
  }
  return out;
}

}  // namespace

void from_json(const json& p, InsertionChoice& c) {
  if (p.contains("insert_lo")) c.lo = core::json::vec3FromJson(p.at("insert_lo"));
  if (p.contains("insert_hi")) c.hi = core::json::vec3FromJson(p.at("insert_hi"));
  for (const auto& placed : p.value("place", json::array()))
    c.place.push_back({placed.at("species").get<std::string>(), core::json::vec3FromJson(placed.at("position"))});
  c.lattice = p.value("insertion", std::string("random")) == "fcc_lattice";
  c.seed = p.at("seed").get<std::uint64_t>();
  c.initialTemperature = p.value("initial_temperature", 0.0);
  c.fromFile = p.contains("lammps_data") || p.contains("initial_frame");
}

std::optional<core::engine::SetupProblem> randomInsertionProblem(const InsertionChoice& choice, const DemSetup& setup,
                                                                 const std::string& boxKeys) {
  if (choice.fromFile || choice.lattice)
    return std::nullopt;  // a state read from a file or a lattice: nothing is inserted at random
  const SpeciesInsertion insertion = speciesInsertion(choice, setup);
  const double fraction = dem::requestedSolidFraction(insertion.request);
  if (!(fraction > dem::kRandomInsertionJamming)) return std::nullopt;
  // Every species shares the one region: name each one inserted, and point at the count when
  // one species alone fills it.
  std::vector<std::int64_t> inserted(setup.species.size(), 0);
  for (const int s : insertion.speciesOf) ++inserted[static_cast<std::size_t>(s)];
  std::string counts;
  std::size_t contributing = 0, last = 0;
  for (std::size_t s = 0; s < inserted.size(); ++s) {
    if (inserted[s] == 0) continue;
    counts += (counts.empty() ? "" : ", ") + setup.species[s].name + " " + std::to_string(inserted[s]);
    ++contributing;
    last = s;
  }
  const Vec3 extent = insertion.request.hi - insertion.request.lo;
  // The region's keys as the user wrote them: the numbers below are SI.
  const std::string region = choice.lo || choice.hi ? "insert_lo/insert_hi" : boxKeys;
  return core::engine::SetupProblem{
      contributing == 1 ? "/species/" + std::to_string(last) + "/count" : "/species",
      std::to_string(insertion.speciesOf.size()) + " spheres to insert at random (" + counts + ") would fill " +
          core::humanNumber(fraction, 3) + " of the insertion region (" + region + ", " + core::humanNumber(extent[0]) +
          " x " + core::humanNumber(extent[1]) + " x " + core::humanNumber(extent[2]) + " m" +
          (insertion.request.insideCylinder ? ", inside the cylinder wall" : "") + "), above the solid fraction " +
          core::humanNumber(dem::kRandomInsertionJamming) +
          " near which random insertion jams: enlarge the insertion region or insert fewer particles"};
}

// Every species at random, without overlap, in the insertion region (inside a cylinder wall
// if there is one).
dem::Particles insertSpecies(const StageContext& ctx, const InsertionChoice& choice, const DemSetup& setup) {
  SpeciesInsertion insertion = speciesInsertion(choice, setup);
  dem::InsertionRequest& request = insertion.request;
  const std::vector<int>& placedSpecies = insertion.placedSpecies;
  const std::vector<int>& speciesOf = insertion.speciesOf;
  request.progress = [&](std::size_t) {
    if (ctx.stopRequested()) throw StageInterrupted{};
  };
  std::mt19937_64 rng(choice.seed);
  double largest = 0.0;
  for (double r : request.radii) largest = std::max(largest, 2.0 * r);
  const auto centres = choice.lattice ? dem::fccLatticeSites(request.lo, request.hi, request.radii.size(), largest, rng)
                                      : dem::insertRandomly(request, rng);
  // Velocity fluctuations of the mobile particles: Maxwellian with exactly zero total momentum
  // about the streaming profile (under shear a net y momentum P_y would drive x momentum as
  // -gammadot P_y t) and exactly the asked T.
  std::vector<Vec3> fluctuation(centres.size(), Vec3::Zero());
  if (const double T0 = choice.initialTemperature; T0 > 0.0) {
    std::vector<std::size_t> mobile;
    for (std::size_t i = 0; i < centres.size(); ++i) {
      if (!setup.species[static_cast<std::size_t>(speciesOf[i])].frozen) mobile.push_back(i);
    }
    const auto drawn = dem::maxwellianVelocities(mobile.size(), T0, rng);
    for (std::size_t k = 0; k < mobile.size(); ++k) fluctuation[mobile[k]] = drawn[k];
  }
  dem::Particles particles;
  std::int64_t id = 0;
  for (std::size_t k = 0; k < placedSpecies.size(); ++k) {
    const auto& sp = setup.species[static_cast<std::size_t>(placedSpecies[k])];
    particles.addOwned(id++, placedSpecies[k], sp.radius, sp.mass, request.fixedCentres[k], Vec3::Zero(), Vec3::Zero(),
                       sp.frozen);
  }
  for (std::size_t i = 0; i < centres.size(); ++i) {
    const auto& sp = setup.species[static_cast<std::size_t>(speciesOf[i])];
    // Under Lees-Edwards shear the particles start on the streaming profile.
    const double ux = setup.engine.shearRate == 0.0
                          ? 0.0
                          : setup.engine.shearRate * (centres[i][1] - 0.5 * (setup.engine.lo[1] + setup.engine.hi[1]));
    Vec3 v = Vec3::Zero();
    if (!sp.frozen) v = Vec3(ux, 0, 0) + fluctuation[i];
    particles.addOwned(id++, speciesOf[i], sp.radius, sp.mass, centres[i], v, Vec3::Zero(), sp.frozen);
  }
  return particles;
}

// Particles from a LAMMPS data file (atom_style sphere): per-atom diameter, density, velocity
// and angular velocity as written, each type mapped to a species (and frozen if asked). A data
// file carries no units: its numbers are read as the config's bare numbers are, so a reduced
// config's file is in d0, m0/d0^3, d0/t0 and 1/t0 like its box (issue 54; it was read as SI).
dem::Particles readLammpsParticles(const json& p, const DemSetup& setup, const core::units::UnitSystem& units) {
  const std::string path = p.at("lammps_data").at("path");
  auto data = core::io::readLammpsData(path);
  const double length = units.d0(), time = units.t0(), density = units.m0() / (length * length * length);
  for (std::size_t i = 0; i < data.size(); ++i) {
    data.position[i] *= length;
    data.diameter[i] *= length;
    data.density[i] *= density;
    data.velocity[i] *= length / time;
    data.angularVelocity[i] /= time;
  }
  std::map<int, std::pair<int, bool>> typeMap;
  for (const auto& t : p.at("lammps_types")) {
    int species = -1;
    for (std::size_t s = 0; s < setup.species.size(); ++s) {
      if (setup.species[s].name == t.at("species")) species = static_cast<int>(s);
    }
    typeMap[t.at("type").get<int>()] = {species, t.at("frozen").get<bool>()};
  }
  dem::Particles particles;
  for (std::size_t i = 0; i < data.size(); ++i) {
    const auto it = typeMap.find(data.type[i]);
    if (it == typeMap.end()) {
      throw Error("LAMMPS data file '" + path + "': atom " + std::to_string(data.id[i]) + " has type " +
                  std::to_string(data.type[i]) + ", which lammps_types does not map to a species");
    }
    for (int a = 0; a < 3; ++a) {
      if (data.position[i][a] < setup.engine.lo[a] || data.position[i][a] > setup.engine.hi[a]) {
        throw Error("LAMMPS data file '" + path + "': atom " + std::to_string(data.id[i]) +
                    " lies outside box_lo/box_hi of the config");
      }
    }
    particles.addOwned(data.id[i], it->second.first, 0.5 * data.diameter[i], data.mass(i), data.position[i],
                       data.velocity[i], data.angularVelocity[i], it->second.second);
  }
  return particles;
}

// Particles from a saved frame of the data model; the frame's species index selects the
// species (and so whether it is frozen).
dem::Particles readFrameParticles(const json& p, const DemSetup& setup) {
  const std::string path = p.at("initial_frame").at("path");
  const auto frame = core::io::readParticleFrame(path);
  dem::Particles particles;
  for (std::size_t i = 0; i < frame.size(); ++i) {
    const auto s = frame.species[i];
    if (s < 0 || static_cast<std::size_t>(s) >= setup.species.size()) {
      throw Error("initial frame '" + path + "': particle " + std::to_string(frame.id[i]) + " has species index " +
                  std::to_string(s) + ", but the config declares " + std::to_string(setup.species.size()) + " species");
    }
    particles.addOwned(frame.id[i], s, frame.radius[i], frame.mass[i], frame.position[i], frame.velocity[i],
                       frame.angularVelocity[i], setup.species[static_cast<std::size_t>(s)].frozen);
  }
  return particles;
}

std::vector<driver::Phase> preparationPhases(const StageContext& ctx, const DemSetup& setup, dem::DemEngine& engine) {
  const json& prep = ctx.params().at("preparation");
  const std::string hold = prep.at("hold_species");
  std::vector<std::int64_t> held;
  const auto& particles = engine.simulation().particles();
  for (std::size_t i = 0; i < particles.nOwned; ++i) {
    if (!hold.empty() && setup.species[static_cast<std::size_t>(particles.species[i])].name == hold) {
      held.push_back(particles.id[i]);
    }
  }
  const double dt = setup.engine.dt;
  dem::Vibration shake;
  shake.direction = Vec3::UnitZ();
  shake.amplitude = prep.at("shake_amplitude");
  shake.frequency = prep.at("shake_frequency");
  // Whole periods, so the walls are back at rest position when the shaking stops.
  const double periods =
      shake.frequency > 0 ? std::ceil(prep.at("shake_duration").get<double>() * shake.frequency) : 0.0;
  const auto shakeSteps = shake.frequency > 0
                              ? static_cast<std::int64_t>(std::llround(periods / shake.frequency / dt))
                              : static_cast<std::int64_t>(std::ceil(prep.at("shake_duration").get<double>() / dt));
  const auto relaxSteps = static_cast<std::int64_t>(std::ceil(prep.at("relax_duration").get<double>() / dt));
  const std::string stage = ctx.stage();
  auto setVibration = [&engine, &setup](auto vibrationOf) {
    for (std::size_t w = 0; w < setup.engine.walls.size(); ++w)
      engine.mutableSimulation().setWallVibration(w, vibrationOf(w));
  };
  auto report = [&engine, stage](const char* what) {
    spdlog::info("{}: preparation: {} until step {}, kinetic energy now {} J", stage, what, engine.step(),
                 core::humanNumber(engine.simulation().energies().kinetic(), 4));
  };

  driver::Phase shaking;
  shaking.name = "preparation (shaking)";
  shaking.steps = shakeSteps;
  // Infinite mass is part of the engine state: a resumed preparation has it already.
  shaking.enter = [&engine, held] {
    for (auto id : held) engine.mutableSimulation().setFrozen(id, true);
  };
  shaking.configure = [setVibration, shake] { setVibration([&](std::size_t) { return shake; }); };
  shaking.leave = [report] { report("shaking"); };

  driver::Phase relaxing;
  relaxing.name = "preparation (relaxing)";
  relaxing.steps = relaxSteps;
  relaxing.configure = [setVibration] { setVibration([](std::size_t) { return dem::Vibration{}; }); };
  relaxing.leave = [&engine, &setup, held, setVibration, report] {
    report("relaxing");
    for (auto id : held) engine.mutableSimulation().setFrozen(id, false);
    setVibration([&](std::size_t w) { return setup.engine.walls[w].vibration; });
    engine.mutableSimulation().restartClock();
  };
  return {shaking, relaxing};
}

}  // namespace grainbridge::workflows::stages
