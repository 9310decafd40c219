#include "engines/dem/contact/Conversions.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/Error.hpp"

namespace grainbridge::dem::contact {

namespace {

template <class Law>
CollisionResponse integrateCollision(const PairMaterial& m, double meff, double d, double v0) {
  // Along n (from j to i): overlap delta grows at w = -v_n; meff delta'' = -F_n . n.
  ContactKinematics c;
  c.setUnitNormal(Vec3::UnitX());
  c.d = d;
  c.vt = Vec3::Zero();
  c.meff = meff;
  auto accel = [&](double delta, double w) {
    c.delta = std::max(delta, 0.0);
    c.vn = -w * c.n;
    return -Law::normalForce(c, m).dot(c.n) / meff;
  };
  // Any f(delta/d) <= 1 while delta < d makes the contact softer than the linear one: its time
  // is a lower bound on this one's, and 2000 steps of it resolve the collision.
  const double h = M_PI * std::sqrt(meff / m.kn) / 2000.0;
  double delta = 0.0;
  double w = v0;
  double t = 0.0;
  // An overdamped contact creeps apart for ever: give up after 500 linear contact times.
  for (long k = 0; k < 1'000'000L; ++k) {
    const double a1 = accel(delta, w);
    const double a2 = accel(delta + 0.5 * h * w, w + 0.5 * h * a1);
    const double a3 = accel(delta + 0.5 * h * (w + 0.5 * h * a1), w + 0.5 * h * a2);
    const double a4 = accel(delta + h * (w + 0.5 * h * a2), w + h * a3);
    const double next = delta + h * (w + h / 6.0 * (a1 + a2 + a3));
    const double wNext = w + h / 6.0 * (a1 + 2.0 * a2 + 2.0 * a3 + a4);
    if (next <= 0.0 && t > 0.0) {
      const double s = delta / (delta - next);  // the crossing, linearly within the step
      return {-(w + s * (wNext - w)) / v0, t + s * h};
    }
    delta = next;
    w = wNext;
    t += h;
  }
  return {0.0, std::numeric_limits<double>::infinity()};
}

template <class Law>
CollisionResponse response(const PairMaterial& m, double meff, double d, double v0) {
  if constexpr (Law::Normal::closedFormCollision) {
    const double rate = Law::Damping::normalRate(m, meff);
    return {linearRestitution(m.kn, rate, meff), linearContactTime(m.kn, rate, meff)};
  } else {
    return integrateCollision<Law>(m, meff, d, v0);
  }
}

}  // namespace

bool hasClosedFormCollision(const AnyContactLaw& law) {
  return std::visit([](auto l) { return decltype(l)::Normal::closedFormCollision; }, law);
}

CollisionResponse headOnCollision(const AnyContactLaw& law, const PairMaterial& m, double meff, double d,
                                  double impactSpeed) {
  return std::visit([&](auto l) { return response<decltype(l)>(m, meff, d, impactSpeed); }, law);
}

CollisionResponse linearEstimate(const AnyContactLaw& law, const PairMaterial& m, double meff) {
  const double rate = std::visit([&](auto l) { return decltype(l)::Damping::normalRate(m, meff); }, law);
  return {linearRestitution(m.kn, rate, meff), linearContactTime(m.kn, rate, meff)};
}

PairMaterial withRestitution(const AnyContactLaw& law, PairMaterial m, double e, double meff, double d,
                             double impactSpeed) {
  return std::visit(
      [&](auto l) {
        using Law = decltype(l);
        using Damping = typename Law::Damping;
        // Closed form: Eqs. 6.9-6.10 inverted for this pair's m_eff.
        if constexpr (Law::Normal::closedFormCollision) {
          Damping::setNormalRate(m, gammaForRestitution(e, m.kn, meff), meff);
          return m;
        } else {
          auto restitutionAt = [&](double rate) {
            Damping::setNormalRate(m, rate, meff);
            return integrateCollision<Law>(m, meff, d, impactSpeed).restitution;
          };
          if (e >= 1.0) {
            Damping::setNormalRate(m, 0.0, meff);
            return m;
          }
          // e falls as the damping rate grows: bracket from the linear law's rate, then bisect.
          double lo = 0.0;
          double hi = std::max(gammaForRestitution(e, m.kn, meff), 1e-12 * std::sqrt(m.kn / meff));
          for (int k = 0; k < 200 && restitutionAt(hi) > e; ++k) {
            lo = hi;
            hi *= 2.0;
          }
          for (int k = 0; k < 200 && hi - lo > 1e-14 * hi; ++k) {
            const double mid = 0.5 * (lo + hi);
            const double em = restitutionAt(mid);
            if (std::abs(em - e) < 1e-10) {
              lo = hi = mid;
              break;
            }
            (em > e ? lo : hi) = mid;
          }
          Damping::setNormalRate(m, 0.5 * (lo + hi), meff);
          return m;
        }
      },
      law);
}

PairMaterial withContactTime(const AnyContactLaw& law, PairMaterial m, double contactTime,
                             std::optional<double> restitution, double meff) {
  return std::visit(
      [&](auto l) {
        using Law = decltype(l);
        GB_ASSERT(Law::Normal::closedFormCollision, "contact_time needs a closed-form collision");
        if (restitution) Law::Damping::setNormalRate(m, -2.0 * std::log(*restitution) / contactTime, meff);
        const double rate = Law::Damping::normalRate(m, meff);
        m.kn = meff * (M_PI * M_PI / (contactTime * contactTime) + 0.25 * rate * rate);
        return m;
      },
      law);
}

}  // namespace grainbridge::dem::contact
