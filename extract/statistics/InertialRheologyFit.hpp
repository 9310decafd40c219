#pragma once
// Fits of the dense-flow rheology to sheared closure points (Chialvo, Sun and Sundaresan 2012,
// PRE 85 021305; Jop, Forterre and Pouliquen 2006):
//   mu(I)  = mu_s + (mu_2 - mu_s) / (1 + I_0 / I)   (stress ratio tau / p against inertial number)
//   phi(I) = phi_c - a I                             (solid fraction against inertial number)
// and the power laws that hold near the critical point for frictionless beads (issue 61; Peyneau
// and Roux 2008 report mu - mu_c and phi_c - phi as powers of I):
//   mu(I)  = mu_c + B I^b        phi(I) = phi_c - A I^a
// fitted as (mu_c, log B, b) and (phi_c, log A, a), so the amplitudes stay positive; a start is
// found by scanning the exponent over 0.1-2 with the other two solved linearly.
//
// Estimator: weighted least squares (Levenberg-Marquardt, LeastSquares.hpp) with effective
// variances (Orear 1982): both coordinates of a point are measured, so each point's variance is
// sigma_y^2 + (f'(I) sigma_I)^2 at the current parameters, re-derived until the parameters
// settle. The errors of I and of mu share the pressure's error and are correlated; that
// correlation is neglected (it makes the stated errors slightly conservative for mu, whose
// numerator and denominator move together). A constant-volume point has no error in phi: its
// variance in the phi fit comes from I alone. When no point has a variance at all the fit is
// unweighted. Parameter errors: covariance (J^T W J)^{-1} scaled by the reduced chi^2, as
// ForcePdfFit does, so that errors estimated from short averaging windows do not set the
// stated precision on their own.
//
// I_0 is fitted as log I_0, so it stays positive; its error is I_0 times log I_0's.
#include <cstddef>
#include <span>
#include <string>
#include <vector>

#include <Eigen/Core>

namespace grainbridge::extract::statistics {

struct RheologySample {
  double inertialNumber = 0.0;
  double inertialNumberErr = 0.0;  // 1-sigma, 0 when unknown
  double value = 0.0;              // the stress ratio or the solid fraction
  double valueErr = 0.0;           // 1-sigma, 0 when unknown (a constant-volume solid fraction)
};

enum class RheologyRelation { MuOfI, PhiOfI, MuOfIPower, PhiOfIPower };

struct RheologyFit {
  RheologyRelation relation = RheologyRelation::MuOfI;
  // mu_s, mu_2, inertial_number_0 | phi_c, slope | mu_c, mu_amplitude, mu_exponent |
  // phi_c_power, phi_amplitude, phi_exponent
  std::vector<std::string> names;
  Eigen::VectorXd params;
  Eigen::VectorXd errors;          // 1-sigma, from the scaled covariance
  Eigen::MatrixXd covariance;      // in the order of names
  double chi2 = 0.0;               // with the effective variances (unit variances when unweighted)
  std::size_t dof = 0;
  double chi2PerDof = 0.0;
  std::size_t points = 0;
  bool weighted = true;            // false: no point had a variance

  // The fitted relation at inertial number I > 0.
  [[nodiscard]] double operator()(double inertialNumber) const;
};

// The name a database row and a report give the relation ("mu_of_I", "phi_of_I"; a power law is
// of the same relation, in another form).
const char* relationName(RheologyRelation relation);
// The form as the database writes it ("mu_s + (mu_2 - mu_s) / (1 + I_0 / I)", ...).
const char* formName(RheologyRelation relation);
// The summary's key of the fit: the relation's name, "_power" added for a power law.
std::string fitKey(RheologyRelation relation);

// Fits the relation to the samples (inertial numbers > 0, finite values). Throws
// grainbridge::Error naming the relation when there are too few samples (one more than its
// parameters: 4, the linear phi(I) 3) or the fit fails.
RheologyFit fitRheology(RheologyRelation relation, std::span<const RheologySample> samples);

}  // namespace grainbridge::extract::statistics
