#pragma once
// Random sequential insertion of non-overlapping spheres into a box region (the first step of
// every preparation: insert, then settle under gravity). Periodic axes wrap the overlap test.
// Fails with a message when the region is too full for random insertion (it jams near solid
// fraction kRandomInsertionJamming for equal spheres).
#include <array>
#include <cstdint>
#include <functional>
#include <random>
#include <vector>

#include "core/Types.hpp"

namespace grainbridge::dem {

// The solid fraction near which random sequential insertion of equal spheres jams (the random
// sequential addition limit, about 0.38 in the bulk): the run-time failure names it, and a stage
// refuses at config check a request whose spheres would fill more of their region than this.
inline constexpr double kRandomInsertionJamming = 0.38;

struct InsertionRequest {
  Vec3 lo = Vec3::Zero();
  Vec3 hi = Vec3::Ones();
  std::array<bool, 3> periodic{false, false, false};  // wrap the overlap test on these axes
  std::vector<double> radii;                          // one per sphere, inserted largest first
  // Spheres already in place (e.g. the Brazil nut held at the bottom): new ones avoid them.
  std::vector<Vec3> fixedCentres;
  std::vector<double> fixedRadii;
  std::int64_t maxAttempts = 100000;  // per sphere
  // Optional cylinder (axis along z through cylinderCentre) the spheres must lie inside.
  bool insideCylinder = false;
  Vec3 cylinderCentre = Vec3::Zero();
  double cylinderRadius = 0.0;
  // Called every 1024 spheres with the number placed so far (progress display; it may throw to
  // abandon the insertion, e.g. on a stop request).
  std::function<void(std::size_t)> progress;
};

// Returns one centre per entry of request.radii (same order). Throws grainbridge::Error naming
// the sphere that could not be placed.
std::vector<Vec3> insertRandomly(const InsertionRequest& request, std::mt19937_64& rng);

// The solid fraction the spheres to insert (request.radii; the fixed ones may lie outside the
// region and are left out) would fill in the region: their volume over the box's, or over the
// box's height times the smaller of its cross-section and the cylinder's where a cylinder bounds
// it. An estimate that errs low (walls and the cylinder's cut corners are not subtracted), so a
// request above kRandomInsertionJamming cannot be met.
[[nodiscard]] double requestedSolidFraction(const InsertionRequest& request);

}  // namespace grainbridge::dem
