#pragma once
// Dashpot sub-models: the dissipative normal and tangential forces of a contact.
// - mass_scaled, Eqs. 6.5-6.6: F = -f gamma m_eff v, gamma a rate [1/s] (Silbert et al. 2001);
// - dimensional: F = -eta v, eta a dashpot coefficient [kg/s], as TF-DEM's Table 7.1 gives it;
//   not scaled by f, so with the linear spring it is mass_scaled with gamma = eta / m_eff.
// Each declares its name (the `damping_model` key), the coefficients it reads, and how a rate
// gamma_n (what Eqs. 6.9-6.10 give for a restitution) becomes its normal coefficient.
#include "engines/dem/Material.hpp"
#include "engines/dem/contact/ContactKinematics.hpp"

namespace grainbridge::dem::contact {

struct MassScaledDamping {
  static constexpr const char* name = "mass_scaled";
  static constexpr const char* doc = "-f gamma m_eff v (Eqs. 6.5-6.6): gamma_n, gamma_t in 1/s";
  [[gnu::always_inline]] static Vec3 normal(const ContactKinematics& c, const PairMaterial& m, double f) {
    return (-f * m.gammaN * c.meff) * c.vn;
  }
  [[gnu::always_inline]] static Vec3 tangential(const ContactKinematics& c, const PairMaterial& m, double f) {
    return (-f * m.gammaT * c.meff) * c.vt;
  }
  // -tangential(c, m, f) / f: what a capped contact's spring displacement is offset by.
  [[gnu::always_inline]] static Vec3 tangentialPerScale(const ContactKinematics& c, const PairMaterial& m,
                                                        double /*f*/) {
    return m.gammaT * c.meff * c.vt;
  }
  static void setNormalRate(PairMaterial& m, double gammaN, double /*meff*/) { m.gammaN = gammaN; }
  [[nodiscard]] static double normalRate(const PairMaterial& m, double /*meff*/) { return m.gammaN; }
};

struct DimensionalDamping {
  static constexpr const char* name = "dimensional";
  static constexpr const char* doc = "-eta v: eta_n, eta_t in kg/s (Table 7.1's dashpot coefficients)";
  [[gnu::always_inline]] static Vec3 normal(const ContactKinematics& c, const PairMaterial& m, double /*f*/) {
    return -m.etaN * c.vn;
  }
  [[gnu::always_inline]] static Vec3 tangential(const ContactKinematics& c, const PairMaterial& m, double /*f*/) {
    return -m.etaT * c.vt;
  }
  [[gnu::always_inline]] static Vec3 tangentialPerScale(const ContactKinematics& c, const PairMaterial& m, double f) {
    return (m.etaT / f) * c.vt;
  }
  static void setNormalRate(PairMaterial& m, double gammaN, double meff) { m.etaN = gammaN * meff; }
  [[nodiscard]] static double normalRate(const PairMaterial& m, double meff) { return m.etaN / meff; }
};

}  // namespace grainbridge::dem::contact
