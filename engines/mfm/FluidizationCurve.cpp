#include "engines/mfm/FluidizationCurve.hpp"

#include <algorithm>
#include <cmath>

namespace grainbridge::mfm {

FluidizationReading readFluidizationCurve(std::vector<CurvePoint> points) {
  std::sort(points.begin(), points.end(), [](const auto& a, const auto& b) { return a.inflow < b.inflow; });
  FluidizationReading r;
  if (points.size() < 3) return r;
  double plateau = 0.0;
  for (const auto& p : points) plateau = std::max(plateau, p.pressureDrop);
  for (int pass = 0; pass < 5; ++pass) {
    // The packed branch: dp = a U + b U^2 through the points below 90 % of the plateau.
    double s11 = 0.0, s12 = 0.0, s22 = 0.0, t1 = 0.0, t2 = 0.0;
    int packed = 0;
    for (const auto& p : points) {
      if (p.pressureDrop >= 0.9 * plateau) continue;
      const double u = p.inflow, u2 = u * u;
      s11 += u * u;
      s12 += u * u2;
      s22 += u2 * u2;
      t1 += u * p.pressureDrop;
      t2 += u2 * p.pressureDrop;
      ++packed;
    }
    if (packed < 2) return r;
    const double det = s11 * s22 - s12 * s12;
    if (det == 0.0) return r;
    const double a = (t1 * s22 - t2 * s12) / det, b = (s11 * t2 - s12 * t1) / det;
    // Where a U + b U^2 = plateau (the positive root; linear when b vanishes).
    const double uf =
        std::abs(b) < 1e-12 * std::abs(a) ? plateau / a : (-a + std::sqrt(a * a + 4.0 * b * plateau)) / (2.0 * b);
    double sum = 0.0, variance = 0.0;
    int n = 0;
    for (const auto& p : points) {
      if (p.inflow <= uf) continue;
      sum += p.pressureDrop;
      variance += p.error * p.error;
      ++n;
    }
    if (n < 2 || !std::isfinite(uf)) return FluidizationReading{};  // a plateau needs two points
    plateau = sum / n;
    r.found = true;
    r.plateau = plateau;
    r.plateauError = std::sqrt(variance) / n;
    r.plateauPoints = n;
    r.fluidizationVelocity = uf;
  }
  return r;
}

}  // namespace grainbridge::mfm
