#include "workflows/stages/DemSetup.hpp"

#include <cmath>
#include <limits>
#include <optional>

#include "core/json/Vec3Json.hpp"
#include "engines/dem/contact/Conversions.hpp"

namespace grainbridge::workflows::stages {

using nlohmann::json;

namespace {

// Material of a surface pair from a contact object, for the run's contact law. A restitution,
// when given, sets the normal damping for this pair's effective mass and contact length
// (Eqs. 6.9-6.10 inverted for a linear spring; a collision at impact_velocity otherwise).
dem::PairMaterial material(const json& c, const dem::contact::AnyContactLaw& law, double meff, double d) {
  dem::PairMaterial m;
  m.kn = c.value("kn", 0.0);
  m.gammaN = c.value("gamma_n", 0.0);
  m.gammaT = c.value("gamma_t", 0.0);
  m.etaN = c.value("eta_n", 0.0);
  m.etaT = c.value("eta_t", 0.0);
  m.mu = c.at("mu");
  const std::optional<double> e =
      c.contains("restitution") ? std::optional<double>(c.at("restitution").get<double>()) : std::nullopt;
  if (c.contains("contact_time")) {
    m = dem::contact::withContactTime(law, m, c.at("contact_time"), e, meff);  // sets k_n (and the damping)
  } else if (e) {
    m = dem::contact::withRestitution(law, m, *e, meff, d, c.value("impact_velocity", 0.0));
  }
  m.kt = c.contains("kt") ? c.at("kt").get<double>() : 2.0 / 7.0 * m.kn;  // Table 6.1: k_t = 2/7 k_n
  return m;
}

// e_n and t_c of a pair as the log and the dt check see them: exact where the law has a closed
// form or an impact speed is stated, else the linear spring's (a lower bound on a Hertzian t_c).
PairTiming timing(std::string pair, std::string pointer, const json& c, const dem::contact::AnyContactLaw& law,
                  const dem::PairMaterial& m, double meff, double d) {
  const bool exact = dem::contact::hasClosedFormCollision(law) || c.contains("impact_velocity");
  const auto r = exact ? dem::contact::headOnCollision(law, m, meff, d, c.value("impact_velocity", 0.0))
                       : dem::contact::linearEstimate(law, m, meff);
  return {std::move(pair), std::move(pointer), r.restitution, r.contactTime, exact};
}

// m_eff of two bodies; a frozen particle or a wall has infinite mass.
double effectiveMass(double ma, bool frozenA, double mb, bool frozenB) {
  if (frozenA && frozenB) return std::numeric_limits<double>::infinity();
  if (frozenA) return mb;
  if (frozenB) return ma;
  return ma * mb / (ma + mb);
}

}  // namespace

DemSetup makeParticleSetup(const json& p) {
  DemSetup out;
  auto& e = out.engine;
  e.dt = p.at("dt");
  e.contact = {p.at("normal_model"), p.at("damping_model"), p.at("tangential_model")};
  const auto law = dem::contact::findContactLaw(e.contact);
  if (!law) return out;  // unregistered names: SimulationSetup::problems() reports them

  double maxDiameter = 0.0;
  for (const auto& s : p.at("species")) {
    const double d = s.at("diameter");
    maxDiameter = std::max(maxDiameter, d);
    out.species.push_back({s.at("name"), 0.5 * d, s.at("density").get<double>() * M_PI / 6.0 * d * d * d,
                           s.at("count").get<std::int64_t>(), s.at("frozen").get<bool>()});
    out.materials.species.push_back({s.at("name"), d, s.at("density").get<double>()});
  }
  e.skin = p.at("skin").get<double>() * maxDiameter;
  const int ns = static_cast<int>(out.species.size());
  e.species = ns;
  e.pairMaterial.resize(static_cast<std::size_t>(ns * ns));
  const json& contact = p.at("contact");
  for (int a = 0; a < ns; ++a) {
    for (int b = 0; b < ns; ++b) {
      const auto& sa = out.species[static_cast<std::size_t>(a)];
      const auto& sb = out.species[static_cast<std::size_t>(b)];
      const double meff = effectiveMass(sa.mass, sa.frozen, sb.mass, sb.frozen);
      // A pair_contacts entry for this pair (either order) replaces `contact`.
      const json* c = &contact;
      if (p.contains("pair_contacts")) {
        for (const auto& pc : p.at("pair_contacts")) {
          if ((pc.at("species") == sa.name && pc.at("with") == sb.name) ||
              (pc.at("species") == sb.name && pc.at("with") == sa.name))
            c = &pc;
        }
      }
      const double d = sa.radius + sb.radius;
      e.pairMaterial[static_cast<std::size_t>(a * ns + b)] = material(*c, *law, std::isfinite(meff) ? meff : 1.0, d);
      if (b >= a && std::isfinite(meff)) {
        out.timings.push_back(timing(sa.name + "-" + sb.name, c == &contact ? "/contact" : "/pair_contacts", *c, *law,
                                     e.pairMaterial[static_cast<std::size_t>(a * ns + b)], meff, d));
        const dem::PairMaterial& m = e.pairMaterial[static_cast<std::size_t>(a * ns + b)];
        out.materials.pairs.push_back({a, b, -1, out.timings.back().restitution, m.mu, m.kn, m.kt});
      }
    }
  }
  return out;
}

void addWall(DemSetup& setup, dem::Wall wall, const json& contact, const std::string& pointer) {
  const auto law = dem::contact::findContactLaw(setup.engine.contact);
  if (!law) return;  // makeParticleSetup made no materials either
  const std::size_t w = setup.engine.walls.size();
  for (const auto& s : setup.species) {
    wall.material.push_back(material(contact, *law, s.mass, 2.0 * s.radius));
    setup.timings.push_back(timing(s.name + "-wall " + std::to_string(w), pointer, contact, *law, wall.material.back(),
                                   s.mass, 2.0 * s.radius));
    const auto si = static_cast<std::int32_t>(wall.material.size() - 1);
    const dem::PairMaterial& m = wall.material.back();
    setup.materials.walls.push_back(
        {si, si, static_cast<std::int32_t>(w), setup.timings.back().restitution, m.mu, m.kn, m.kt});
  }
  setup.engine.walls.push_back(std::move(wall));
}

double speciesSolidFraction(const json& p) {
  double volume = 0.0;
  for (const auto& s : p.at("species")) {
    volume += static_cast<double>(s.at("count").get<std::int64_t>()) * M_PI / 6.0 * std::pow(s.at("diameter").get<double>(), 3);
  }
  double box = 1.0;
  for (int a = 0; a < 3; ++a) box *= p.at("box_hi")[a].get<double>() - p.at("box_lo")[a].get<double>();
  return volume / box;
}

DemSetup makeDemSetup(const json& p) {
  DemSetup out = makeParticleSetup(p);
  auto& e = out.engine;
  e.lo = core::json::vec3FromJson(p.at("box_lo"));
  e.hi = core::json::vec3FromJson(p.at("box_hi"));
  const std::string periodic = p.at("periodic");
  for (int a = 0; a < 3; ++a) e.periodic[static_cast<std::size_t>(a)] = periodic.find("xyz"[a]) != std::string::npos;
  e.gravity = core::json::vec3FromJson(p.at("gravity"));
  out.materials.gravity = e.gravity;
  e.backgroundDamping = p.at("background_damping");
  for (const auto& id : p.at("track_ids")) out.trackedIds.push_back(std::llround(id.get<double>()));
  e.shearRate = p.at("shear_rate");
  if (p.contains("pressure_control")) {
    const auto& pc = p.at("pressure_control");
    e.pressureControl.stress = pc.at("stress");
    e.pressureControl.relaxationTime = pc.at("relaxation_time");
    e.pressureControl.interval = pc.at("interval");
  }
  if (p.contains("compression")) {
    // The engine compresses from the box the grains are inserted in to the fraction they fill in
    // box_hi's: the inserted box is box_hi's made longer along y by held / from.
    const auto& c = p.at("compression");
    const double held = speciesSolidFraction(p);
    const double from = c.at("from_solid_fraction");
    e.compression.solidFraction = held;
    e.compression.duration = c.at("duration");
    e.compression.interval = c.at("interval");
    if (from > 0.0 && held > from) e.hi[1] = e.lo[1] + (e.hi[1] - e.lo[1]) * (held / from);
  }
  const std::string planar = p.at("planar");
  e.planarAxis = planar.empty() ? -1 : planar[0] - 'x';
  if (p.contains("walls")) {
    const json& walls = p.at("walls");
    for (std::size_t w = 0; w < walls.size(); ++w) {
      const json& wj = walls[w];
      dem::Wall wall;
      wall.kind = wj.at("kind") == "cylinder" ? dem::Wall::Kind::Cylinder : dem::Wall::Kind::Plane;
      wall.origin = core::json::vec3FromJson(wj.at("point"));
      wall.direction = core::json::vec3FromJson(wj.at("direction")).normalized();
      wall.radius = wj.at("radius");
      wall.vibration.amplitude = wj.at("vibration_amplitude");
      wall.vibration.frequency = wj.at("vibration_frequency");
      wall.vibration.direction = core::json::vec3FromJson(wj.at("vibration_direction")).normalized();
      wall.vibration.start = dem::vibrationStartFromName(wj.at("vibration_start"));
      addWall(out, std::move(wall), wj, "/walls/" + std::to_string(w));
    }
  }
  return out;
}

}  // namespace grainbridge::workflows::stages
