#include "core/ClosureTable.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/Error.hpp"

namespace grainbridge::core {

namespace {

void requireIncreasing(const std::string& quantity, const char* axis, const std::vector<double>& v) {
  if (v.empty()) throw Error("closure table " + quantity + ": the " + axis + " axis is empty");
  for (std::size_t i = 0; i < v.size(); ++i) {
    if (!std::isfinite(v[i])) {
      throw Error("closure table " + quantity + ": " + axis + " value " + std::to_string(i) + " is not finite");
    }
    if (i > 0 && !(v[i] > v[i - 1])) {
      std::ostringstream msg;
      msg << "closure table " << quantity << ": the " << axis << " axis must be strictly increasing, but entry " << i
          << " (" << v[i] << ") follows " << v[i - 1];
      throw Error(msg.str());
    }
  }
}

// Fritsch-Carlson slopes as MATLAB's pchip sets them: zero at a local extremum, else a
// weighted harmonic mean of the neighbouring secants (Fritsch & Butland 1984), and one-sided
// three-point end slopes limited so the end interval stays monotone.
std::vector<double> pchipSlopes(const std::vector<double>& x, const double* y) {
  const std::size_t n = x.size();
  std::vector<double> d(n, 0.0);
  if (n < 2) return d;
  std::vector<double> h(n - 1), delta(n - 1);
  for (std::size_t k = 0; k + 1 < n; ++k) {
    h[k] = x[k + 1] - x[k];
    delta[k] = (y[k + 1] - y[k]) / h[k];
  }
  if (n == 2) {
    d[0] = d[1] = delta[0];
    return d;
  }
  for (std::size_t k = 1; k + 1 < n; ++k) {
    if (delta[k - 1] * delta[k] <= 0.0) continue;
    const double w1 = 2.0 * h[k] + h[k - 1];
    const double w2 = h[k] + 2.0 * h[k - 1];
    d[k] = (w1 + w2) / (w1 / delta[k - 1] + w2 / delta[k]);
  }
  auto endSlope = [](double h0, double h1, double d0, double d1) {
    double s = ((2.0 * h0 + h1) * d0 - h0 * d1) / (h0 + h1);
    if (s * d0 <= 0.0) return 0.0;
    if (d0 * d1 < 0.0 && std::abs(s) > 3.0 * std::abs(d0)) return 3.0 * d0;
    return s;
  };
  d[0] = endSlope(h[0], h[1], delta[0], delta[1]);
  d[n - 1] = endSlope(h[n - 2], h[n - 3], delta[n - 2], delta[n - 3]);
  return d;
}

}  // namespace

ClosureTable::ClosureTable(std::string quantity, std::vector<double> solidFraction, std::vector<double> values)
    : ClosureTable(std::move(quantity), std::move(solidFraction), "", {}, std::move(values)) {}

ClosureTable::ClosureTable(std::string quantity, std::vector<double> solidFraction, std::string secondVariable,
                           std::vector<double> second, std::vector<double> values)
    : ClosureTable(std::move(quantity), std::move(solidFraction), std::move(secondVariable), std::move(second), "", {},
                   std::move(values)) {}

ClosureTable::ClosureTable(std::string quantity, std::vector<double> solidFraction, std::string secondVariable,
                           std::vector<double> second, std::string thirdVariable, std::vector<double> third,
                           std::vector<double> values)
    : quantity_(std::move(quantity)),
      solidFraction_(std::move(solidFraction)),
      secondVariable_(std::move(secondVariable)),
      second_(std::move(second)),
      thirdVariable_(std::move(thirdVariable)),
      third_(std::move(third)),
      values_(std::move(values)) {
  requireIncreasing(quantity_, "solid fraction", solidFraction_);
  if (!second_.empty()) requireIncreasing(quantity_, secondVariable_.c_str(), second_);
  if (!third_.empty()) {
    if (second_.empty()) throw Error("closure table " + quantity_ + ": a third axis needs a second one");
    requireIncreasing(quantity_, thirdVariable_.c_str(), third_);
  }
  const std::size_t rows = std::max<std::size_t>(1, second_.size()) * std::max<std::size_t>(1, third_.size());
  if (values_.size() != rows * solidFraction_.size()) {
    throw Error("closure table " + quantity_ + ": " + std::to_string(values_.size()) + " values for a " +
                std::to_string(solidFraction_.size()) + " x " + std::to_string(std::max<std::size_t>(1, second_.size())) +
                (third_.empty() ? "" : " x " + std::to_string(third_.size())) + " grid");
  }
  for (std::size_t i = 0; i < values_.size(); ++i) {
    if (!std::isfinite(values_[i])) {
      throw Error("closure table " + quantity_ + ": value " + std::to_string(i) + " is not finite");
    }
  }
  slopes_.reserve(values_.size());
  for (std::size_t r = 0; r < rows; ++r) {
    const auto d = pchipSlopes(solidFraction_, values_.data() + r * solidFraction_.size());
    slopes_.insert(slopes_.end(), d.begin(), d.end());
  }
}

double ClosureTable::alongSolidFraction(std::size_t row, double x) const {
  const std::size_t n = solidFraction_.size();
  const double* y = values_.data() + row * n;
  const double* d = slopes_.data() + row * n;
  if (n == 1) return y[0];
  // Interval k with x_k <= x <= x_{k+1} (x already clamped to the axis).
  const auto upper = std::upper_bound(solidFraction_.begin(), solidFraction_.end(), x);
  const std::size_t k = std::min<std::size_t>(
      n - 2, static_cast<std::size_t>(std::max<std::ptrdiff_t>(0, upper - solidFraction_.begin() - 1)));
  const double h = solidFraction_[k + 1] - solidFraction_[k];
  const double t = (x - solidFraction_[k]) / h;
  const double t2 = t * t;
  const double t3 = t2 * t;
  // Cubic Hermite basis on [x_k, x_k+1].
  return (2 * t3 - 3 * t2 + 1) * y[k] + (t3 - 2 * t2 + t) * h * d[k] + (-2 * t3 + 3 * t2) * y[k + 1] +
         (t3 - t2) * h * d[k + 1];
}

namespace {

// Where y falls on a coarse axis (already clamped to it): the node below and the weight of the
// one above (0 on a one-node axis).
std::pair<std::size_t, double> bracket(const std::vector<double>& axis, double y) {
  if (axis.size() < 2) return {0, 0.0};
  const auto upper = std::upper_bound(axis.begin(), axis.end(), y);
  const std::size_t r = std::min<std::size_t>(
      axis.size() - 2, static_cast<std::size_t>(std::max<std::ptrdiff_t>(0, upper - axis.begin() - 1)));
  return {r, (y - axis[r]) / (axis[r + 1] - axis[r])};
}

}  // namespace

ClosureLookup ClosureTable::operator()(double solidFraction, double second, double third) const {
  ClosureLookup out;
  const double x = std::clamp(solidFraction, solidFraction_.front(), solidFraction_.back());
  out.inRange = x == solidFraction;
  if (second_.empty()) {
    out.value = alongSolidFraction(0, x);
    return out;
  }
  const double y = std::clamp(second, second_.front(), second_.back());
  out.inRange = out.inRange && y == second;
  const auto [r, s] = bracket(second_, y);
  const std::size_t ny = second_.size();
  // Linear in the second variable within one plane of the third (iz).
  auto plane = [&](std::size_t iz) {
    const double low = alongSolidFraction(iz * ny + r, x);
    return s == 0.0 ? low : (1.0 - s) * low + s * alongSolidFraction(iz * ny + r + 1, x);
  };
  if (third_.empty()) {
    out.value = plane(0);
    return out;
  }
  const double z = std::clamp(third, third_.front(), third_.back());
  out.inRange = out.inRange && z == third;
  const auto [q, t] = bracket(third_, z);
  out.value = t == 0.0 ? plane(q) : (1.0 - t) * plane(q) + t * plane(q + 1);
  return out;
}

}  // namespace grainbridge::core
