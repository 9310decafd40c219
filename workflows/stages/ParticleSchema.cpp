#include "workflows/stages/ParticleSchema.hpp"

#include <set>

#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>

#include "engines/dem/contact/Conversions.hpp"

namespace grainbridge::workflows::stages {

using core::units::Dimension;
using nlohmann::json;
using params::ParamSchema;
using params::ParamSpec;

// The contact coefficients shared by particle pairs and walls (Eqs. 6.5-6.6, Table 6.1). Which
// damping keys apply depends on the stage's damping_model (checked in checkParams).
void addContactModelParams(ParamSchema& s) {
  s.add(ParamSpec::string("normal_model")
            .defaultValue(dem::contact::LinearSpring::name)
            .options(dem::contact::normalModelNames())
            .doc("normal spring: linear (f = 1) or hertz (f = sqrt(delta/d)) in Eqs. 6.5-6.6"))
      .add(ParamSpec::string("damping_model")
               .defaultValue(dem::contact::MassScaledDamping::name)
               .options(dem::contact::dampingModelNames())
               .doc("dashpots: mass_scaled (-f gamma m_eff v, Eqs. 6.5-6.6) or dimensional (-eta v, Table 7.1)"))
      .add(ParamSpec::string("tangential_model")
               .defaultValue(dem::contact::ProjectedHistory::name)
               .options(dem::contact::tangentialModelNames())
               .doc("tangential history: history (Eq. 6.4, projected and rescaled) or lammps_history (LAMMPS "
                    "gran/hooke/history's order, to reproduce a LAMMPS run)"));
}

void addSpeciesParams(ParamSchema& s) {
  s.add(ParamSpec::objectList("species", speciesSchema()).required().doc("particle species"))
      .add(ParamSpec::object("contact", contactSchema()).required().doc("particle-particle contact coefficients"))
      .add(ParamSpec::objectList("pair_contacts", pairContactSchema())
               .doc("coefficients of particular species pairs (others use contact)"));
}

ParamSpec skinParam() {
  return ParamSpec::number("skin").defaultValue(0.3).min(0.0).doc("Verlet skin, in largest diameters");
}

ParamSpec seedParam() { return ParamSpec::integer("seed").defaultValue(1).min(0).doc("random seed of the insertion"); }

void addContactParams(ParamSchema& s) {
  s.add(ParamSpec::quantity("kn", Dimension::stiffness()).positive().doc("normal spring constant k_n (Eq. 6.5)"))
      .add(ParamSpec::quantity("contact_time", Dimension::timeDim())
               .positive()
               .doc("contact time t_c instead of kn: k_n from Eq. 6.10 with each pair's m_eff (linear spring)"))
      .add(ParamSpec::quantity("kt", Dimension::stiffness())
               .min(0.0)
               .doc("tangential spring constant k_t (default 2/7 k_n)"))
      .add(ParamSpec::quantity("gamma_n", Dimension::frequency())
               .min(0.0)
               .doc("normal damping rate gamma_n, times m_eff in Eq. 6.5 (damping_model mass_scaled)"))
      .add(ParamSpec::quantity("eta_n", Dimension{0, 1, -1})
               .min(0.0)
               .doc("normal dashpot coefficient eta_n: F = -eta_n v_n (damping_model dimensional)"))
      .add(ParamSpec::number("restitution")
               .min(0.0, false)
               .max(1.0)
               .doc("normal restitution e_n: the normal damping from Eqs. 6.9-6.10 with each pair's m_eff (linear "
                    "spring), or from a head-on collision at impact_velocity (hertz)"))
      .add(ParamSpec::quantity("impact_velocity", Dimension::velocity())
               .positive()
               .doc("the impact speed at which restitution holds (needed with normal_model hertz, whose "
                    "restitution depends on it)"))
      .add(ParamSpec::quantity("gamma_t", Dimension::frequency())
               .min(0.0)
               .doc("tangential damping rate gamma_t (Eq. 6.6; default 0)"))
      .add(ParamSpec::quantity("eta_t", Dimension{0, 1, -1})
               .min(0.0)
               .doc("tangential dashpot coefficient eta_t (damping_model dimensional; default 0)"))
      .add(ParamSpec::number("mu").defaultValue(0.5).min(0.0).doc("Coulomb friction coefficient"))
      .exactlyOneOf({"kn", "contact_time"}, "the normal stiffness")
      .exactlyOneOf({"gamma_n", "eta_n", "restitution"}, "the normal damping")
      .atMostOneOf({"gamma_t", "eta_t"}, "the tangential damping")
      .requiresKey("impact_velocity", "restitution");
}

// The damping keys a contact object may carry under the stage's damping_model, and that a
// Hertzian restitution states its impact speed.
std::vector<core::engine::SetupProblem> checkContactKeys(const json& c, const json& p, const std::string& where) {
  std::vector<core::engine::SetupProblem> problems;
  const bool dimensional = p.at("damping_model") == dem::contact::DimensionalDamping::name;
  const std::array<const char*, 2> foreign =
      dimensional ? std::array<const char*, 2>{"gamma_n", "gamma_t"} : std::array<const char*, 2>{"eta_n", "eta_t"};
  for (const char* key : foreign) {
    if (c.contains(key)) {
      problems.emplace_back(where + "/" + key, std::string(key) + " does not apply with damping_model \"" +
                                                   p.at("damping_model").get<std::string>() + "\" (use " +
                                                   (dimensional ? "eta_n, eta_t" : "gamma_n, gamma_t") + ")");
    }
  }
  const auto law =
      dem::contact::findContactLaw({p.at("normal_model"), p.at("damping_model"), p.at("tangential_model")});
  if (law && c.contains("contact_time") && !dem::contact::hasClosedFormCollision(*law)) {
    problems.emplace_back(where + "/contact_time", "with normal_model \"" + p.at("normal_model").get<std::string>() +
                                                       "\" the contact time depends on the impact speed: give kn");
  }
  if (law && c.contains("restitution") && !c.contains("impact_velocity") &&
      !dem::contact::hasClosedFormCollision(*law)) {
    problems.emplace_back(
        where + "/restitution",
        "with normal_model \"" + p.at("normal_model").get<std::string>() +
            "\" the restitution depends on the impact speed: give impact_velocity (the speed at which it holds), "
            "or the damping itself");
  }
  return problems;
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

std::vector<core::engine::SetupProblem> checkContactTimes(const DemSetup& setup, double dt) {
  std::vector<core::engine::SetupProblem> problems;
  // A dt too large for one pair is usually too large for many (every species pair and wall):
  // one message for dt, led by the shortest contact, instead of one per pair.
  std::vector<const PairTiming*> tooShort;
  for (const auto& t : setup.timings) {
    if (!std::isfinite(t.contactTime)) {
      problems.emplace_back(t.pointer,
                            "pair " + t.pair +
                                " is overdamped (gamma_n^2/4 >= k_n/m_eff): no rebound and no contact time (Eq. "
                                "6.10); lower gamma_n or raise k_n");
    } else if (dt > t.contactTime / 10.0) {
      tooShort.push_back(&t);
    }
  }
  if (tooShort.empty()) return problems;
  std::sort(tooShort.begin(), tooShort.end(), [](auto* a, auto* b) { return a->contactTime < b->contactTime; });
  std::ostringstream msg;
  msg << "dt = " << dt << " s is above t_c/10 = " << tooShort.front()->contactTime / 10.0 << " s of pair "
      << tooShort.front()->pair << " (t_c from Eq. 6.10)";
  if (tooShort.size() > 1) {
    msg << ", and above t_c/10 of " << tooShort.size() - 1 << " more pair" << (tooShort.size() > 2 ? "s" : "") << " (";
    for (std::size_t i = 1; i < tooShort.size() && i <= 3; ++i) msg << (i > 1 ? ", " : "") << tooShort[i]->pair;
    msg << (tooShort.size() > 4 ? ", ..." : "") << ")";
  }
  msg << "; the reference recommends about t_c/50";
  problems.emplace_back("/dt", msg.str());
  return problems;
}

std::vector<core::engine::SetupProblem> checkSpeciesParams(const nlohmann::json& p) {
  std::vector<core::engine::SetupProblem> problems;
  std::set<std::string> names;
  const auto& species = p.at("species");
  for (std::size_t k = 0; k < species.size(); ++k) {
    if (!names.insert(species[k].at("name").get<std::string>()).second)
      problems.push_back({"/species/" + std::to_string(k) + "/name", "species name used twice"});
  }
  auto append = [&problems](std::vector<core::engine::SetupProblem> more) {
    for (auto& problem : more) problems.push_back(std::move(problem));
  };
  append(checkContactKeys(p.at("contact"), p, "/contact"));
  if (p.contains("pair_contacts")) {
    for (std::size_t k = 0; k < p.at("pair_contacts").size(); ++k) {
      const nlohmann::json& pc = p.at("pair_contacts")[k];
      const std::string where = "/pair_contacts/" + std::to_string(k);
      append(checkContactKeys(pc, p, where));
      for (const char* f : {"species", "with"}) {
        if (names.count(pc.at(f).get<std::string>()) == 0)
          problems.push_back({where + "/" + f, "no species named \"" + pc.at(f).get<std::string>() + "\""});
      }
    }
  }
  return problems;
}

}  // namespace grainbridge::workflows::stages
