#include "engines/fluid/FieldSampling.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace grainbridge::fluid {

namespace {

// The lower of the two carriers of a value along an axis around coordinate `s` (in carrier
// spacings from the first carrier, index `first`) and the weight of the upper one, both clamped to
// the carriers from `first` to `last`.
struct Bracket {
  int lower = 0;
  double weight = 0.0;
};

Bracket bracket(double s, int first, int last) {
  const double clamped = std::clamp(s, static_cast<double>(first), static_cast<double>(last));
  const int lower = std::min(static_cast<int>(std::floor(clamped)), last - 1);
  return {std::max(lower, first), clamped - std::max(lower, first)};
}

}  // namespace

Vec3 cellVelocity(const PhaseFields& phase, std::size_t cell) {
  const StaggeredGrid& grid = phase.fraction.grid();
  Vec3 v = Vec3::Zero();
  for (int a = 0; a < grid.dimensions(); ++a) {
    const FaceField& u = phase.velocity[static_cast<std::size_t>(a)];
    v[a] = 0.5 * (u[cell] + u[grid.neighbour(cell, a, -1)]);
  }
  return v;
}

Vec3 velocityAt(const PhaseFields& phase, const Vec3& point) {
  const StaggeredGrid& grid = phase.fraction.grid();
  const auto& geometry = grid.geometry();
  Vec3 v = Vec3::Zero();
  for (int a = 0; a < grid.dimensions(); ++a) {
    const FaceField& u = phase.velocity[static_cast<std::size_t>(a)];
    std::array<Bracket, 3> along{};
    for (int b = 0; b < 3; ++b) {
      if (!grid.active(b)) continue;  // z in 2D: the one layer
      const double s = (point[b] - geometry.origin[b]) / grid.spacing(b);
      const int n = grid.cells(b);
      // Component a sits on the faces along a (face i at (i + 1) h, i from -1 to n - 1) and at the
      // cell centres along the others ((j + 0.5) h, ghosts -1 and n included).
      along[static_cast<std::size_t>(b)] = b == a ? bracket(s - 1.0, -1, n - 1) : bracket(s - 0.5, -1, n);
    }
    double value = 0.0;
    for (int corner = 0; corner < 8; ++corner) {
      std::array<int, 3> at{0, 0, 0};
      double w = 1.0;
      bool used = true;
      for (int b = 0; b < 3; ++b) {
        const int up = (corner >> b) & 1;
        if (!grid.active(b)) {
          used = used && up == 0;
          continue;
        }
        const Bracket& br = along[static_cast<std::size_t>(b)];
        at[static_cast<std::size_t>(b)] = br.lower + up;
        w *= up != 0 ? br.weight : 1.0 - br.weight;
      }
      if (used && w != 0.0) value += w * u[grid.index(at[0], at[1], at[2])];
    }
    v[a] = value;
  }
  return v;
}

Vec3 pressureGradient(const CellField& pressure, std::size_t cell) {
  const StaggeredGrid& grid = pressure.grid();
  const auto position = grid.coordinates(cell);
  Vec3 g = Vec3::Zero();
  for (int a = 0; a < grid.dimensions(); ++a) {
    const int i = position[static_cast<std::size_t>(a)], n = grid.cells(a);
    const bool low = i > 0, high = i < n - 1;
    const std::size_t W = grid.neighbour(cell, a, -1), E = grid.neighbour(cell, a, +1);
    const double h = grid.spacing(a);
    if (low && high) {
      g[a] = (pressure[E] - pressure[W]) / (2.0 * h);
    } else if (high) {
      g[a] = (pressure[E] - pressure[cell]) / h;
    } else if (low) {
      g[a] = (pressure[cell] - pressure[W]) / h;
    }
  }
  return g;
}

}  // namespace grainbridge::fluid
