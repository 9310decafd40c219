#pragma once
// Levenberg-Marquardt fits of Eq. 6.11 and Eq. 6.13 to a force histogram (f = F_n / <F_n>).
//
// Estimator: the model is integrated over each bin (4-point Gauss-Legendre), and the weights are
// re-derived from the fitted model's expected counts until the parameters settle (iteratively
// reweighted least squares with Pearson weights). Its fixed point is the binned Poisson maximum
// likelihood estimate, so sparse tail bins do not bias beta as weights from the observed counts
// would. Uncertainties: covariance (J^T W J)^{-1} scaled by the reduced chi^2.
//
// Eq. 6.13 degeneracy: a e^{-beta (f - gamma)} = (a e^{beta gamma}) e^{-beta f}, so a and gamma are
// one parameter. By default gamma is tied to alpha (gamma = alpha), the reading of the
// reference's reported alpha = gamma = 0.45 / 0.1 / 0 fits; gamma can instead be held at a
// given value. Fitting a and gamma together is refused with an error that says why.
#include <array>
#include <cstddef>
#include <limits>
#include <string>

#include <Eigen/Core>

#include "extract/statistics/DensityHistogram.hpp"
#include "extract/statistics/ForcePdfModel.hpp"

namespace grainbridge::extract::statistics {

enum class GammaRule {
  TiedToAlpha,  // gamma = alpha (default; Eq. 6.13 then has four identifiable parameters)
  Fixed,        // gamma held at start.gamma; a is then the amplitude for that gamma
  Free,         // only allowed with a held fixed, else a and gamma are degenerate
};

struct ForcePdfFitOptions {
  // Starting values. a <= 0 means "from the normalisation", beta <= 0 "from the tail slope".
  // Parameters held fixed keep these values.
  ForcePdfParams start{0.0, 0.5, 0.0, 0.0, 0.0};
  bool fitA = true, fitB = true, fitBeta = true;
  bool fitAlpha = true;                      // Eq. 6.13 only
  GammaRule gamma = GammaRule::TiedToAlpha;  // Eq. 6.13 only
  // Bins wholly inside [fitMin, fitMax] are fitted. fitMax = inf: up to the last bin holding at
  // least tailMinCounts samples (empty bins below it are kept: they carry information).
  double fitMin = 0.0;
  double fitMax = std::numeric_limits<double>::infinity();
  double tailMinCounts = 5.0;
  int maxReweights = 20;
};

struct ForcePdfFit {
  std::string equation;        // "6.11" or "6.13"
  std::string gammaRule;       // how gamma was treated (Eq. 6.13); "alpha = gamma = 0" for Eq. 6.11
  ForcePdfParams params;       // fitted (fixed ones as given; gamma = alpha when tied)
  ForcePdfParams error;        // 1-sigma, 0 for fixed parameters; gamma's error is alpha's when tied
  Eigen::MatrixXd covariance;  // 5 x 5 in the order a, b, beta, alpha, gamma (scaled by chi^2/dof)
  std::array<bool, ForcePdfParams::kCount> free{};
  double chi2 = 0.0;  // Pearson chi^2 with the model's Poisson variances
  std::size_t dof = 0;
  double chi2PerDof = 0.0;
  std::size_t binsUsed = 0;
  double fitMin = 0.0, fitMax = 0.0;  // range actually fitted
  std::size_t samples = 0;            // N of the histogram
  // Z = integral of the fitted P over [0, inf) (1 for a normalised density) and a / Z, the
  // amplitude of the fitted shape normalised to unit integral; both with propagated errors.
  double integral = 0.0, integralError = 0.0;
  double normalisedA = 0.0, normalisedAError = 0.0;
  int reweights = 0;  // iterations used
};

// Eq. 6.11: alpha = gamma = 0 (options.fitAlpha and options.gamma are ignored).
ForcePdfFit fitEq611(const DensityHistogram& histogram, const ForcePdfFitOptions& options = {});
// Eq. 6.13 with the gamma rule of the options.
ForcePdfFit fitEq613(const DensityHistogram& histogram, const ForcePdfFitOptions& options = {});

}  // namespace grainbridge::extract::statistics
