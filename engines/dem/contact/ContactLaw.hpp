#pragma once
// A contact law composed of a normal spring, a damping and a tangential sub-model
// (NormalModels.hpp, DampingModels.hpp, TangentialModels.hpp):
//
//   F_n = f(delta/d) k_n delta n + D_n                                        (6.5)
//   F_t = -f(delta/d) k_t u_t + D_t,  |F_t| <= mu |F_n|                        (6.6)
//
// D the damping model's dashpot forces, u_t the tangential model's history. A small value type
// with static members only: the engine picks one composition per run (ContactModels.hpp) and the
// pair and wall loops are instantiated for it, so nothing inside them is virtual. The sub-models'
// members are always_inline: left to itself GCC kept the tangential step out of line, +20 %
// instructions in the dense-bed benchmark (callgrind).
#include "engines/dem/Material.hpp"
#include "engines/dem/contact/ContactKinematics.hpp"

namespace grainbridge::dem::contact {

template <class NormalModel, class DampingModel, class TangentialModel>
struct ContactLaw {
  using Normal = NormalModel;
  using Damping = DampingModel;
  using Tangential = TangentialModel;
  static_assert(Tangential::historySize <= 3, "a contact stores one Vec3 of history");

  // The force on i; with History::Advance also moves u_t on by one step of dt. About 60 flops.
  [[gnu::always_inline]] static ContactForce evaluate(const ContactKinematics& c, const PairMaterial& m, double dt,
                                                      Vec3& ut, History h) {
    const double f = Normal::scale(c.delta, c.d);
    ContactForce out;
    out.normalElastic = (f * m.kn * c.delta) * c.n;
    out.normalDissipative = Damping::normal(c, m, f);
    Tangential::template apply<Damping>(c, m, f, dt, ut, h, out);
    return out;
  }

  // A contact of friction mu = 0: the cap |F_t| <= mu |F_n| of Eq. 6.6 leaves no tangential force,
  // and none is computed (evaluate would give F_t = 0 to round-off, after the whole tangential
  // step: a third of a frictionless sheared box's pair loop). Nothing to remember either: a
  // frictionless contact's history stays zero.
  [[gnu::always_inline]] static ContactForce evaluateNormal(const ContactKinematics& c, const PairMaterial& m) {
    const double f = Normal::scale(c.delta, c.d);
    ContactForce out;
    out.normalElastic = (f * m.kn * c.delta) * c.n;
    out.normalDissipative = Damping::normal(c, m, f);
    out.tangentialElastic.setZero();
    out.tangentialDissipative.setZero();
    return out;
  }

  // The normal force alone (head-on collisions, Conversions.hpp).
  static Vec3 normalForce(const ContactKinematics& c, const PairMaterial& m) {
    const double f = Normal::scale(c.delta, c.d);
    return (f * m.kn * c.delta) * c.n + Damping::normal(c, m, f);
  }
};

}  // namespace grainbridge::dem::contact
