#include "engines/dem/SimulationSetup.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/json/Vec3Json.hpp"
#include "engines/dem/NeighborList.hpp"

namespace grainbridge::dem {

using nlohmann::json;

namespace {

constexpr const char* kAxes = "xyz";

// A message from its pieces, numbers in the stream's default (shortest readable) format.
template <class... Pieces>
std::string text(const Pieces&... pieces) {
  std::ostringstream out;
  (out << ... << pieces);
  return out.str();
}

json materialJson(const PairMaterial& m) {
  return {{"kn", m.kn},     {"kt", m.kt},       {"gamma_n", m.gammaN}, {"gamma_t", m.gammaT},
          {"eta_n", m.etaN}, {"eta_t", m.etaT}, {"mu", m.mu}};
}
PairMaterial material(const json& j) {
  PairMaterial m;
  m.kn = j.at("kn");
  m.kt = j.at("kt");
  m.gammaN = j.at("gamma_n");
  m.gammaT = j.at("gamma_t");
  m.etaN = j.value("eta_n", 0.0);
  m.etaT = j.value("eta_t", 0.0);
  m.mu = j.at("mu");
  return m;
}

std::string listed(const std::vector<std::string>& names) {
  std::string out;
  for (const auto& n : names) out += (out.empty() ? "" : ", ") + n;
  return out;
}

}  // namespace

std::vector<SetupProblem> SimulationSetup::problems(double largestDiameter,
                                                    std::optional<std::int64_t> insertedParticles) const {
  std::vector<SetupProblem> out;
  auto add = [&out](std::string pointer, std::string message) {
    out.push_back({std::move(pointer), std::move(message)});
  };
  if (!(dt > 0.0)) add("/dt", text("the time step must be positive, found ", dt, " s"));
  if (!(skin >= 0.0)) add("/skin", text("the Verlet skin must be >= 0, found ", skin, " m"));
  bool boxUsable = true;
  for (int a = 0; a < 3; ++a) {
    if (!(hi[a] > lo[a])) {
      add("/box_hi/" + std::to_string(a),
          text("box_hi must exceed box_lo on every axis, found ", hi[a], " m against ", lo[a], " m along ", kAxes[a]));
      boxUsable = false;
    }
  }
  const double range = interactionRange(largestDiameter, skin);
  for (int a = 0; a < 3 && boxUsable; ++a) {
    // One periodic image per neighbour: a periodic length must exceed twice the range.
    const double length = hi[a] - lo[a];
    if (periodic[static_cast<std::size_t>(a)] && length < 2.0 * range) {
      add("/box_hi/" + std::to_string(a),
          text("the periodic length along ", kAxes[a], " is ", length, " m, less than twice the interaction range ",
               range, " m (largest diameter + skin)"));
    }
  }
  if (boxUsable && range > 0.0) {
    const double cells = NeighborList::gridCells(lo, hi, range);
    if (cells > NeighborList::kMaxGridCells) {
      add("/box_hi", text("the neighbour grid over this box would have ", cells, " cells of side ", range,
                          " m (the interaction range: largest diameter + skin), more than the ",
                          static_cast<long long>(NeighborList::kMaxGridCells),
                          " (1 GiB of cell starts) one neighbour list may take: a smaller box or larger grains"));
    }
  }
  if (shearRate != 0.0 && !(periodic[0] && periodic[1])) {
    add("/shear_rate", text("Lees-Edwards shear needs periodic \"x\" (flow) and \"y\" (gradient)"));
  }
  if (pressureControl.stress < 0.0) {
    add("/pressure_control/stress", text("the target stress must be positive, found ", pressureControl.stress));
  }
  if (pressureControl.stress != 0.0) {  // configured (a negative target is reported above too)
    if (shearRate == 0.0) {
      add("/pressure_control", text("pressure control adjusts a Lees-Edwards box: give a shear_rate"));
    }
    if (!(periodic[0] && periodic[1] && periodic[2])) {
      add("/pressure_control", text("pressure control needs a box periodic in \"xyz\""));
    }
    if (!walls.empty()) {
      add("/pressure_control", text("pressure control needs a box without walls, found ", walls.size()));
    }
    if (!(pressureControl.relaxationTime > 0.0)) {
      add("/pressure_control/relaxation_time",
          text("the relaxation time must be positive, found ", pressureControl.relaxationTime));
    }
    if (pressureControl.interval < 1) {
      add("/pressure_control/interval", text("the interval must be at least 1 step, found ", pressureControl.interval));
    }
  }
  if (compression.solidFraction != 0.0) {  // configured
    if (!(compression.solidFraction > 0.0 && compression.solidFraction < 1.0)) {
      add("/compression", text("the solid fraction to compress to (the grains' in the box they are to fill) must lie "
                               "in (0, 1), found ",
                               compression.solidFraction));
    }
    if (!(compression.duration > 0.0)) {
      add("/compression/duration", text("the compression's duration must be positive, found ", compression.duration));
    }
    if (compression.interval < 1) {
      add("/compression/interval", text("the interval must be at least 1 step, found ", compression.interval));
    }
    if (shearRate == 0.0) add("/compression", text("compression shrinks a Lees-Edwards box: give a shear_rate"));
    if (!(periodic[0] && periodic[1] && periodic[2])) {
      add("/compression", text("compression needs a box periodic in \"xyz\""));
    }
    if (!walls.empty()) add("/compression", text("compression needs a box without walls, found ", walls.size()));
    if (pressureControl.stress != 0.0) {
      add("/compression", text("compression fixes the box's volume and pressure control varies it: give one of them"));
    }
  }
  if (planarAxis < -1 || planarAxis > 2) {
    add("/planar", text("the planar axis must be x, y, z or none, found index ", planarAxis));
  }
  if (!contact::findContactLaw(contact)) {
    const std::pair<const std::string*, std::vector<std::string>> kinds[] = {
        {&contact.normal, contact::normalModelNames()},
        {&contact.damping, contact::dampingModelNames()},
        {&contact.tangential, contact::tangentialModelNames()}};
    const char* keys[] = {"/normal_model", "/damping_model", "/tangential_model"};
    for (std::size_t k = 0; k < 3; ++k) {
      const auto& [name, known] = kinds[k];
      if (std::find(known.begin(), known.end(), *name) == known.end())
        add(keys[k], text("no contact sub-model named \"", *name, "\" (registered: ", listed(known), ")"));
    }
  }
  if (species < 1 || pairMaterial.size() != static_cast<std::size_t>(species * species)) {
    add("/pair_materials",
        text("need one material per species pair: ", species, " species, ", pairMaterial.size(), " materials"));
  }
  if (insertedParticles && *insertedParticles == 0) {
    add("/species", text("no species inserts a particle (every count is 0) and no state is read from a file "
                         "(lammps_data or initial_frame): the run would have no particles; give a species a count"));
  }
  for (std::size_t w = 0; w < walls.size(); ++w) {
    if (walls[w].material.size() != static_cast<std::size_t>(species)) {
      add("/walls/" + std::to_string(w),
          text("need one material per species: ", species, " species, ", walls[w].material.size(), " materials"));
    }
  }
  return out;
}

void to_json(json& j, const SimulationSetup& s) {
  std::string periodic, planar;
  for (int a = 0; a < 3; ++a) {
    if (s.periodic[static_cast<std::size_t>(a)]) periodic += kAxes[a];
  }
  if (s.planarAxis >= 0 && s.planarAxis < 3) planar = std::string(1, kAxes[s.planarAxis]);
  json pairs = json::array();
  for (const auto& m : s.pairMaterial) pairs.push_back(materialJson(m));
  json walls = json::array();
  for (const auto& w : s.walls) {
    json materials = json::array();
    for (const auto& m : w.material) materials.push_back(materialJson(m));
    walls.push_back({{"kind", w.kind == Wall::Kind::Cylinder ? "cylinder" : "plane"},
                     {"point", core::json::vec3Json(w.origin)},
                     {"direction", core::json::vec3Json(w.direction)},
                     {"radius", w.radius},
                     {"vibration_amplitude", w.vibration.amplitude},
                     {"vibration_frequency", w.vibration.frequency},
                     {"vibration_direction", core::json::vec3Json(w.vibration.direction)},
                     {"materials", materials}});
    // Only when not the default, so the states of runs from before the key are read as they were.
    if (w.vibration.start != Vibration::Start::MidStroke)
      walls.back()["vibration_start"] = vibrationStartName(w.vibration.start);
  }
  j = {{"box_lo", core::json::vec3Json(s.lo)},
       {"box_hi", core::json::vec3Json(s.hi)},
       {"periodic", periodic},
       {"gravity", core::json::vec3Json(s.gravity)},
       {"background_damping", s.backgroundDamping},
       {"shear_rate", s.shearRate},
       {"planar", planar},
       {"dt", s.dt},
       {"skin", s.skin},
       {"normal_model", s.contact.normal},
       {"damping_model", s.contact.damping},
       {"tangential_model", s.contact.tangential},
       {"species", s.species},
       {"pair_materials", pairs},
       {"walls", walls},
       {"sort_every_rebuilds", s.sortEveryRebuilds}};
  // Only when on: a run without it keeps the JSON (and fingerprint) it always had.
  if (s.pressureControl.active()) {
    j["pressure_control"] = {{"stress", s.pressureControl.stress},
                             {"relaxation_time", s.pressureControl.relaxationTime},
                             {"interval", s.pressureControl.interval}};
  }
  if (s.compression.active()) {
    j["compression"] = {{"solid_fraction", s.compression.solidFraction},
                        {"duration", s.compression.duration},
                        {"interval", s.compression.interval}};
  }
}

void from_json(const json& j, SimulationSetup& s) {
  s.lo = core::json::vec3FromJson(j.at("box_lo"));
  s.hi = core::json::vec3FromJson(j.at("box_hi"));
  const std::string periodic = j.at("periodic");
  for (int a = 0; a < 3; ++a) s.periodic[static_cast<std::size_t>(a)] = periodic.find(kAxes[a]) != std::string::npos;
  s.gravity = core::json::vec3FromJson(j.at("gravity"));
  s.backgroundDamping = j.at("background_damping");
  s.shearRate = j.at("shear_rate");
  const std::string planar = j.at("planar");
  s.planarAxis = planar.empty() ? -1 : planar[0] - 'x';
  s.dt = j.at("dt");
  s.skin = j.at("skin");
  s.contact.normal = j.at("normal_model");
  s.contact.damping = j.at("damping_model");
  s.contact.tangential = j.at("tangential_model");
  s.species = j.at("species");
  s.pairMaterial.clear();
  for (const auto& m : j.at("pair_materials")) s.pairMaterial.push_back(material(m));
  s.walls.clear();
  for (const auto& wj : j.at("walls")) {
    Wall w;
    w.kind = wj.at("kind") == "cylinder" ? Wall::Kind::Cylinder : Wall::Kind::Plane;
    w.origin = core::json::vec3FromJson(wj.at("point"));
    w.direction = core::json::vec3FromJson(wj.at("direction"));
    w.radius = wj.at("radius");
    w.vibration.amplitude = wj.at("vibration_amplitude");
    w.vibration.frequency = wj.at("vibration_frequency");
    w.vibration.direction = core::json::vec3FromJson(wj.at("vibration_direction"));
    w.vibration.start = vibrationStartFromName(wj.value("vibration_start", "mid_stroke"));
    for (const auto& m : wj.at("materials")) w.material.push_back(material(m));
    s.walls.push_back(std::move(w));
  }
  s.sortEveryRebuilds = j.at("sort_every_rebuilds");
  s.pressureControl = {};
  if (j.contains("pressure_control")) {
    const auto& pc = j.at("pressure_control");
    s.pressureControl.stress = pc.at("stress");
    s.pressureControl.relaxationTime = pc.at("relaxation_time");
    s.pressureControl.interval = pc.at("interval");
  }
  s.compression = {};
  if (j.contains("compression")) {
    const auto& c = j.at("compression");
    s.compression.solidFraction = c.at("solid_fraction");
    s.compression.duration = c.at("duration");
    s.compression.interval = c.at("interval");
  }
}

}  // namespace grainbridge::dem
