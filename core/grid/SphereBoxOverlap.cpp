#include "core/grid/SphereBoxOverlap.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace grainbridge::core::grid {

namespace {

// 1 - x^2 - y^2 with the squares and sums compensated (exact products by fma, Knuth's
// two-sum): near the sphere surface this is a small difference of O(1) numbers, and its square
// root enters atan2 terms whose sensitivity grows as 1 / sqrt, so plain evaluation loses half
// the digits (1e-8 errors in volumes of order 1).
double oneMinusSquares(double x, double y) {
  const auto twoSum = [](double a, double b, double& err) {
    const double s = a + b;
    const double bb = s - a;
    err = (a - (s - bb)) + (b - bb);
    return s;
  };
  const double px = x * x, ex = std::fma(x, x, -px);
  const double py = y * y, ey = std::fma(y, y, -py);
  double e1 = 0.0, e2 = 0.0;
  double s = twoSum(1.0, -px, e1);
  s = twoSum(s, -py, e2);
  return s + ((e1 + e2) - (ex + ey));
}

double safeSqrt(double x) { return std::sqrt(std::max(0.0, x)); }

// Antiderivative of 1 - x^2: the area of a slice x = const of the unit ball is pi (1 - x^2).
double slicePrimitive(double x) { return x - x * x * x / 3.0; }

// Antiderivative of sqrt(u^2 - x^2) at x, given root = sqrt(u^2 - x^2) (asin written as atan2
// of the accurate root, which stays well conditioned near x = u).
double circlePrimitive(double u2, double x, double root) { return 0.5 * (x * root + u2 * std::atan2(x, root)); }

// Integrating (1 - x^2) asin(b / sqrt(1 - x^2)) by parts leaves
//   b * integral of x^2 (1 - x^2/3) / ((1 - x^2) sqrt(u^2 - x^2)) dx,   u^2 = 1 - b^2,
// whose antiderivative is (b/3) [I2 - 2 I0] + (2/3) atan(x b / sqrt(u^2 - x^2)), with I0, I2 the
// integrals of 1 and x^2 over sqrt(u^2 - x^2); root = sqrt(u^2 - x^2).
double byPartsRemainder(double b, double u2, double x, double root) {
  const double i0 = std::atan2(x, root);
  const double i2 = 0.5 * (u2 * i0 - x * root);
  return b / 3.0 * (i2 - 2.0 * i0) + 2.0 / 3.0 * std::atan2(x * b, root);
}

// Unit ball intersected with {x > a, y > b, z > c} for a, b, c >= 0. The slice at x has
// radius q = sqrt(1 - x^2); its part with y > b, z > c has area
//   A(x) = b c - (c sqrt(q^2 - c^2) + b sqrt(q^2 - b^2)) / 2 + q^2/2 (pi/2 - asin(b/q) - asin(c/q)),
// integrated from x = a to X = sqrt(1 - b^2 - c^2), where the slice leaves the corner. At X the
// roots are known exactly (sqrt(1 - b^2 - X^2) = c, sqrt(1 - c^2 - X^2) = b).
double nonNegativeCorner(double a, double b, double c) {
  const double X2 = oneMinusSquares(b, c);
  if (X2 <= a * a) return 0.0;
  const double X = std::sqrt(X2);
  const double ub2 = oneMinusSquares(b, 0.0), uc2 = oneMinusSquares(c, 0.0);
  const double rootAB = safeSqrt(oneMinusSquares(a, b));  // sqrt(1 - a^2 - b^2) >= c
  const double rootAC = safeSqrt(oneMinusSquares(a, c));  // sqrt(1 - a^2 - c^2) >= b
  const double rectangle = b * c * (X - a);
  const double cTerm = -0.5 * c * (circlePrimitive(uc2, X, b) - circlePrimitive(uc2, a, rootAC));
  const double bTerm = -0.5 * b * (circlePrimitive(ub2, X, c) - circlePrimitive(ub2, a, rootAB));
  const double quarterDiscs = 0.25 * M_PI * (slicePrimitive(X) - slicePrimitive(a));
  // integral_a^X (1 - x^2) asin(b / sqrt(1 - x^2)) dx by parts; asin(b / sqrt(1 - x^2)) is
  // atan2(b, c) at X and atan2(b, rootAB) at a.
  const double asinB = slicePrimitive(X) * std::atan2(b, c) - slicePrimitive(a) * std::atan2(b, rootAB) -
                       (byPartsRemainder(b, ub2, X, c) - byPartsRemainder(b, ub2, a, rootAB));
  const double asinC = slicePrimitive(X) * std::atan2(c, b) - slicePrimitive(a) * std::atan2(c, rootAC) -
                       (byPartsRemainder(c, uc2, X, b) - byPartsRemainder(c, uc2, a, rootAC));
  return rectangle + cTerm + bTerm + quarterDiscs - 0.5 * (asinB + asinC);
}

}  // namespace

