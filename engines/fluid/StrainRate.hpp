#pragma once
// The rate-of-strain tensor D = (grad v + grad v^T) / 2 of a phase at a cell centre from its
// staggered face velocities: the diagonal from the cell's own two faces, the off-diagonal from
// the cell-centred means of the neighbours on either side (central differences). Closures read
// tr(D), D:D and the second invariant of the deviator (Schaeffer's I2D) from it.
#include <array>
#include <cstddef>

#include "engines/fluid/FlowState.hpp"

namespace grainbridge::fluid {

struct StrainRate {
  std::array<std::array<double, 3>, 3> d{};  // D_ab [1/s]

  [[nodiscard]] double trace() const { return d[0][0] + d[1][1] + d[2][2]; }
  // D:D = sum_ab D_ab^2.
  [[nodiscard]] double doubleDot() const {
    double s = 0.0;
    for (const auto& row : d)
      for (double v : row) s += v * v;
    return s;
  }
  // I2D = ((D11 - D22)^2 + (D22 - D33)^2 + (D33 - D11)^2) / 6 + D12^2 + D23^2 + D31^2.
  [[nodiscard]] double deviatorInvariant() const {
    const double a = d[0][0] - d[1][1], b = d[1][1] - d[2][2], c = d[2][2] - d[0][0];
    return (a * a + b * b + c * c) / 6.0 + d[0][1] * d[0][1] + d[1][2] * d[1][2] + d[2][0] * d[2][0];
  }
};

// D of `phase` at interior cell c; the ghost velocities must hold their boundary values.
[[nodiscard]] inline StrainRate strainRate(const PhaseFields& phase, std::size_t c) {
  const StaggeredGrid& grid = phase.fraction.grid();
  StrainRate s;
  // Cell-centred component a at cell n: the mean of its two faces.
  auto centred = [&](int a, std::size_t n) {
    const FaceField& v = phase.velocity[static_cast<std::size_t>(a)];
    return 0.5 * (v[n] + v[grid.neighbour(n, a, -1)]);
  };
  std::array<std::array<double, 3>, 3> grad{};  // grad[a][b] = d v_a / d x_b
  for (int a = 0; a < grid.dimensions(); ++a) {
    for (int b = 0; b < grid.dimensions(); ++b) {
      if (a == b) {
        const FaceField& v = phase.velocity[static_cast<std::size_t>(a)];
        grad[static_cast<std::size_t>(a)][static_cast<std::size_t>(b)] =
            (v[c] - v[grid.neighbour(c, a, -1)]) / grid.spacing(a);
      } else {
        grad[static_cast<std::size_t>(a)][static_cast<std::size_t>(b)] =
            (centred(a, grid.neighbour(c, b, +1)) - centred(a, grid.neighbour(c, b, -1))) / (2.0 * grid.spacing(b));
      }
    }
  }
  for (std::size_t a = 0; a < 3; ++a)
    for (std::size_t b = 0; b < 3; ++b) s.d[a][b] = 0.5 * (grad[a][b] + grad[b][a]);
  return s;
}

}  // namespace grainbridge::fluid
