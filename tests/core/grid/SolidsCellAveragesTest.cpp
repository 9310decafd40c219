// Eqs. 7.35-7.36: solid fraction = particle volume in the cell / cell volume and the
// volume-weighted mean velocity; exact overlap reduces to the centre-cell result for spheres
// inside single cells, and either way the integral of the solid fraction is the particle volume.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "core/Error.hpp"
#include "core/grid/SolidsCellAverages.hpp"

using namespace grainbridge;
using namespace grainbridge::core::grid;

namespace {
double sphereVolume(double r) { return 4.0 / 3.0 * M_PI * r * r * r; }
}  // namespace

TEST(SolidsCellAverages, CentreCellIsEquations735And736) {
  const CellGrid grid(Vec3(0, 0, 0), Vec3(2, 1, 1), {2, 1, 1});
  // Two particles in cell 0 (one straddling into cell 1: its whole volume still goes to cell 0).
  const std::vector<Vec3> x{Vec3(0.3, 0.5, 0.5), Vec3(0.9, 0.5, 0.5), Vec3(1.5, 0.5, 0.5)};
  const std::vector<double> r{0.1, 0.2, 0.15};
  const std::vector<Vec3> v{Vec3(1, 0, 0), Vec3(0, 2, 0), Vec3(0, 0, 3)};
  const auto avg = averageSolidsOnCells(grid, x, r, v, VolumeDeposition::CentreCell);
  const double v0 = sphereVolume(0.1), v1 = sphereVolume(0.2), v2 = sphereVolume(0.15);
  EXPECT_NEAR(avg.solidFraction[0], (v0 + v1) / 1.0, 1e-15);
  EXPECT_NEAR(avg.solidFraction[1], v2, 1e-15);
  EXPECT_TRUE(avg.velocity[0].isApprox((v0 * v[0] + v1 * v[1]) / (v0 + v1), 1e-15));
  EXPECT_TRUE(avg.velocity[1].isApprox(v[2], 1e-15));
}

TEST(SolidsCellAverages, OverlapReducesToCentreCellForSpheresInsideCells) {
  const CellGrid grid(Vec3(0, 0, 0), Vec3(4, 4, 4), {4, 4, 4});
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(0.25, 0.75);
  std::normal_distribution<double> g;
  std::vector<Vec3> x, v;
  std::vector<double> r;
  for (int k = 0; k < 4; ++k) {
    for (int j = 0; j < 4; ++j) {
      for (int i = 0; i < 4; ++i) {
        x.emplace_back(i + u(rng), j + u(rng), k + u(rng));
        r.push_back(0.2);
        v.emplace_back(g(rng), g(rng), g(rng));
      }
    }
  }
  const auto centre = averageSolidsOnCells(grid, x, r, v, VolumeDeposition::CentreCell);
  const auto overlap = averageSolidsOnCells(grid, x, r, v, VolumeDeposition::ExactOverlap);
  for (std::size_t c = 0; c < grid.cellCount(); ++c) {
    EXPECT_NEAR(overlap.solidFraction[c], centre.solidFraction[c], 1e-15);
    EXPECT_TRUE(overlap.velocity[c].isApprox(centre.velocity[c], 1e-14));
  }
}

TEST(SolidsCellAverages, IntegralOfSolidFractionIsTheParticleVolume) {
  const CellGrid grid(Vec3(0, 0, 0), Vec3(3, 3, 3), {6, 6, 6}, {true, true, true});
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(0.0, 3.0);
  std::vector<Vec3> x, v;
  std::vector<double> r;
  double volume = 0.0;
  for (int p = 0; p < 60; ++p) {
    x.emplace_back(u(rng), u(rng), u(rng));
    r.push_back(0.1 + 0.1 * u(rng));
    v.emplace_back(Vec3::Ones());
    volume += sphereVolume(r.back());
  }
  for (auto mode : {VolumeDeposition::CentreCell, VolumeDeposition::ExactOverlap}) {
    const auto avg = averageSolidsOnCells(grid, x, r, v, mode);
    double integral = 0.0;
    for (double eps : avg.solidFraction) integral += eps * grid.cellVolume();
    EXPECT_NEAR(integral / volume, 1.0, 1e-12);
    for (std::size_t c = 0; c < grid.cellCount(); ++c) {
      if (avg.solidFraction[c] > 0) {
        EXPECT_TRUE(avg.velocity[c].isApprox(Vec3::Ones(), 1e-14));
      }
    }
  }
}

TEST(SolidsCellAverages, MismatchedArraysAreAnError) {
  const CellGrid grid(Vec3(0, 0, 0), Vec3(1, 1, 1), {1, 1, 1});
  const std::vector<Vec3> x{Vec3::Zero()};
  const std::vector<double> r;
  EXPECT_THROW(averageSolidsOnCells(grid, x, r, x, VolumeDeposition::CentreCell), Error);
}
