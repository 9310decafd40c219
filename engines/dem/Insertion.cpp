#include "engines/dem/Insertion.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <string>

#include "core/Error.hpp"
#include "core/text/NumberText.hpp"

namespace grainbridge::dem {

std::vector<Vec3> insertRandomly(const InsertionRequest& rq, std::mt19937_64& rng) {
  const std::size_t n = rq.radii.size();
  std::vector<Vec3> centre(n, Vec3::Zero());
  if (n == 0) return centre;
  double maxRadius = *std::max_element(rq.radii.begin(), rq.radii.end());
  for (double a : rq.fixedRadii) maxRadius = std::max(maxRadius, a);
  const Vec3 extent = rq.hi - rq.lo;
  // Cells of side >= the largest diameter: an overlap can only be with the 27 neighbours.
  Vec3i cells;
  for (int a = 0; a < 3; ++a) cells[a] = std::max(1, static_cast<int>(std::floor(extent[a] / (2.0 * maxRadius))));
  const Vec3 cellSize = extent.cwiseQuotient(cells.cast<double>());
  std::vector<std::vector<std::size_t>> grid(static_cast<std::size_t>(cells[0]) * cells[1] * cells[2]);
  auto cellOf = [&](const Vec3& x) {
    Vec3i c;
    for (int a = 0; a < 3; ++a) c[a] = std::clamp(static_cast<int>((x[a] - rq.lo[a]) / cellSize[a]), 0, cells[a] - 1);
    return c;
  };
  auto flat = [&](const Vec3i& c) { return (static_cast<std::size_t>(c[2]) * cells[1] + c[1]) * cells[0] + c[0]; };

  // Fixed spheres take indices n.. in the grid's view.
  std::vector<Vec3> all = centre;
  std::vector<double> radius = rq.radii;
  for (std::size_t k = 0; k < rq.fixedCentres.size(); ++k) {
    all.push_back(rq.fixedCentres[k]);
    radius.push_back(rq.fixedRadii[k]);
    grid[flat(cellOf(rq.fixedCentres[k]))].push_back(n + k);
  }

  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), 0);
  // Largest first: big spheres are the hard ones to fit once the space fills up.
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return rq.radii[a] > rq.radii[b]; });

  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (std::size_t k = 0; k < n; ++k) {
    if (rq.progress && (k & 1023) == 0) rq.progress(k);
    const std::size_t i = order[k];
    const double a = rq.radii[i];
    bool placed = false;
    for (std::int64_t attempt = 0; attempt < rq.maxAttempts && !placed; ++attempt) {
      Vec3 x;
      for (int d = 0; d < 3; ++d) {
        // Non-periodic axes keep the whole sphere inside the region.
        const double margin = rq.periodic[static_cast<std::size_t>(d)] ? 0.0 : a;
        x[d] = rq.lo[d] + margin + unit(rng) * (extent[d] - 2.0 * margin);
      }
      if (rq.insideCylinder) {
        const Vec3 radial(x[0] - rq.cylinderCentre[0], x[1] - rq.cylinderCentre[1], 0.0);
        if (radial.norm() > rq.cylinderRadius - a) continue;
      }
      const Vec3i c = cellOf(x);
      bool overlap = false;
      for (int dz = -1; dz <= 1 && !overlap; ++dz)
        for (int dy = -1; dy <= 1 && !overlap; ++dy)
          for (int dx = -1; dx <= 1 && !overlap; ++dx) {
            Vec3i q = c + Vec3i(dx, dy, dz);
            bool skip = false;
            for (int d = 0; d < 3; ++d) {
              if (q[d] >= 0 && q[d] < cells[d]) continue;
              if (!rq.periodic[static_cast<std::size_t>(d)] || cells[d] < 3) skip = true;
              q[d] = (q[d] + cells[d]) % cells[d];
            }
            if (skip) continue;
            for (std::size_t j : grid[flat(q)]) {
              Vec3 r = x - all[j];
              for (int d = 0; d < 3; ++d) {
                if (rq.periodic[static_cast<std::size_t>(d)]) r[d] -= extent[d] * std::round(r[d] / extent[d]);
              }
              const double reach = a + radius[j];
              if (r.squaredNorm() < reach * reach) {
                overlap = true;
                break;
              }
            }
          }
      if (overlap) continue;
      centre[i] = x;
      all[i] = x;
      grid[flat(c)].push_back(i);
      placed = true;
    }
    if (!placed) {
      throw Error("could not insert sphere " + std::to_string(k + 1) + " of " + std::to_string(n) + " (radius " +
                  std::to_string(a) + " m) without overlap after " + std::to_string(rq.maxAttempts) +
                  " attempts: the region is too full for random insertion (it jams near solid fraction " +
                  core::humanNumber(kRandomInsertionJamming) + "); enlarge the insertion region or insert fewer particles");
    }
  }
  return centre;
}

double requestedSolidFraction(const InsertionRequest& rq) {
  double spheres = 0.0;
  for (const double a : rq.radii) spheres += 4.0 / 3.0 * M_PI * a * a * a;
  const Vec3 extent = rq.hi - rq.lo;
  double crossSection = extent[0] * extent[1];
  if (rq.insideCylinder) crossSection = std::min(crossSection, M_PI * rq.cylinderRadius * rq.cylinderRadius);
  const double volume = crossSection * extent[2];
  return volume > 0.0 ? spheres / volume : std::numeric_limits<double>::infinity();
}

}  // namespace grainbridge::dem
