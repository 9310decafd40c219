#pragma once
// Weighted non-linear least squares by MINPACK's Levenberg-Marquardt (Eigen's unsupported
// NonLinearOptimization module, a port of lmder): the force PDF fits of Eqs. 6.11/6.13 and the
// exponential correlation-length fit share it. Residuals come in already divided by their
// standard deviations, so the returned J^T J is the Fisher matrix J^T W J.
#include <cstddef>
#include <functional>
#include <string>

#include <Eigen/Core>

namespace grainbridge::extract::statistics {

// Fills r (size m) with weighted residuals (data - model) / sigma at parameters p, and J (m x n)
// with dr/dp when J is not null.
using ResidualFunction = std::function<void(const Eigen::VectorXd& p, Eigen::VectorXd& r, Eigen::MatrixXd* J)>;

struct LeastSquaresResult {
  Eigen::VectorXd params;
  Eigen::MatrixXd fisher;  // J^T J of the weighted residuals at the solution
  double chi2 = 0.0;       // sum of squared weighted residuals
  int status = 0;          // Eigen::LevenbergMarquardtSpace::Status
  long evaluations = 0;
};

// Minimises |r(p)|^2 from p0. Throws grainbridge::Error naming `what` when there are fewer
// residuals than parameters, the residuals become non-finite, or MINPACK reports failure.
LeastSquaresResult levenbergMarquardt(const ResidualFunction& residuals, std::size_t m, const Eigen::VectorXd& p0,
                                      const std::string& what);

}  // namespace grainbridge::extract::statistics
