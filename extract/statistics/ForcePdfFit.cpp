#include "extract/statistics/ForcePdfFit.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include <Eigen/LU>

#include "core/Error.hpp"
#include "extract/statistics/LeastSquares.hpp"

namespace grainbridge::extract::statistics {

namespace {
constexpr std::size_t kP = ForcePdfParams::kCount;
enum : std::size_t { kA = 0, kB = 1, kBeta = 2, kAlpha = 3, kGamma = 4 };

// 4-point Gauss-Legendre on [-1, 1]: exact for polynomials of degree 7, so bin averages of the
// smooth P(f) are exact to far below the statistical error even for wide logarithmic bins.
constexpr std::array<double, 4> kNodes = {-0.8611363115940526, -0.3399810435848563, 0.3399810435848563,
                                          0.8611363115940526};
constexpr std::array<double, 4> kWeights = {0.3478548451374538, 0.6521451548625461, 0.6521451548625461,
                                            0.3478548451374538};

// Which model parameters the LM vector holds, and how gamma follows alpha.
struct Layout {
  std::array<bool, kP> free{};
  bool tie = false;  // gamma = alpha
  ForcePdfParams fixed;
  std::vector<std::size_t> index;  // LM slot -> model parameter

  [[nodiscard]] ForcePdfParams expand(const Eigen::VectorXd& x) const {
    auto v = fixed.toArray();
    for (std::size_t s = 0; s < index.size(); ++s) v[index[s]] = x[static_cast<Eigen::Index>(s)];
    if (tie) v[kGamma] = v[kAlpha];
    return ForcePdfParams::fromArray(v);
  }
  // d(model parameters)/d(LM vector): 5 x n.
  [[nodiscard]] Eigen::MatrixXd jacobian() const {
    Eigen::MatrixXd T = Eigen::MatrixXd::Zero(kP, static_cast<Eigen::Index>(index.size()));
    for (std::size_t s = 0; s < index.size(); ++s) {
      T(static_cast<Eigen::Index>(index[s]), static_cast<Eigen::Index>(s)) = 1.0;
      if (tie && index[s] == kAlpha) T(kGamma, static_cast<Eigen::Index>(s)) = 1.0;
    }
    return T;
  }
};

// Bin average of P and of its gradient over [lo, hi].
void binAverage(const ForcePdfParams& p, double lo, double hi, double& value, std::array<double, kP>& grad) {
  value = 0.0;
  grad.fill(0.0);
  const double half = 0.5 * (hi - lo), mid = 0.5 * (hi + lo);
  for (std::size_t q = 0; q < kNodes.size(); ++q) {
    const double f = mid + half * kNodes[q];
    const double w = 0.5 * kWeights[q];  // weights sum to 2 on [-1, 1]; average needs 1/2
    value += w * forcePdf(p, f);
    const auto g = forcePdfGradient(p, f);
    for (std::size_t k = 0; k < kP; ++k) grad[k] += w * g[k];
  }
}

// Starting beta from the exponential tail: least squares of ln(density) on f over bins above
// the median bin with at least 5 counts. Falls back to 1.5 (Mueth et al.) when too few.
double tailSlopeGuess(const DensityHistogram& h, std::size_t first, std::size_t last) {
  double sw = 0, sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (std::size_t k = first + (last - first) / 3; k <= last; ++k) {
    if (h.counts[k] < 5.0 || h.centre[k] < 1.0) continue;
    const double w = h.counts[k];  // var(ln n) ~ 1/n
    const double x = h.centre[k], y = std::log(h.density[k]);
    sw += w;
    sx += w * x;
    sy += w * y;
    sxx += w * x * x;
    sxy += w * x * y;
  }
  const double det = sw * sxx - sx * sx;
  if (sw <= 0.0 || det <= 0.0) return 1.5;
  const double slope = (sw * sxy - sx * sy) / det;
  return slope < -0.05 ? -slope : 1.5;
}

// Central-difference gradient of a scalar function of the model parameters.
template <class F>
Eigen::VectorXd numericGradient(const ForcePdfParams& p, F&& fn) {
  Eigen::VectorXd g(kP);
  const auto v = p.toArray();
  for (std::size_t k = 0; k < kP; ++k) {
    const double h = 1e-6 * std::max(1.0, std::abs(v[k]));
    auto up = v, dn = v;
    up[k] += h;
    dn[k] -= h;
    g[static_cast<Eigen::Index>(k)] = (fn(ForcePdfParams::fromArray(up)) - fn(ForcePdfParams::fromArray(dn))) / (2 * h);
  }
  return g;
}

ForcePdfFit fit(const DensityHistogram& h, const ForcePdfFitOptions& o, bool eq613) {
  const std::string what = eq613 ? "force PDF fit (Eq. 6.13)" : "force PDF fit (Eq. 6.11)";
  if (h.bins() == 0 || h.samples == 0) throw Error(what + ": empty histogram");
  Layout L;
  L.fixed = o.start;
  L.free = {o.fitA, o.fitB, o.fitBeta, false, false};
  std::string gammaRule = "alpha = gamma = 0";
  if (eq613) {
    L.free[kAlpha] = o.fitAlpha;
    switch (o.gamma) {
      case GammaRule::TiedToAlpha:
        L.tie = true;
        gammaRule = "gamma = alpha (tied)";
        break;
      case GammaRule::Fixed:
        gammaRule = "gamma fixed at " + std::to_string(o.start.gamma);
        break;
      case GammaRule::Free:
        if (o.fitA) {
          throw Error(what +
                      ": a and gamma cannot both be free, since a e^{-beta (f - gamma)} depends on them only "
                      "through a e^{beta gamma}; tie gamma to alpha, fix gamma, or fix a");
        }
        L.free[kGamma] = true;
        gammaRule = "gamma free (a fixed)";
        break;
    }
  } else {
    L.fixed.alpha = L.fixed.gamma = 0.0;
  }
  if (L.tie) L.fixed.gamma = L.fixed.alpha;
  for (std::size_t k = 0; k < kP; ++k) {
    if (L.free[k]) L.index.push_back(k);
  }
  if (L.index.empty()) throw Error(what + ": no free parameters");

  // Bins to fit.
  std::size_t first = h.bins(), last = 0;
  double tailEdge = -std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k < h.bins(); ++k) {
    if (h.counts[k] >= o.tailMinCounts) tailEdge = h.edges[k + 1];
  }
  if (!std::isfinite(o.fitMax) && !std::isfinite(tailEdge)) {
    throw Error(what + ": no histogram bin holds " + std::to_string(o.tailMinCounts) + " or more of the " +
                std::to_string(h.samples) + " samples; too few forces for a fit (or bins too narrow)");
  }
  const double hiLimit = std::isfinite(o.fitMax) ? o.fitMax : tailEdge;
  for (std::size_t k = 0; k < h.bins(); ++k) {
    if (h.edges[k] >= o.fitMin - 1e-12 && h.edges[k + 1] <= hiLimit + 1e-12) {
      first = std::min(first, k);
      last = k;
    }
  }
  if (first > last || first == h.bins()) {
    throw Error(what + ": no histogram bin lies inside the fit range [" + std::to_string(o.fitMin) + ", " +
                std::to_string(hiLimit) + "]");
  }
  const std::size_t m = last - first + 1;
  const auto n = static_cast<double>(h.samples);

