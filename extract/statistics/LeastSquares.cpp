#include "extract/statistics/LeastSquares.hpp"

#include <string>

#include "core/Error.hpp"
#include "extract/statistics/EigenLevenbergMarquardt.hpp"

namespace grainbridge::extract::statistics {

namespace {
// The functor shape MINPACK's port expects: values(), inputs(), operator() and df().
struct Functor {
  using Scalar = double;
  using InputType = Eigen::VectorXd;
  using ValueType = Eigen::VectorXd;
  using JacobianType = Eigen::MatrixXd;
  enum { InputsAtCompileTime = Eigen::Dynamic, ValuesAtCompileTime = Eigen::Dynamic };

  const ResidualFunction& f;
  Eigen::Index m, n;

  [[nodiscard]] Eigen::Index values() const { return m; }
  [[nodiscard]] Eigen::Index inputs() const { return n; }
  // MINPACK minimises |fvec|^2; a negative return aborts (UserAsked) on non-finite values.
  int operator()(const Eigen::VectorXd& x, Eigen::VectorXd& fvec) const {
    fvec.resize(m);
    f(x, fvec, nullptr);
    return fvec.allFinite() ? 0 : -1;
  }
  int df(const Eigen::VectorXd& x, Eigen::MatrixXd& fjac) const {
    Eigen::VectorXd r(m);
    fjac.resize(m, n);
    f(x, r, &fjac);
    // MINPACK's convention is the Jacobian of fvec; our r is (data - model)/sigma, consistent.
    return fjac.allFinite() ? 0 : -1;
  }
};
}  // namespace

LeastSquaresResult levenbergMarquardt(const ResidualFunction& residuals, std::size_t m, const Eigen::VectorXd& p0,
                                      const std::string& what) {
  const auto n = p0.size();
  if (static_cast<Eigen::Index>(m) <= n) {
    throw Error(what + ": " + std::to_string(m) + " data points cannot constrain " + std::to_string(n) +
                " parameters (need more points than parameters)");
  }
  Functor functor{residuals, static_cast<Eigen::Index>(m), n};
  Eigen::LevenbergMarquardt<Functor> lm(functor);
  lm.parameters.maxfev = 2000;
  lm.parameters.ftol = 1e-12;
  lm.parameters.xtol = 1e-12;
  Eigen::VectorXd p = p0;
  const auto status = lm.minimize(p);
  using namespace Eigen::LevenbergMarquardtSpace;
  if (status == ImproperInputParameters || status == UserAsked || status == TooManyFunctionEvaluation) {
    const char* why = status == UserAsked                   ? "residuals became non-finite"
                      : status == TooManyFunctionEvaluation ? "no convergence within 2000 evaluations"
                                                            : "improper input parameters";
    throw Error(what + ": Levenberg-Marquardt failed (" + why + "); check the data and the starting values");
  }
  LeastSquaresResult out;
  Eigen::VectorXd r(static_cast<Eigen::Index>(m));
  Eigen::MatrixXd J(static_cast<Eigen::Index>(m), n);
  residuals(p, r, &J);
  out.params = p;
  out.fisher = J.transpose() * J;
  out.chi2 = r.squaredNorm();
  out.status = static_cast<int>(status);
  out.evaluations = static_cast<long>(lm.nfev);
  return out;
}

}  // namespace grainbridge::extract::statistics
