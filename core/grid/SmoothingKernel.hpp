#pragma once
// Smooth coarse-graining kernels phi(r) of width w, normalised so that their integral over
// space is 1 (Section 8.2.1.3 of the reference: "a coarse-graining function with width w").
// Both take w as a per-axis standard deviation, so the same w smooths by about the same amount
// whichever kernel is chosen:
//  - Gaussian: phi = A exp(-r^2 / (2 w^2)) for r < 3w, 0 beyond; w is the standard deviation
//    of the untruncated Gaussian, and A renormalises the truncated one to unit integral (the
//    cut drops 2.9 % of the weight; the truncated per-axis variance is 0.918 w^2).
//  - Lucy: phi = 105 / (16 pi c^3) (1 + 3 s)(1 - s)^3, s = r / c < 1, with cutoff c = 2 sqrt(3) w
//    = 3.46 w, so that its per-axis variance c^2 / 12 is exactly w^2; compact, C^2 at the cutoff.
// Each also integrates itself exactly along a straight line (the contact part of Eq. 2.3 is
// spread along the contact line), so no quadrature error enters the contact stress.
// Values are small value types: the deposition loop is a template over them (STYLE.md 3).
#include <string_view>
#include <variant>

namespace grainbridge::core::grid {

class GaussianKernel {
 public:
  static constexpr std::string_view name = "gaussian";
  // Throws grainbridge::Error naming the width when it is not positive and finite.
  explicit GaussianKernel(double width);
  [[nodiscard]] double width() const { return width_; }
  [[nodiscard]] double cutoff() const { return 3.0 * width_; }
  [[nodiscard]] double operator()(double r) const;
  // integral over t in [t0, t1] of phi(sqrt(b^2 + t^2)) dt, for |t0|, |t1| inside the support
  // (b: distance from the line; t: length along it).
  [[nodiscard]] double lineIntegral(double b, double t0, double t1) const;

 private:
  double width_;
  double amplitude_;
};

class LucyKernel {
 public:
  static constexpr std::string_view name = "lucy";
  explicit LucyKernel(double width);
  [[nodiscard]] double width() const { return width_; }
  [[nodiscard]] double cutoff() const { return cutoff_; }
  [[nodiscard]] double operator()(double r) const;
  [[nodiscard]] double lineIntegral(double b, double t0, double t1) const;

 private:
  double width_;
  double cutoff_;
  double amplitude_;
};

using SmoothingKernel = std::variant<GaussianKernel, LucyKernel>;

}  // namespace grainbridge::core::grid
