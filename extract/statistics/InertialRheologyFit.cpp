#include "extract/statistics/InertialRheologyFit.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/Dense>

#include "core/Error.hpp"
#include "core/LoadedRheology.hpp"
#include "extract/statistics/LeastSquares.hpp"

namespace grainbridge::extract::statistics {

namespace {

bool isPower(RheologyRelation r) { return r == RheologyRelation::MuOfIPower || r == RheologyRelation::PhiOfIPower; }
bool isMu(RheologyRelation r) { return r == RheologyRelation::MuOfI || r == RheologyRelation::MuOfIPower; }

// The model in its fitted parameters p and its derivatives: mu(I) in (mu_s, mu_2, log I_0),
// phi(I) in (phi_c, a), the power laws in (critical value, log amplitude, exponent) with the
// sign s = +1 for mu (rising with I) and -1 for phi (falling).
struct Model {
  RheologyRelation relation;

  [[nodiscard]] double sign() const { return isMu(relation) ? 1.0 : -1.0; }

  [[nodiscard]] double value(const Eigen::VectorXd& p, double I) const {
    if (isPower(relation)) return p[0] + sign() * std::exp(p[1]) * std::pow(I, p[2]);
    if (relation == RheologyRelation::PhiOfI) return p[0] - p[1] * I;
    const double s = I / (I + std::exp(p[2]));  // 1 / (1 + I_0 / I)
    return p[0] + (p[1] - p[0]) * s;
  }
  // d value / d p into row.
  void gradient(const Eigen::VectorXd& p, double I, Eigen::Ref<Eigen::RowVectorXd, 0, Eigen::InnerStride<>> row) const {
    if (isPower(relation)) {
      const double term = sign() * std::exp(p[1]) * std::pow(I, p[2]);
      row << 1.0, term, term * std::log(I);
      return;
    }
    if (relation == RheologyRelation::PhiOfI) {
      row << 1.0, -I;
      return;
    }
    const double I0 = std::exp(p[2]);
    const double s = I / (I + I0);
    row << 1.0 - s, s, -(p[1] - p[0]) * I * I0 / ((I + I0) * (I + I0));
  }
  // d value / d I, for the effective variance.
  [[nodiscard]] double slope(const Eigen::VectorXd& p, double I) const {
    if (isPower(relation)) return sign() * std::exp(p[1]) * p[2] * std::pow(I, p[2] - 1.0);
    if (relation == RheologyRelation::PhiOfI) return -p[1];
    const double I0 = std::exp(p[2]);
    return (p[1] - p[0]) * I0 / ((I + I0) * (I + I0));
  }
};

// A fitted exponent below this is a power law running away towards a logarithm (see
// bestExponentAtLowEdge), not a critical point.
constexpr double kLowestExponent = 0.02;

// The best power law on a grid of exponents, from `from` to 2 in steps of `step`: at each, the
// critical value and amplitude by weighted linear least squares (residuals over sigma); the
// exponent with the smallest chi^2 and a positive amplitude wins. NaN exponent when none has one.
struct ExponentScan {
  double exponent = std::numeric_limits<double>::quiet_NaN();
  double critical = 0.0, amplitude = 0.0;
};
ExponentScan scanExponents(RheologyRelation relation, std::span<const RheologySample> samples,
                           const Eigen::VectorXd& sigma, double from, double step) {
  const double sign = isMu(relation) ? 1.0 : -1.0;
  const auto m = static_cast<Eigen::Index>(samples.size());
  double best = std::numeric_limits<double>::infinity();
  ExponentScan out;
  for (double exponent = from; exponent <= 2.0 + 1e-9; exponent += step) {
    Eigen::MatrixXd A(m, 2);
    Eigen::VectorXd y(m);
    for (Eigen::Index i = 0; i < m; ++i) {
      const auto& s = samples[static_cast<std::size_t>(i)];
      A(i, 0) = 1.0 / sigma[i];
      A(i, 1) = sign * std::pow(s.inertialNumber, exponent) / sigma[i];
      y[i] = s.value / sigma[i];
    }
    const Eigen::VectorXd c = A.colPivHouseholderQr().solve(y);
    const double chi2 = (A * c - y).squaredNorm();
    if (c[1] > 0.0 && chi2 < best) {
      best = chi2;
      out = {exponent, c[0], c[1]};
    }
  }
  return out;
}

// A power law's start: the unweighted scan over exponents 0.1-2.
Eigen::VectorXd powerLawStart(RheologyRelation relation, std::span<const RheologySample> samples,
                              const std::string& what) {
  const ExponentScan scan =
      scanExponents(relation, samples, Eigen::VectorXd::Ones(static_cast<Eigen::Index>(samples.size())), 0.1, 0.02);
  if (std::isnan(scan.exponent)) {
    throw Error(what + ": no exponent in 0.1-2 gives a positive amplitude (the values do not " +
                (isMu(relation) ? "rise" : "fall") + " with I)");
  }
  return Eigen::Vector3d(scan.critical, std::log(scan.amplitude), scan.exponent);
}

// For the diagnosis of a power law that runs away: whether the weighted scan's smallest chi^2
// lies at the grid's low edge, where the exponent heads for 0 and the critical value and
// amplitude grow without bound together (the points bend like a logarithm of I).
bool bestExponentAtLowEdge(RheologyRelation relation, std::span<const RheologySample> samples,
                           const Eigen::VectorXd& sigma) {
  return !(scanExponents(relation, samples, sigma, kLowestExponent, 0.01).exponent >= kLowestExponent + 0.005);
}

std::string runawayPowerLaw(const std::string& what) {
  return what + ": the points determine no power law: its chi^2 keeps falling as the exponent goes to 0, with " +
         "the critical value and the amplitude growing without bound (the points bend like a logarithm of I); " +
         "fit a range nearer the critical point, or add points there";
}

}  // namespace

const char* relationName(RheologyRelation relation) { return isMu(relation) ? "mu_of_I" : "phi_of_I"; }

const char* formName(RheologyRelation relation) {
  switch (relation) {
    case RheologyRelation::MuOfI:
      return core::kMuOfIJopForm;
    case RheologyRelation::PhiOfI:
      return "phi_c - slope I";
    case RheologyRelation::MuOfIPower:
      return "mu_c + mu_amplitude I^mu_exponent";
    case RheologyRelation::PhiOfIPower:
      return "phi_c_power - phi_amplitude I^phi_exponent";
  }
  return "";
}

std::string fitKey(RheologyRelation relation) {
  return std::string(relationName(relation)) + (isPower(relation) ? "_power" : "");
}

double RheologyFit::operator()(double inertialNumber) const {
  if (isPower(relation)) {
    return params[0] + (isMu(relation) ? 1.0 : -1.0) * params[1] * std::pow(inertialNumber, params[2]);
  }
  if (relation == RheologyRelation::PhiOfI) return params[0] - params[1] * inertialNumber;
  return params[0] + (params[1] - params[0]) / (1.0 + params[2] / inertialNumber);
}

RheologyFit fitRheology(RheologyRelation relation, std::span<const RheologySample> samples) {
  const std::string what = "the " + fitKey(relation) + " fit";
  const Model model{relation};
  const Eigen::Index n = relation == RheologyRelation::PhiOfI ? 2 : 3;
  const auto m = static_cast<Eigen::Index>(samples.size());
  if (m <= n) {
    throw Error(what + ": " + std::to_string(m) + " points with an inertial number cannot constrain " +
                std::to_string(n) + " parameters (need at least " + std::to_string(n + 1) + ")");
  }
  double lowest = samples.front().value, highest = lowest, logSum = 0.0;
  for (const auto& s : samples) {
    if (!(s.inertialNumber > 0.0) || !std::isfinite(s.inertialNumber) || !std::isfinite(s.value)) {
      throw Error(what + ": a point has inertial number " + std::to_string(s.inertialNumber) + " and value " +
                  std::to_string(s.value) + " (needs I > 0 and a finite value)");
    }
    lowest = std::min(lowest, s.value);
    highest = std::max(highest, s.value);
    logSum += std::log(s.inertialNumber);
  }
  Eigen::VectorXd p(n);
  if (isPower(relation)) {
    p = powerLawStart(relation, samples, what);
  } else if (relation == RheologyRelation::MuOfI) {
    // mu rises from mu_s to mu_2 around I_0: start at the data's extremes and its typical I.
    const double pad = 0.1 * (highest - lowest) + 1e-3;
    p << lowest - pad, highest + pad, logSum / static_cast<double>(m);
  } else {
    p << highest, 0.0;
  }

  // sigma = 1 everywhere until the fitted parameters give every point an effective variance.
  Eigen::VectorXd sigma = Eigen::VectorXd::Ones(m);
  bool weighted = false;
  auto residuals = [&](const Eigen::VectorXd& q, Eigen::VectorXd& r, Eigen::MatrixXd* J) {
    for (Eigen::Index i = 0; i < m; ++i) {
      const auto& s = samples[static_cast<std::size_t>(i)];
      r[i] = (s.value - model.value(q, s.inertialNumber)) / sigma[i];
      if (J != nullptr) {
        model.gradient(q, s.inertialNumber, J->row(i));
        J->row(i) *= -1.0 / sigma[i];
      }
    }
  };
  // A power law whose fit fails or whose exponent heads for 0 is diagnosed, not reported.
  const auto fitOrDiagnose = [&](const Eigen::VectorXd& from) {
    try {
      LeastSquaresResult r = levenbergMarquardt(residuals, samples.size(), from, what);
      if (isPower(relation) && r.params[2] < kLowestExponent) throw Error(runawayPowerLaw(what));
      return r;
    } catch (const Error&) {
      if (isPower(relation) && bestExponentAtLowEdge(relation, samples, sigma)) throw Error(runawayPowerLaw(what));
      throw;
    }
  };
  LeastSquaresResult fit = fitOrDiagnose(p);
  for (int pass = 0; pass < 50; ++pass) {
    Eigen::VectorXd next(m);
    for (Eigen::Index i = 0; i < m; ++i) {
      const auto& s = samples[static_cast<std::size_t>(i)];
      const double fromI = model.slope(fit.params, s.inertialNumber) * s.inertialNumberErr;
      next[i] = std::sqrt(s.valueErr * s.valueErr + fromI * fromI);
    }
    if (!(next.minCoeff() > 0.0)) break;  // a point without any variance: the fit stays unweighted
    const bool settled = weighted && ((next - sigma).cwiseAbs().array() <= 1e-10 * next.array()).all();
    sigma = next;
    weighted = true;
    if (settled) break;
    fit = fitOrDiagnose(fit.params);
  }

  RheologyFit out;
  out.relation = relation;
  out.points = samples.size();
  out.dof = samples.size() - static_cast<std::size_t>(n);
  out.chi2 = fit.chi2;
  out.chi2PerDof = fit.chi2 / static_cast<double>(out.dof);
  out.weighted = weighted;
  const Eigen::MatrixXd inverse = fit.fisher.ldlt().solve(Eigen::MatrixXd::Identity(n, n));
  if (!inverse.allFinite()) throw Error(what + ": the parameters are not determined by these points");
  // From the fitted coordinates to the reported ones: I_0 = exp(log I_0).
  Eigen::MatrixXd D = Eigen::MatrixXd::Identity(n, n);
  out.params = fit.params;
  if (relation == RheologyRelation::MuOfI) {
    out.names = {"mu_s", "mu_2", "inertial_number_0"};
    out.params[2] = std::exp(fit.params[2]);
    D(2, 2) = out.params[2];
  } else if (isPower(relation)) {
    // The amplitude from its logarithm: A = exp(log A).
    out.names = isMu(relation) ? std::vector<std::string>{"mu_c", "mu_amplitude", "mu_exponent"}
                               : std::vector<std::string>{"phi_c_power", "phi_amplitude", "phi_exponent"};
    out.params[1] = std::exp(fit.params[1]);
    D(1, 1) = out.params[1];
  } else {
    out.names = {"phi_c", "slope"};
  }
  out.covariance = D * inverse * D * out.chi2PerDof;
  out.errors = out.covariance.diagonal().cwiseSqrt();
  return out;
}

}  // namespace grainbridge::extract::statistics