  // Starting values.
  if (!(L.fixed.beta > 0.0)) L.fixed.beta = tailSlopeGuess(h, first, last);
  if (!(L.fixed.a > 0.0)) {
    auto unit = L.fixed;
    unit.a = 1.0;
    const double z = forcePdfIntegral(unit);
    if (!(z > 0.0)) throw Error(what + ": the starting b and beta give a non-positive integral; choose start values");
    L.fixed.a = 1.0 / z;
  }
  Eigen::VectorXd x(static_cast<Eigen::Index>(L.index.size()));
  {
    const auto v = L.fixed.toArray();
    for (std::size_t s = 0; s < L.index.size(); ++s) x[static_cast<Eigen::Index>(s)] = v[L.index[s]];
  }

  // Variances of the bin densities: Poisson, from the observed counts on the first pass and from
  // the model's expected counts after that (IRLS towards the Poisson likelihood).
  Eigen::VectorXd sigma(static_cast<Eigen::Index>(m));
  for (std::size_t k = 0; k < m; ++k) {
    const std::size_t b = first + k;
    sigma[static_cast<Eigen::Index>(k)] = std::sqrt(std::max(h.counts[b], 1.0)) / (n * h.width(b));
  }
  auto residuals = [&](const Eigen::VectorXd& xv, Eigen::VectorXd& r, Eigen::MatrixXd* J) {
    const ForcePdfParams p = L.expand(xv);
    const Eigen::MatrixXd T = J ? L.jacobian() : Eigen::MatrixXd();
    for (std::size_t k = 0; k < m; ++k) {
      const std::size_t b = first + k;
      double value = 0.0;
      std::array<double, kP> grad{};
      binAverage(p, h.edges[b], h.edges[b + 1], value, grad);
      const auto row = static_cast<Eigen::Index>(k);
      r[row] = (h.density[b] - value) / sigma[row];
      if (J) {
        Eigen::Map<const Eigen::Matrix<double, 1, static_cast<int>(kP)>> g(grad.data());
        J->row(row) = -(g * T) / sigma[row];
      }
    }
  };
  auto modelSigma = [&](const Eigen::VectorXd& xv) {
    const ForcePdfParams p = L.expand(xv);
    for (std::size_t k = 0; k < m; ++k) {
      const std::size_t b = first + k;
      double value = 0.0;
      std::array<double, kP> grad{};
      binAverage(p, h.edges[b], h.edges[b + 1], value, grad);
      // A floor of 1e-3 expected counts keeps a bin the model empties from getting infinite weight.
      const double mu = std::max(value * n * h.width(b), 1e-3);
      sigma[static_cast<Eigen::Index>(k)] = std::sqrt(mu) / (n * h.width(b));
    }
  };

