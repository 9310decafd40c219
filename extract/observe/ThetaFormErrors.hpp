#pragma once
// The errors of a closure point's theta-scaled forms, and their correlations, from the frame
// series (issue 63). p_theta = p / (rho theta), eta_theta = mu / (rho d sqrt(theta)) and
// j_theta = J d / (rho theta^(3/2)) each divide a time-averaged quantity by a power of the
// time-averaged temperature. Adding the two relative errors in quadrature (core::closureFormError)
// treats them as independent; in a gas they are not: the kinetic pressure is rho phi theta frame
// by frame, so p and theta rise and fall together, and p_theta's error came out 1.5 times its
// spread over independent realisations (issue 63's seed sweep). Here a form's error is the
// block-averaging error (core/averaging/BlockAverage) of its linearised frame series, the delta
// method as RatioOfMeans uses it for tau / p:
//     d_k = f (x_k / <x> - q theta_k / <theta>),   f = c <x> / <theta>^q,
// whose mean is zero and whose standard error is f's to first order, covariances included.
// The same series give two forms' correlation: that of their block means at the longer of the two
// blocking levels (where blocks are about independent, so it is the correlation of the means).
// The forms share theta, and for sheared points eta_theta and j_theta share tau as well
// (J = tau gammadot): the closure draw of issue 31 uses it to draw a node's quantities jointly.
#include <nlohmann/json_fwd.hpp>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "core/ClosureForms.hpp"

namespace grainbridge::extract::observe {

// A theta-scaled form of a point and the frame series of the quantity it scales (p, mu or J).
struct ThetaFormSeries {
  core::ClosureForm form = core::ClosureForm::PTheta;
  std::span<const double> values;
};

struct ThetaFormError {
  std::string name;    // "p_theta"
  double value = 0.0;  // the form of the means
  double error = 0.0;  // of the linearised series
  bool plateauReached = true;
};

struct ThetaFormCorrelation {
  std::string first, second;  // names, in the order given
  double coefficient = 0.0;
};

struct ThetaFormErrors {
  std::vector<ThetaFormError> forms;
  std::vector<ThetaFormCorrelation> correlations;  // every pair, in the order given
};

// The temperature series must be as long as each form's and have a positive mean (the forms are
// taken at it, whatever state.granularTemperature says); a form whose quantity has a zero mean
// gets a zero error and no correlations, as does a pair with fewer than 3 blocks. Throws grainbridge::Error for
// series of different lengths.
[[nodiscard]] ThetaFormErrors thetaFormErrors(std::span<const ThetaFormSeries> forms,
                                              std::span<const double> temperature, const core::ClosureFormState& state);

// A closure point's theta forms' errors (<form>_err, replacing addStressForms' quadrature sums)
// and correlations (<a>_<b>_corr) from its frame series: p_theta from the pressure; under shear
// (state.shearRate > 0) eta_theta from tau / gammadot and j_theta from the shear work tau
// gammadot (the point's J in steady shear); without it j_theta from `dissipation` when given.
// Returns the forms whose blocking curve reached no plateau.
std::vector<std::string> addThetaFormErrors(nlohmann::json& row, const core::ClosureFormState& state,
                                            const std::vector<double>& temperature, const std::vector<double>& pressure,
                                            const std::vector<double>& shearStress,
                                            const std::vector<double>& dissipation);

// A point's error warning (column error_warning) when the blocking curves of `quantities`
// reached no plateau in `frames` frames: their errors are lower bounds. None for none.
[[nodiscard]] std::optional<std::string> errorWarning(std::size_t frames, const std::vector<std::string>& quantities);

// The column of a correlation coefficient: "p_theta_eta_theta_corr".
[[nodiscard]] std::string correlationColumn(const std::string& first, const std::string& second);

}  // namespace grainbridge::extract::observe