double unitBallCornerVolume(double a, double b, double c) {
  if (a >= 1.0 || b >= 1.0 || c >= 1.0) return 0.0;
  // {x > a} for a < 0 is the whole ball minus its mirror image {x > -a}; the whole ball is
  // twice the half x > 0 (nothing else depends on x).
  if (a < 0.0) return 2.0 * unitBallCornerVolume(0.0, b, c) - unitBallCornerVolume(-a, b, c);
  if (b < 0.0) return 2.0 * unitBallCornerVolume(a, 0.0, c) - unitBallCornerVolume(a, -b, c);
  if (c < 0.0) return 2.0 * unitBallCornerVolume(a, b, 0.0) - unitBallCornerVolume(a, b, -c);
  return nonNegativeCorner(a, b, c);
}

double sphereBoxOverlapVolume(const Vec3& centre, double radius, const Vec3& boxLo, const Vec3& boxHi) {
  if (!(radius > 0.0)) return 0.0;
  for (int a = 0; a < 3; ++a) {
    if (!(boxHi[a] > boxLo[a])) return 0.0;
  }
  // Quick exits: box clear of the sphere, sphere inside the box, box inside the sphere.
  const Vec3 nearest = centre.cwiseMax(boxLo).cwiseMin(boxHi);
  if ((nearest - centre).squaredNorm() >= radius * radius) return 0.0;
  const Vec3 farthest = (centre - boxLo).cwiseAbs().cwiseMax((boxHi - centre).cwiseAbs());
  if (farthest.squaredNorm() <= radius * radius) return (boxHi - boxLo).prod();
  const double r3 = radius * radius * radius;
  if (((centre.array() - radius) >= boxLo.array()).all() && ((centre.array() + radius) <= boxHi.array()).all()) {
    return 4.0 / 3.0 * M_PI * r3;
  }
  // {lo < x < hi} = {x > lo} minus {x > hi}; an upper face beyond the sphere drops its term.
  struct Term {
    double u;
    double sign;
  };
  std::array<std::array<Term, 2>, 3> terms{};
  std::array<int, 3> count{};
  for (int a = 0; a < 3; ++a) {
    const auto s = static_cast<std::size_t>(a);
    const double lo = std::clamp((boxLo[a] - centre[a]) / radius, -1.0, 1.0);
    const double hi = std::clamp((boxHi[a] - centre[a]) / radius, -1.0, 1.0);
    terms[s][0] = {lo, 1.0};
    count[s] = 1;
    if (hi < 1.0) terms[s][count[s]++] = {hi, -1.0};
  }
  double unit = 0.0;
  for (int i = 0; i < count[0]; ++i) {
    for (int j = 0; j < count[1]; ++j) {
      for (int k = 0; k < count[2]; ++k) {
        const Term& x = terms[0][static_cast<std::size_t>(i)];
        const Term& y = terms[1][static_cast<std::size_t>(j)];
        const Term& z = terms[2][static_cast<std::size_t>(k)];
        unit += x.sign * y.sign * z.sign * unitBallCornerVolume(x.u, y.u, z.u);
      }
    }
  }
  return std::max(0.0, unit) * r3;
}

}  // namespace grainbridge::core::grid
