#include "extract/statistics/ForcePdfModel.hpp"

#include <cmath>

#include "core/Error.hpp"

namespace grainbridge::extract::statistics {

const char* ForcePdfParams::name(std::size_t k) {
  static const char* names[kCount] = {"a", "b", "beta", "alpha", "gamma"};
  return k < kCount ? names[k] : "?";
}

double forcePdf(const ForcePdfParams& p, double f) {
  const double g = std::exp(-(f - p.alpha) * (f - p.alpha));
  return p.a * (1.0 - p.b * g) * std::exp(-p.beta * (f - p.gamma));
}

std::array<double, ForcePdfParams::kCount> forcePdfGradient(const ForcePdfParams& p, double f) {
  const double g = std::exp(-(f - p.alpha) * (f - p.alpha));
  const double e = std::exp(-p.beta * (f - p.gamma));
  const double value = p.a * (1.0 - p.b * g) * e;
  return {(1.0 - p.b * g) * e,                       // d/da
          -p.a * g * e,                              // d/db
          -(f - p.gamma) * value,                    // d/dbeta
          -2.0 * p.a * p.b * (f - p.alpha) * g * e,  // d/dalpha
          p.beta * value};                           // d/dgamma
}

double forcePdfIntegral(const ForcePdfParams& p) {
  if (!(p.beta > 0.0)) {
    throw Error("force PDF: beta = " + std::to_string(p.beta) +
                " is not positive, so P(f) is not integrable on [0, inf)");
  }
  // int_0^inf e^{-(f-alpha)^2 - beta f} df = e^{beta^2/4 - beta alpha} (sqrt(pi)/2) erfc(u), u = beta/2 - alpha.
  // For large u, e^{u^2} erfc(u) would be inf * 0; use its asymptotic series instead.
  const double u = 0.5 * p.beta - p.alpha;
  double gaussPart = 0.0;
  if (u < 25.0) {
    gaussPart = std::exp(0.25 * p.beta * p.beta - p.beta * p.alpha) * 0.5 * std::sqrt(M_PI) * std::erfc(u);
  } else {
    const double u2 = u * u;
    const double erfcx = (1.0 - 0.5 / u2 + 0.75 / (u2 * u2)) / (u * std::sqrt(M_PI));
    gaussPart = std::exp(-p.alpha * p.alpha) * 0.5 * std::sqrt(M_PI) * erfcx;
  }
  return p.a * std::exp(p.beta * p.gamma) * (1.0 / p.beta - p.b * gaussPart);
}

}  // namespace grainbridge::extract::statistics
