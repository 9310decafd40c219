#include "engines/closures/MinimumFluidization.hpp"

#include "core/Error.hpp"

namespace grainbridge::closures {

namespace {

// The bisection for one law: up to 200 evaluations, so the law is chosen once, outside it.
template <class Law>
double bisect(const Law& law, const PackedBed& bed) {
  const double epsG = bed.voidFraction, epsS = 1.0 - epsG;
  const double weight = epsS * epsG * epsG * (bed.solidsDensity - bed.gasDensity) * bed.gravity;
  auto excess = [&](double U) {
    const DragState s{epsG, epsS, bed.diameter, bed.gasDensity, bed.gasViscosity, U / epsG};
    return law.evaluate(s).beta * U - weight;
  };
  double lo = 0.0, hi = 1e3;
  if (excess(hi) < 0.0) throw Error("minimum fluidization: the drag law does not carry the bed below 1000 m/s");
  for (int i = 0; i < 200 && hi - lo > 1e-12 * hi; ++i) {
    const double mid = 0.5 * (lo + hi);
    (excess(mid) < 0.0 ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

}  // namespace

double minimumFluidizationVelocity(const GasSolidsDrag& drag, const PackedBed& bed) {
  return drag.visit([&bed](const auto& law) { return bisect(law, bed); });
}

}  // namespace grainbridge::closures
