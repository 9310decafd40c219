#pragma once
// The stress ratio of dense sheared grains as a function of the inertial number (the mu(I)
// rheology of GDR MiDi 2004 and Jop et al. 2006, measured in DEM by Chialvo, Sun and Sundaresan
// 2012, Phys. Rev. E 85, 021305):
//
//   I = gamma_dot d / sqrt(p / rho_p),   mu = tau / p = mu(I),
//
// either as the fitted law mu(I) = mu_s + (mu_2 - mu_s) / (1 + I_0 / I) or as the measured
// points (I_k, mu_k), interpolated linearly in I between them and held at the end values outside
// (the slowest point stands for the quasi-static limit, the fastest for the collisional end: no
// extrapolation of a noisy slope). Both come from a tabulate stage's `rheology` rows
// (extract/statistics/InertialRheologyFit), made with the grains' diameter and density, which
// the rheology keeps so that I is formed with the grains it was measured for.
#include <string>
#include <vector>

namespace grainbridge::closures {

class InertialRheology {
 public:
  struct Grains {
    double diameter = 0.0;  // d [m]
    double density = 0.0;   // rho_p [kg/m^3]
  };
  struct Law {
    double staticRatio = 0.0;          // mu_s
    double limitRatio = 0.0;           // mu_2
    double inertialNumberScale = 0.0;  // I_0
  };

  // The fitted law. Throws grainbridge::Error unless d, rho_p > 0, 0 <= mu_s <= mu_2, I_0 > 0.
  static InertialRheology fitted(Grains grains, Law law);
  // The measured points, in increasing I. Throws grainbridge::Error unless there is at least one
  // point, I strictly increases from > 0, every mu is finite and >= 0, and d, rho_p > 0.
  static InertialRheology tabulated(Grains grains, std::vector<double> inertialNumbers,
                                    std::vector<double> stressRatios);

  [[nodiscard]] const Grains& grains() const { return grains_; }
  [[nodiscard]] bool isFitted() const { return points_.empty(); }
  // mu at inertial number I >= 0.
  [[nodiscard]] double stressRatio(double inertialNumber) const;
  // I = gamma_dot d / sqrt(p / rho_p) for shear rate gamma_dot >= 0 [1/s] and pressure p > 0 [Pa].
  [[nodiscard]] double inertialNumber(double shearRate, double pressure) const;
  // One line for logs: "mu_s 0.38 mu_2 0.64 I_0 0.28" or "12 points, I 0.01-0.3".
  [[nodiscard]] std::string describe() const;

 private:
  InertialRheology() = default;
  Grains grains_;
  Law law_;
  std::vector<double> points_, ratios_;
};

}  // namespace grainbridge::closures
