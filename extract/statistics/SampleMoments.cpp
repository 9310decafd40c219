#include "extract/statistics/SampleMoments.hpp"

#include <cmath>

#include "core/Error.hpp"

namespace grainbridge::extract::statistics {

SampleMoments sampleMoments(std::span<const double> x, const std::string& what) {
  if (x.size() < 2) throw Error(what + ": need at least 2 samples, got " + std::to_string(x.size()));
  const auto n = static_cast<double>(x.size());
  double mean = 0.0;
  for (double v : x) {
    if (!std::isfinite(v)) throw Error(what + ": a sample is not finite");
    mean += v;
  }
  mean /= n;
  double m2 = 0.0, m3 = 0.0, m4 = 0.0;
  for (double v : x) {
    const double c = v - mean, c2 = c * c;
    m2 += c2;
    m3 += c2 * c;
    m4 += c2 * c2;
  }
  m2 /= n;
  m3 /= n;
  m4 /= n;
  if (!(m2 > 0.0)) throw Error(what + ": all samples are equal, so variance-normalised moments are undefined");
  SampleMoments out;
  out.samples = x.size();
  out.mean = mean;
  out.variance = m2;
  out.skewness = m3 / std::pow(m2, 1.5);
  out.kurtosis = m4 / (m2 * m2);
  // Influence functions (first-order expansion about the true moments, with the mean estimated):
  //   psi2 = c^2 - m2,  psi3 = c^3 - m3 - 3 m2 c,  psi4 = c^4 - m4 - 4 m3 c,
  //   psi_skew = psi3 / m2^{3/2} - 3/2 m3 psi2 / m2^{5/2},  psi_kurt = psi4 / m2^2 - 2 m4 psi2 / m2^3.
  double s2 = 0.0, sSkew = 0.0, sKurt = 0.0;
  for (double v : x) {
    const double c = v - mean, c2 = c * c;
    const double psi2 = c2 - m2;
    const double psi3 = c2 * c - m3 - 3.0 * m2 * c;
    const double psi4 = c2 * c2 - m4 - 4.0 * m3 * c;
    const double pSkew = psi3 / std::pow(m2, 1.5) - 1.5 * m3 * psi2 / std::pow(m2, 2.5);
    const double pKurt = psi4 / (m2 * m2) - 2.0 * m4 * psi2 / (m2 * m2 * m2);
    s2 += psi2 * psi2;
    sSkew += pSkew * pSkew;
    sKurt += pKurt * pKurt;
  }
  out.varianceError = std::sqrt(s2) / n;
  out.skewnessError = std::sqrt(sSkew) / n;
  out.kurtosisError = std::sqrt(sKurt) / n;
  return out;
}

}  // namespace grainbridge::extract::statistics
