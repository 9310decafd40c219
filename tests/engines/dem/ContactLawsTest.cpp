// Every registered composition of contact sub-models (contact/ContactModels.hpp; the normal and
// tangential forces of Eqs. 6.5-6.6 with the history of Eq. 6.4), one typed test each, so a new
// sub-model is checked by adding it to its list:
// - Newton's third law: the pair seen from j is the pair seen from i with n, v and u_t reversed,
//   and its force is the exact opposite;
// - the zero-overlap and zero-velocity limits: no force at first touch, no dashpot force and no
//   change of history without relative motion;
// - energy consistency of the elastic parts: without damping a head-on collision rebounds at its
//   impact speed, and a sticking tangential spring stores exactly the work done on it;
// - history under rigid rotation: u_t stays in the tangent plane and keeps its length up to the
//   projection's second-order loss;
// - the set-up evaluation (History::Keep) leaves the history as it was;
// - only the branch's direction counts, not its length (ContactKinematics::branch).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "engines/dem/contact/ContactModels.hpp"
#include "engines/dem/contact/Conversions.hpp"

using namespace grainbridge;
using namespace grainbridge::dem;
using namespace grainbridge::dem::contact;

namespace {

template <class List>
struct GtestTypes;
template <class... L>
struct GtestTypes<TypeList<L...>> {
  using type = ::testing::Types<L...>;
};

// Table 6.1's particle coefficients in reduced units, with both dashpot forms set.
PairMaterial material(bool damped) {
  PairMaterial m;
  m.kn = 2e5;
  m.kt = 2.0 / 7.0 * m.kn;
  m.gammaN = damped ? 40.0 : 0.0;
  m.gammaT = damped ? 20.0 : 0.0;
  m.etaN = damped ? 12.0 : 0.0;
  m.etaT = damped ? 6.0 : 0.0;
  m.mu = 0.5;
  return m;
}

ContactKinematics someContact() {
  ContactKinematics c;
  c.setUnitNormal(Vec3(1.0, 2.0, -2.0) / 3.0);
  c.d = 1.0;
  c.delta = 2e-3;
  c.meff = 0.26;
  const Vec3 vij(0.3, -0.7, 0.4);
  c.vn = vij.dot(c.n) * c.n;
  c.vt = vij - c.vn + Vec3(0.05, 0.0, 0.025);  // plus a rolling part, in the tangent plane
  c.vt -= c.vt.dot(c.n) * c.n;
  return c;
}

ContactKinematics mirrored(ContactKinematics c) {
  c.setUnitNormal(-c.n);
  c.vn = -c.vn;
  c.vt = -c.vt;
  return c;
}

Vec3 inPlane(const Vec3& u, const Vec3& n) { return u - u.dot(n) * n; }

template <class Law>
class EveryContactLaw : public ::testing::Test {};
TYPED_TEST_SUITE(EveryContactLaw, GtestTypes<ContactLaws>::type);

TYPED_TEST(EveryContactLaw, ObeyNewtonsThirdLaw) {
  using Law = TypeParam;
  const double dt = 1e-4;
  for (const double mu : {0.5, 0.01}) {  // sticking, and sliding under the Coulomb cap
    PairMaterial m = material(true);
    m.mu = mu;
    const ContactKinematics c = someContact();
    Vec3 ui = inPlane(Vec3(1e-4, 3e-5, -2e-5), c.n);
    Vec3 uj = -ui;
    for (int step = 0; step < 5; ++step) {
      const auto fi = Law::evaluate(c, m, dt, ui, History::Advance);
      const auto fj = Law::evaluate(mirrored(c), m, dt, uj, History::Advance);
      EXPECT_LE((fi.normal() + fj.normal()).norm(), 1e-14 * fi.normal().norm()) << "mu " << mu;
      EXPECT_LE((fi.tangential() + fj.tangential()).norm(), 1e-14 * fi.normal().norm()) << "mu " << mu;
      EXPECT_LE((ui + uj).norm(), 1e-14 * ui.norm()) << "mu " << mu;
      EXPECT_GT(fi.tangential().norm(), 0.0);
      // The Coulomb cap holds on the whole normal force.
      EXPECT_LE(fi.tangential().norm(), mu * fi.normal().norm() * (1.0 + 1e-12));
    }
  }
}

TYPED_TEST(EveryContactLaw, GiveNoForceAtFirstTouchAndNoDashpotWithoutMotion) {
  using Law = TypeParam;
  const PairMaterial m = material(true);
  ContactKinematics c = someContact();
  // First touch at rest: nothing at all, and finite (Hertz takes a square root of delta/d).
  c.vn.setZero();
  c.vt.setZero();
  c.delta = 1e-300;
  Vec3 u = Vec3::Zero();
  auto f = Law::evaluate(c, m, 1e-4, u, History::Advance);
  EXPECT_LT(f.normal().norm(), 1e-290);
  EXPECT_EQ(f.tangential().norm(), 0.0);
  EXPECT_EQ(u, Vec3::Zero());
  // At rest with an overlap and a stored displacement: dashpots silent, history kept.
  c.delta = 2e-3;
  const Vec3 u0 = inPlane(Vec3(2e-5, -1e-5, 3e-5), c.n);
  u = u0;
  f = Law::evaluate(c, m, 1e-4, u, History::Advance);
  EXPECT_EQ(f.normalDissipative.norm(), 0.0);
  EXPECT_EQ(f.tangentialDissipative.norm(), 0.0);
  EXPECT_LE((u - u0).norm(), 1e-15 * u0.norm());
  EXPECT_GT(f.normalElastic.dot(c.n), 0.0);  // repulsive
  if constexpr (Law::Tangential::historySize > 0) {
    EXPECT_LT(f.tangentialElastic.dot(u0), 0.0);  // restoring
  }
}

TYPED_TEST(EveryContactLaw, ElasticPartsStoreWhatIsDoneOnThem) {
  using Law = TypeParam;
  const PairMaterial m = material(false);
  // Normal: an undamped head-on collision gives back its impact speed.
  const auto r = headOnCollision(Law{}, m, 0.26, 1.0, 0.5);
  EXPECT_NEAR(r.restitution, 1.0, 1e-9);
  EXPECT_TRUE(std::isfinite(r.contactTime));
  // Tangential: a sticking contact driven along a closed loop in the tangent plane at fixed
  // overlap. The work done on it, -integral F_t,el . v_t dt, equals the spring energy
  // 1/2 f k_t |u_t|^2 at every point and returns to zero when the loop closes.
  PairMaterial stuck = m;
  stuck.mu = 1e6;
  ContactKinematics c = someContact();
  c.vn.setZero();
  const Vec3 e1 = inPlane(Vec3::UnitX(), c.n).normalized();
  const Vec3 e2 = c.n.cross(e1);
  const double f = Law::Normal::scale(c.delta, c.d);
  const int steps = 4000;
  const double dt = 1e-5;
  Vec3 u = Vec3::Zero();
  double work = 0.0;
  double worst = 0.0;
  Vec3 before = Vec3::Zero();
  for (int k = 0; k < steps; ++k) {
    const double phase = 2.0 * M_PI * (k + 0.5) / steps;
    c.vt = 1e-1 * (std::cos(phase) * e1 + std::sin(2.0 * phase) * e2);
    const auto force = Law::evaluate(c, stuck, dt, u, History::Advance);
    // Midpoint rule on the spring force, linear in u_t across the step.
    work -= 0.5 * (-f * stuck.kt * before + force.tangentialElastic).dot(c.vt * dt);
    before = force.tangentialElastic / (-f * stuck.kt);
    const double stored = 0.5 * f * stuck.kt * u.squaredNorm();
    worst = std::max(worst, std::abs(work - stored));
  }
  const double scale = 0.5 * f * stuck.kt * std::pow(1e-1 * dt * steps / (2.0 * M_PI), 2);
  EXPECT_LE(worst, 1e-9 * scale);
  EXPECT_LE(u.norm(), 1e-12 * 1e-1 * dt * steps);
}

TYPED_TEST(EveryContactLaw, KeepTheHistoryInTheTangentPlaneUnderRigidRotation) {
  using Law = TypeParam;
  if constexpr (Law::Tangential::historySize == 0) GTEST_SKIP() << "no history";
  PairMaterial m = material(false);
  m.mu = 1e6;
  ContactKinematics c = someContact();
  c.vn.setZero();
  c.vt.setZero();  // rigid rotation of the pair: the contact surfaces do not slip
  const Vec3 axis = c.n.cross(Vec3::UnitZ()).normalized().cross(c.n).normalized();  // in the tangent plane
  const Vec3 u0 = 1e-4 * axis.cross(c.n);
  Vec3 u = u0;
  const int perTurn = 1000;
  const int turns = 10;
  const Eigen::AngleAxisd turn(2.0 * M_PI / perTurn, axis);
  const double lossBound = std::pow(std::cos(2.0 * M_PI / perTurn), perTurn * turns);
  for (int k = 0; k < perTurn * turns; ++k) {
    c.setUnitNormal(turn * c.n);
    const auto f = Law::evaluate(c, m, 1e-4, u, History::Advance);
    ASSERT_LE(std::abs(u.dot(c.n)), 1e-12 * u0.norm()) << "step " << k;
    ASSERT_LE(std::abs(f.tangential().dot(c.n)), 1e-12 * f.tangential().norm()) << "step " << k;
    ASSERT_LE(u.norm(), u0.norm() * (1.0 + 1e-12));
    ASSERT_GE(u.norm(), u0.norm() * (lossBound - 1e-9));
  }
}

TYPED_TEST(EveryContactLaw, SeeOnlyTheDirectionOfTheBranch) {
  // A pair's contact carries its branch r_ij and 1 / r^2 beside n (ContactKinematics::branch);
  // the law must give the force and history of the unit normal whatever the branch's length.
  using Law = TypeParam;
  for (const double mu : {0.5, 0.01}) {
    PairMaterial m = material(true);
    m.mu = mu;
    const ContactKinematics unit = someContact();
    const Vec3 u0 = inPlane(Vec3(1e-4, 3e-5, -2e-5), unit.n) + 1e-6 * unit.n;  // a little off the plane
    for (const double length : {1e-3, 0.7, 3.1}) {
      ContactKinematics c = unit;
      c.branch = length * unit.n;
      c.invBranch2 = 1.0 / (length * length);
      Vec3 uUnit = u0;
      Vec3 u = u0;
      const auto fUnit = Law::evaluate(unit, m, 1e-4, uUnit, History::Advance);
      const auto f = Law::evaluate(c, m, 1e-4, u, History::Advance);
      EXPECT_LE((f.normal() - fUnit.normal()).norm(), 1e-14 * fUnit.normal().norm()) << length;
      EXPECT_LE((f.tangential() - fUnit.tangential()).norm(), 1e-14 * fUnit.normal().norm()) << length;
      EXPECT_LE((u - uUnit).norm(), 1e-14 * u0.norm()) << length;
    }
  }
}

TEST(LengthRestoringFactor, IsOneOverTheSineOfTheHistorysAngleToTheNormal) {
  // Eq. 6.4's rescale |u| / |u - (u.n) n| = 1 / sqrt(1 - s), s = (u.n)^2 / |u|^2: a series
  // below s = 1e-4, the direct form above. Both within two ulps of the exact value.
  for (const double s : {1e-16, 1e-12, 3e-8, 1e-6, 9.99e-5, 1e-4, 0.01, 0.5}) {
    const Vec3 n = Vec3(2.0, -1.0, 2.0) / 3.0;
    const Vec3 t = Vec3(1.0, 2.0, 0.0) / std::sqrt(5.0);  // normal to n
    const Vec3 u = 3e-5 * (std::sqrt(s) * n + std::sqrt(1.0 - s) * t);
    const double before2 = u.squaredNorm();
    const double along = u.dot(n);
    const Vec3 projected = u - along * n;
    const double exact = static_cast<double>(1.0L / std::sqrt(1.0L - static_cast<long double>(along) * along / before2));
    const double factor = lengthRestoringFactor(before2, along * along, projected);
    EXPECT_NEAR(factor, exact, 2.0 * std::numeric_limits<double>::epsilon() * exact) << "s " << s;
  }
}

TYPED_TEST(EveryContactLaw, LeaveTheHistoryAloneInTheSetUpEvaluation) {
  using Law = TypeParam;
  for (const double mu : {0.5, 1e-3}) {
    PairMaterial m = material(true);
    m.mu = mu;
    const ContactKinematics c = someContact();
    const Vec3 u0 = Vec3(3e-5, 1e-5, -4e-5);  // even out of the plane: Keep touches nothing
    Vec3 u = u0;
    const auto f = Law::evaluate(c, m, 1e-4, u, History::Keep);
    EXPECT_EQ(u, u0);
    EXPECT_LE(f.tangential().norm(), mu * f.normal().norm() * (1.0 + 1e-12));
  }
}

}  // namespace
