#include "extract/statistics/InertialRheologyFit.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/Dense>

#include "core/Error.hpp"
#include "extract/statistics/LeastSquares.hpp"

namespace grainbridge::extract::statistics {

namespace {

// The model in its fitted parameters p and its derivatives: mu(I) in (mu_s, mu_2, log I_0),
// phi(I) in (phi_c, a).
struct Model {
  RheologyRelation relation;

  [[nodiscard]] double value(const Eigen::VectorXd& p, double I) const {
    if (relation == RheologyRelation::PhiOfI) return p[0] - p[1] * I;
    const double s = I / (I + std::exp(p[2]));  // 1 / (1 + I_0 / I)
    return p[0] + (p[1] - p[0]) * s;
  }
  // d value / d p into row.
  void gradient(const Eigen::VectorXd& p, double I, Eigen::Ref<Eigen::RowVectorXd, 0, Eigen::InnerStride<>> row) const {
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
    if (relation == RheologyRelation::PhiOfI) return -p[1];
    const double I0 = std::exp(p[2]);
    return (p[1] - p[0]) * I0 / ((I + I0) * (I + I0));
  }
};

}  // namespace

const char* relationName(RheologyRelation relation) {
  return relation == RheologyRelation::MuOfI ? "mu_of_I" : "phi_of_I";
}

double RheologyFit::operator()(double inertialNumber) const {
  if (relation == RheologyRelation::PhiOfI) return params[0] - params[1] * inertialNumber;
  return params[0] + (params[1] - params[0]) / (1.0 + params[2] / inertialNumber);
}

RheologyFit fitRheology(RheologyRelation relation, std::span<const RheologySample> samples) {
  const std::string what = std::string("the ") + relationName(relation) + " fit";
  const Model model{relation};
  const Eigen::Index n = relation == RheologyRelation::MuOfI ? 3 : 2;
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
  if (relation == RheologyRelation::MuOfI) {
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
  LeastSquaresResult fit = levenbergMarquardt(residuals, samples.size(), p, what);
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
    fit = levenbergMarquardt(residuals, samples.size(), fit.params, what);
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
  } else {
    out.names = {"phi_c", "slope"};
  }
  out.covariance = D * inverse * D * out.chi2PerDof;
  out.errors = out.covariance.diagonal().cwiseSqrt();
  return out;
}

}  // namespace grainbridge::extract::statistics
