#include "engines/dem/Material.hpp"

#include <cmath>
#include <limits>

namespace grainbridge::dem {

double linearContactTime(double kn, double gammaN, double meff) {
  const double w2 = kn / meff - 0.25 * gammaN * gammaN;
  if (w2 <= 0.0) return std::numeric_limits<double>::infinity();
  return M_PI / std::sqrt(w2);
}

double linearRestitution(double kn, double gammaN, double meff) {
  const double tc = linearContactTime(kn, gammaN, meff);
  return std::isfinite(tc) ? std::exp(-0.5 * gammaN * tc) : 0.0;
}

double gammaForRestitution(double e, double kn, double meff) {
  // With beta = -ln(e)/pi, Eqs. 6.9-6.10 give gamma_n = 2 beta sqrt(k_n/m_eff) / sqrt(1 + beta^2).
  const double beta = -std::log(e) / M_PI;
  return 2.0 * beta * std::sqrt(kn / meff) / std::sqrt(1.0 + beta * beta);
}

}  // namespace grainbridge::dem
