#include "core/grid/SmoothingKernel.hpp"

#include <cmath>
#include <string>

#include "core/Error.hpp"

namespace grainbridge::core::grid {

namespace {
void checkWidth(double width, std::string_view kernel) {
  if (!(width > 0.0) || !std::isfinite(width)) {
    throw Error("smoothing kernel: " + std::string(kernel) + " width " + std::to_string(width) +
                " must be positive and finite");
  }
}
}  // namespace

GaussianKernel::GaussianKernel(double width) : width_(width), amplitude_(0.0) {
  checkWidth(width, name);
  // Integral of exp(-r^2/2w^2) over the ball r < c = 3w:
  //   (2 pi w^2)^(3/2) [erf(c / (sqrt2 w)) - sqrt(2/pi) (c/w) exp(-c^2 / (2 w^2))].
  const double cw = 3.0;
  const double inside = std::erf(cw / std::sqrt(2.0)) - std::sqrt(2.0 / M_PI) * cw * std::exp(-0.5 * cw * cw);
  amplitude_ = 1.0 / (std::pow(2.0 * M_PI * width * width, 1.5) * inside);
}

double GaussianKernel::operator()(double r) const {
  if (r >= cutoff()) return 0.0;
  return amplitude_ * std::exp(-0.5 * r * r / (width_ * width_));
}

double GaussianKernel::lineIntegral(double b, double t0, double t1) const {
  // A exp(-b^2/2w^2) integral exp(-t^2/2w^2) dt = A exp(-b^2/2w^2) sqrt(pi/2) w [erf]_t0^t1;
  // erfc on one side of 0 keeps the difference accurate when both ends are far out.
  const double k = 1.0 / (std::sqrt(2.0) * width_);
  double span = 0.0;
  if (t0 >= 0.0) {
    span = std::erfc(k * t0) - std::erfc(k * t1);
  } else if (t1 <= 0.0) {
    span = std::erfc(-k * t1) - std::erfc(-k * t0);
  } else {
    span = std::erf(k * t1) - std::erf(k * t0);
  }
  return amplitude_ * std::exp(-0.5 * b * b / (width_ * width_)) * std::sqrt(M_PI / 2.0) * width_ * span;
}

LucyKernel::LucyKernel(double width) : width_(width), cutoff_(2.0 * std::sqrt(3.0) * width), amplitude_(0.0) {
  checkWidth(width, name);
  amplitude_ = 105.0 / (16.0 * M_PI * cutoff_ * cutoff_ * cutoff_);
}

double LucyKernel::operator()(double r) const {
  const double s = r / cutoff_;
  if (s >= 1.0) return 0.0;
  const double t = 1.0 - s;
  return amplitude_ * (1.0 + 3.0 * s) * t * t * t;
}

double LucyKernel::lineIntegral(double b, double t0, double t1) const {
  // phi = A (1 - 6 rho^2 + 8 rho^3 - 3 rho^4), rho^2 = (b^2 + t^2) / c^2: polynomial in t
  // except rho^3, whose integral is
  //   J3 = t (2 t^2 + 5 b^2) sqrt(t^2 + b^2) / 8 + 3 b^4 / 8 asinh(t / b).
  const double c = cutoff_;
  const double b2 = b * b;
  const auto primitive = [&](double t) {
    const double t2 = t * t;
    const double j3 = t * (2.0 * t2 + 5.0 * b2) * std::sqrt(t2 + b2) / 8.0 +
                      (b > 0.0 ? 3.0 * b2 * b2 / 8.0 * std::asinh(t / b) : 0.0);
    const double j2 = b2 * t + t2 * t / 3.0;
    const double j4 = b2 * b2 * t + 2.0 * b2 * t2 * t / 3.0 + t2 * t2 * t / 5.0;
    return t - 6.0 * j2 / (c * c) + 8.0 * j3 / (c * c * c) - 3.0 * j4 / (c * c * c * c);
  };
  return amplitude_ * (primitive(t1) - primitive(t0));
}

}  // namespace grainbridge::core::grid