  LeastSquaresResult r;
  int iterations = 0;
  for (int it = 0; it < std::max(1, o.maxReweights); ++it) {
    r = levenbergMarquardt(residuals, m, x, what);
    const double change = (r.params - x).cwiseAbs().maxCoeff() / std::max(1.0, x.cwiseAbs().maxCoeff());
    x = r.params;
    modelSigma(x);
    iterations = it + 1;
    if (it > 0 && change < 1e-9) break;
  }
  // Final chi^2 and Fisher matrix with the converged model's variances.
  {
    Eigen::VectorXd res(static_cast<Eigen::Index>(m));
    Eigen::MatrixXd J(static_cast<Eigen::Index>(m), x.size());
    residuals(x, res, &J);
    r.chi2 = res.squaredNorm();
    r.fisher = J.transpose() * J;
  }

  ForcePdfFit out;
  out.equation = eq613 ? "6.13" : "6.11";
  out.gammaRule = gammaRule;
  out.params = L.expand(x);
  out.free = L.free;
  out.binsUsed = m;
  out.fitMin = h.edges[first];
  out.fitMax = h.edges[last + 1];
  out.samples = h.samples;
  out.reweights = iterations;
  out.dof = m - L.index.size();
  out.chi2 = r.chi2;
  out.chi2PerDof = out.dof > 0 ? r.chi2 / static_cast<double>(out.dof) : std::numeric_limits<double>::quiet_NaN();

  Eigen::FullPivLU<Eigen::MatrixXd> lu(r.fisher);
  if (!lu.isInvertible()) {
    throw Error(what +
                ": the fitted parameters are not all constrained by the data (singular J^T W J); fix some of "
                "them or widen the fit range");
  }
  const double scale = out.dof > 0 ? std::max(out.chi2PerDof, 0.0) : 1.0;
  const Eigen::MatrixXd covX = lu.inverse() * scale;
  const Eigen::MatrixXd T = L.jacobian();
  out.covariance = T * covX * T.transpose();
  std::array<double, kP> err{};
  for (std::size_t k = 0; k < kP; ++k) {
    err[k] = std::sqrt(std::max(0.0, out.covariance(static_cast<Eigen::Index>(k), static_cast<Eigen::Index>(k))));
  }
  out.error = ForcePdfParams::fromArray(err);

  out.integral = forcePdfIntegral(out.params);
  const Eigen::VectorXd gz = numericGradient(out.params, [](const ForcePdfParams& p) { return forcePdfIntegral(p); });
  out.integralError = std::sqrt(std::max(0.0, gz.dot(out.covariance * gz)));
  out.normalisedA = out.params.a / out.integral;
  const Eigen::VectorXd ga =
      numericGradient(out.params, [](const ForcePdfParams& p) { return p.a / forcePdfIntegral(p); });
  out.normalisedAError = std::sqrt(std::max(0.0, ga.dot(out.covariance * ga)));
  return out;
}
}  // namespace

ForcePdfFit fitEq611(const DensityHistogram& histogram, const ForcePdfFitOptions& options) {
  return fit(histogram, options, false);
}

ForcePdfFit fitEq613(const DensityHistogram& histogram, const ForcePdfFitOptions& options) {
  return fit(histogram, options, true);
}

}  // namespace grainbridge::extract::statistics
