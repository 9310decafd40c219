#include "workflows/closures/ClosureCatalog.hpp"

#include <cmath>

#include "core/Error.hpp"
#include "engines/closures/EffectiveRestitution.hpp"
#include "engines/closures/GranularEnergyGasTerms.hpp"
#include "engines/closures/JohnsonJackson.hpp"
#include "engines/closures/KineticModel.hpp"
#include "engines/closures/PlasticRegime.hpp"
#include "engines/closures/RadialDistribution.hpp"
#include "engines/closures/SolidsSolidsDrag.hpp"
#include "workflows/closures/DragLawCatalog.hpp"

namespace grainbridge::workflows::closures {

namespace gc = grainbridge::closures;
using core::units::Dimension;
using nlohmann::json;
using params::ParamSchema;
using params::ParamSpec;

namespace {

constexpr Dimension kDragCoefficient{-3, 1, -1};  // kg/(m^3 s)
constexpr Dimension kStrainInvariant{0, 0, -2};   // 1/s^2

std::shared_ptr<ParamSchema> schema() { return std::make_shared<ParamSchema>(); }

ParamSpec fraction(const std::string& name, const std::string& doc) {
  return std::move(ParamSpec::number(name).required().min(0.0).max(1.0).doc(doc));
}

std::shared_ptr<ParamSchema> kineticInputs(bool withGasDrag) {
  auto s = schema();
  s->add(fraction("solid_fraction", "eps_s"))
      .add(ParamSpec::quantity("granular_temperature", Dimension::granularTemperature())
               .required()
               .min(0.0)
               .doc("theta = <C^2>/3"))
      .add(ParamSpec::quantity("diameter", Dimension::lengthDim()).required().positive().doc("particle diameter"))
      .add(ParamSpec::quantity("density", Dimension::density()).required().positive().doc("material density rho_s"))
      .add(ParamSpec::number("restitution").required().min(0.0, false).max(1.0).doc("normal restitution e"));
  if (withGasDrag) {
    s->add(ParamSpec::quantity("gas_drag_coefficient", kDragCoefficient)
               .defaultValue(0.0)
               .min(0.0)
               .doc("beta of the Ma-Ahmadi gas modification (0: no gas)"));
  }
  return s;
}

ClosureEntry kinetic(gc::KineticModelName model, std::string summary, std::string equations, std::string source) {
  const bool lun = model == gc::KineticModelName::Lun1984 || model == gc::KineticModelName::Lun1984Mfix;
  return {std::string(gc::toString(model)),
          std::move(summary),
          std::move(equations),
          std::move(source),
          schema(),
          kineticInputs(lun),
          [model, lun](const json&, const json& in) {
            gc::KineticState s;
            s.solidFraction = in.at("solid_fraction");
            s.granularTemperature = in.at("granular_temperature");
            s.diameter = in.at("diameter");
            s.density = in.at("density");
            s.restitution = in.at("restitution");
            if (lun) s.gasDragCoefficient = in.at("gas_drag_coefficient");
            const auto t = gc::evaluate(model, s);
            return std::vector<ClosureOutput>{{"pressure", "Pa", t.pressure},
                                              {"shear_viscosity", "Pa s", t.shearViscosity},
                                              {"bulk_viscosity", "Pa s", t.bulkViscosity},
                                              {"conductivity", "kg/(m s)", t.conductivity},
                                              {"dissipation_rate", "W/m3", t.dissipationRate}};
          }};
}

gc::PlasticRegime::Params plasticParams(const json& p) {
  // Schaeffer's viscosity: the catalog evaluates the closure of the reference, no DEM rheology.
  return {p.at("critical_void_fraction"), p.at("coefficient"), p.at("exponent"), p.at("internal_friction_angle"),
          p.at("max_viscosity"), std::nullopt};
}

std::vector<ClosureEntry> makeCatalog() {
  std::vector<ClosureEntry> out;

  // The drag laws, from their structs (engines/closures/GasSolidsDrag.hpp's list).
  for (auto& entry : dragLawEntries(gc::DragLaws{})) out.push_back(std::move(entry));
  {
    auto p = schema();
    p->add(ParamSpec::number("friction_coefficient")
               .defaultValue(gc::SolidsSolidsDrag::Params{}.frictionCoefficient)
               .min(0.0)
               .doc("C_f between the phases' "
                    "particles"))
        .add(ParamSpec::number("restitution")
                 .defaultValue(gc::SolidsSolidsDrag::Params{}.restitution)
                 .min(0.0, false)
                 .max(1.0)
                 .doc("e_lm"));
    auto in = schema();
    for (const char* phase : {"l", "m"}) {
      const std::string sfx = std::string("_") + phase;
      in->add(fraction("solid_fraction" + sfx, "eps_s of phase " + std::string(phase)))
          .add(ParamSpec::quantity("density" + sfx, Dimension::density()).required().positive().doc("rho_s"))
          .add(ParamSpec::quantity("diameter" + sfx, Dimension::lengthDim()).required().positive().doc("d_p"));
    }
    in->add(ParamSpec::number("g0").required().positive().doc("g0_lm (lebowitz for a mixture)"))
        .add(ParamSpec::quantity("relative_speed", Dimension::velocity()).required().min(0.0).doc("|v_sl - v_sm|"));
    out.push_back({"solids_drag", "solids-solids drag between two solids phases", "Eq. 3.18",
                   "Syamlal 1987; MFIX model/drag_ss.f", p, in, [](const json& params, const json& i) {
                     const gc::SolidsSolidsDrag law{{params.at("friction_coefficient"), params.at("restitution")}};
                     const double f = law.evaluate({i.at("solid_fraction_l"), i.at("density_l"), i.at("diameter_l")},
                                                   {i.at("solid_fraction_m"), i.at("density_m"), i.at("diameter_m")},
                                                   i.at("g0"), i.at("relative_speed"));
                     return std::vector<ClosureOutput>{{"f_sml", "kg/(m3 s)", f}};
                   }});
  }
  {
    auto in = schema();
    in->add(fraction("solid_fraction", "eps_s"));
    out.push_back({"carnahan_starling", "radial distribution at contact, one solids phase (the default)", "-",
                   "Carnahan and Starling 1969; MFIX G_0CS", schema(), in, [](const json&, const json& i) {
                     return std::vector<ClosureOutput>{{"g0", "", gc::carnahanStarlingG0(i.at("solid_fraction"))}};
                   }});
    auto ma = schema();
    ma->add(fraction("solid_fraction", "eps_s, below the packing limit 0.64356"));
    out.push_back({"ma_ahmadi_g0", "radial distribution of Ma and Ahmadi, diverging at 0.64356", "-",
                   "Ma and Ahmadi 1986", schema(), ma, [](const json&, const json& i) {
                     return std::vector<ClosureOutput>{{"g0", "", gc::maAhmadiG0(i.at("solid_fraction"))}};
                   }});
    auto leb = schema();
    leb->add(ParamSpec::quantityList("solid_fractions", Dimension::none(), 0).required().doc("eps_k of every phase"))
        .add(ParamSpec::quantityList("diameters", Dimension::lengthDim(), 0).required().doc("d_k of every phase"))
        .add(ParamSpec::integer("l").defaultValue(0).min(0).doc("first phase of the pair"))
        .add(ParamSpec::integer("m").defaultValue(0).min(0).doc("second phase of the pair"));
    out.push_back({"lebowitz", "radial distribution of a mixture (the default for several solids phases)", "-",
                   "Lebowitz 1964; MFIX rdf LEBOWITZ", schema(), leb, [](const json&, const json& i) {
                     const double g = gc::lebowitzG0(i.at("solid_fractions").get<std::vector<double>>(),
                                                     i.at("diameters").get<std::vector<double>>(),
                                                     i.at("l").get<std::size_t>(), i.at("m").get<std::size_t>());
                     return std::vector<ClosureOutput>{{"g0", "", g}};
                   }});
  }
  out.push_back(kinetic(gc::KineticModelName::Lun1984,
                        "kinetic theory of Lun et al. with the Ma-Ahmadi gas modification (the default)",
                        "Eqs. 3.34, 5.5-5.7", "Lun et al. 1984, Ma and Ahmadi 1988; MFIX calc_mu_s.f LUN_1984"));
  out.push_back(kinetic(gc::KineticModelName::Lun1984Mfix,
                        "lun1984 with MFIX's shear viscosity, (2 + alpha)/3 = 1.2 times Lun's (alpha 1.6)",
                        "Eqs. 3.34, 5.5-5.7", "MFIX calc_mu_s.f (2005, 21.3): Mu_s = ((2d0+ALPHA)/3d0)*(...)"));
  out.push_back(kinetic(gc::KineticModelName::SyamlalAlgebraicPrinted,
                        "Syamlal's algebraic closure as printed (leading term 1 in K3)", "Eqs. 3.21-3.25, 5.7",
                        "Syamlal 1987; MFIX theory guide (conductivity)"));
  out.push_back(kinetic(gc::KineticModelName::SyamlalAlgebraicMfix,
                        "Syamlal's algebraic closure with MFIX's (3e + 1)/2 in K3", "Eqs. 3.21-3.25, 5.7",
                        "MFIX gt_algebraic (2005-21.3)"));
  {
    auto p = schema();
    p->add(ParamSpec::number("critical_void_fraction")
               .required()
               .min(0.0, false)
               .max(1.0, false)
               .doc("eps_g*, where the plastic regime begins (Eqs. 3.26-3.27; usually eps_mf)"))
        .add(ParamSpec::quantity("coefficient", Dimension::pressure())
                 .defaultValue(gc::PlasticRegime::Params{}.coefficient)
                 .positive()
                 .doc("A of P* = A (eps_g* - eps_g)^n (1e25 dyn/cm2)"))
        .add(ParamSpec::number("exponent").defaultValue(gc::PlasticRegime::Params{}.exponent).positive().doc("n"))
        // With its unit for the docs; PlasticRegimeTest pins "30 degree" to Params{}'s default.
        .add(ParamSpec::number("internal_friction_angle")
                 .defaultValue("30 degree")
                 .positive()
                 .doc("phi, a quantity with its unit (\"30 degree\"); a bare number is radians"))
        .add(ParamSpec::quantity("max_viscosity", Dimension::viscosity())
                 .defaultValue(gc::PlasticRegime::Params{}.maxViscosity)
                 .positive()
                 .doc("cap of the frictional viscosity (MFIX: 1000 poise)"));
    auto in = schema();
    in->add(fraction("void_fraction", "eps_g"))
        .add(fraction("solid_fraction", "eps_s of this phase"))
        .add(ParamSpec::quantity("strain_invariant", kStrainInvariant)
                 .required()
                 .min(0.0)
                 .doc("I2D, second invariant of the deviator of D_s"));
    out.push_back({"schaeffer", "plastic regime: P* and Schaeffer's frictional viscosity", "Eqs. 3.26-3.27",
                   "Schaeffer 1987; MFIX calc_mu_s.f", p, in,
                   [](const json& params, const json& i) {
                     gc::PlasticRegime law;
                     law.params = plasticParams(params);
                     const auto r =
                         law.evaluate(i.at("void_fraction"), i.at("solid_fraction"), i.at("strain_invariant"));
                     return std::vector<ClosureOutput>{
                         {"p_star", "Pa", r.pStar}, {"pressure", "Pa", r.pressure}, {"viscosity", "Pa s", r.viscosity}};
                   },
                   [](const json& params) { return plasticParams(params).problem(); }});
  }
  {
    auto p = schema();
    p->add(ParamSpec::number("specularity")
               .defaultValue(gc::JohnsonJackson::Params{}.specularity)
               .min(0.0)
               .max(1.0)
               .doc("specularity phi': 0 free slip, 1 every collision diffuse (VALIDATION.md: MFiX's run used 0.6)"))
        .add(ParamSpec::number("max_solid_fraction")
                 .required()
                 .min(0.0, false)
                 .max(1.0, false)
                 .doc("eps_s,max, the solids fraction at packing (1 - eps_g*)"))
        .add(ParamSpec::number("wall_restitution").required().min(0.0, false).max(1.0).doc("e_w"))
        .add(ParamSpec::number("wall_effective_restitution")
                 .max(1.0)
                 .doc("e_w,eff of the rotation model (Eq. 5.21); none without it"));
    auto in = schema();
    in->add(fraction("solid_fraction", "eps_s at the wall"))
        .add(ParamSpec::quantity("density", Dimension::density()).required().positive().doc("rho_s"))
        .add(ParamSpec::number("g0").required().positive().doc("g0 at the wall"))
        .add(ParamSpec::quantity("granular_temperature", Dimension::granularTemperature())
                 .required()
                 .min(0.0)
                 .doc("theta"))
        .add(ParamSpec::quantity("slip_speed", Dimension::velocity()).required().min(0.0).doc("|v_s - v_w|"));
    out.push_back({"johnson_jackson", "partial-slip wall and wall granular-energy flux", "Eqs. 5.8-5.10, 5.21",
                   "Johnson and Jackson 1987", p, in, [](const json& params, const json& i) {
                     gc::JohnsonJackson law;
                     law.params.specularity = params.at("specularity");
                     law.params.maxSolidFraction = params.at("max_solid_fraction");
                     law.params.wallRestitution = params.at("wall_restitution");
                     if (params.contains("wall_effective_restitution"))
                       law.params.wallEffectiveRestitution = params.at("wall_effective_restitution").get<double>();
                     const auto r = law.evaluate({i.at("solid_fraction"), i.at("density"), i.at("g0"),
                                                  i.at("granular_temperature"), i.at("slip_speed")});
                     return std::vector<ClosureOutput>{{"slip_coefficient", "kg/(m2 s)", r.slipCoefficient},
                                                       {"shear_stress", "Pa", r.shearStress},
                                                       {"slip_production", "W/m2", r.slipProduction},
                                                       {"wall_dissipation", "W/m2", r.wallDissipation},
                                                       {"energy_flux_into_flow", "W/m2", r.energyFluxIntoFlow()}};
                   }});
  }
  {
    auto p = schema();
    p->add(ParamSpec::number("mu").required().min(0.0).doc("Coulomb friction coefficient of the surfaces"))
        .add(ParamSpec::number("beta0")
                 .defaultValue(gc::EffectiveRestitution::Params{}.tangentialRestitution)
                 .min(-1.0)
                 .max(1.0)
                 .doc("tangential restitution (Table 5.1: 0.33)"));
    auto in = schema();
    in->add(ParamSpec::number("e").required().min(0.0, false).max(1.0).doc("normal restitution"));
    out.push_back({"effective_restitution", "particle-rotation model: e_eff for Eqs. 5.20-5.21 only", "Eqs. 5.11-5.21",
                   "Jenkins and Zhang 2002", p, in, [](const json& params, const json& i) {
                     const auto r = gc::EffectiveRestitution{{params.at("mu"), params.at("beta0")}}.evaluate(i.at("e"));
                     return std::vector<ClosureOutput>{{"e_eff", "", r.effectiveRestitution},
                                                       {"theta_r_over_theta_t", "", r.rotationalToTranslational},
                                                       {"dissipation_factor", "", r.dissipationFactor}};
                   }});
  }
  {
    auto in = schema();
    in->add(fraction("solid_fraction", "eps_s"))
        .add(ParamSpec::quantity("diameter", Dimension::lengthDim()).required().positive().doc("d_p"))
        .add(ParamSpec::quantity("density", Dimension::density()).required().positive().doc("rho_s"))
        .add(ParamSpec::number("g0").required().positive().doc("g0"))
        .add(ParamSpec::quantity("gas_viscosity", Dimension::viscosity())
                 .defaultValue("1.8e-5 Pa s")
                 .positive()
                 .doc("mu_g"))
        .add(ParamSpec::quantity("slip", Dimension::velocity()).required().min(0.0).doc("|v_g - v_s|"))
        .add(ParamSpec::quantity("beta", kDragCoefficient).required().min(0.0).doc("gas-solids drag coefficient"));
    out.push_back(
        {"granular_energy_gas_terms", "gamma_slip and J_vis of the granular-energy equation", "Eq. 5.5",
         "MFIX's Lun path (Koch 1990, Gidaspow 1994)", schema(), in, [](const json&, const json& i) {
           const auto r =
               gc::GranularEnergyGasTerms{}.evaluate({i.at("solid_fraction"), i.at("diameter"), i.at("density"),
                                                      i.at("g0"), i.at("gas_viscosity"), i.at("slip"), i.at("beta")});
           return std::vector<ClosureOutput>{{"gamma_slip_coefficient", "W m/(m3 s)", r.slipProductionCoefficient},
                                             {"j_vis_coefficient", "kg/(m3 s)", r.viscousDissipationCoefficient}};
         }});
  }
  return out;
}

}  // namespace

// The gas-solids drag state, shared by every drag law (DragLawCatalog.hpp).
std::shared_ptr<ParamSchema> dragInputs() {
  auto s = schema();
  s->add(fraction("void_fraction", "eps_g"))
      .add(fraction("solid_fraction", "eps_s of this solids phase"))
      .add(ParamSpec::quantity("diameter", Dimension::lengthDim()).required().positive().doc("particle diameter d_p"))
      .add(ParamSpec::quantity("gas_density", Dimension::density()).defaultValue("1.2 kg/m3").positive().doc("rho_g"))
      .add(ParamSpec::quantity("gas_viscosity", Dimension::viscosity())
               .defaultValue("1.8e-5 Pa s")
               .positive()
               .doc("mu_g"))
      .add(ParamSpec::quantity("slip", Dimension::velocity()).required().min(0.0).doc("|v_g - v_s|"));
  return s;
}

gc::DragState dragState(const json& in) {
  return {in.at("void_fraction"), in.at("solid_fraction"), in.at("diameter"),
          in.at("gas_density"),   in.at("gas_viscosity"),  in.at("slip")};
}

std::vector<ClosureOutput> dragOutputs(const gc::DragCoefficients& c) {
  return {{"beta", "kg/(m3 s)", c.beta}, {"particle_drag_coefficient", "kg/s", c.particle}};
}

const std::vector<ClosureEntry>& closureCatalog() {
  static const std::vector<ClosureEntry> catalog = makeCatalog();
  return catalog;
}

const ClosureEntry* findClosure(std::string_view name) {
  for (const auto& e : closureCatalog()) {
    if (e.name == name) return &e;
  }
  return nullptr;
}

params::ParamSpec closureParameter(std::string_view law, const std::string& key) {
  const ClosureEntry* entry = findClosure(law);
  const params::ParamSpec* spec = entry != nullptr ? entry->params->find(key) : nullptr;
  if (spec == nullptr) throw Error("closure catalog: law " + std::string(law) + " has no parameter " + key);
  return *spec;
}

}  // namespace grainbridge::workflows::closures
