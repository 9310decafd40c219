#pragma once
// Where one particle sits relative to the free surface of the bed around it: the Brazil-nut
// criterion of VALIDATION.md ("at the top" means the large particle's top within 1 d0 of the
// local free surface, Section 6.2). A global maximum height (the dem series' top_z columns) is
// not enough: one grain thrown up anywhere in the column, or a heap against the wall, moves it.
//
// Definition used here (the reference gives none):
// - heights are measured along `up` (against gravity);
// - the local free surface over particle P is the highest top (centre + radius) among the grains
//   that (a) overlap P's footprint: their distance from P's vertical axis is below r_P + r_j,
//   (b) have their centre above P's centre, and (c) touch something in the frame (a particle or a
//   wall): a grain in flight is not part of the bed;
// - gap = that surface - P's top, or 0 when no such grain exists (P is the top of its column).
// A grain resting on P gives a gap just under its diameter, so "within 1 d0" allows one
// incomplete layer above P and no more.
#include <cstddef>
#include <cstdint>

#include "core/Types.hpp"
#include "core/data/ParticleFrame.hpp"

namespace grainbridge::extract::structure {

struct LocalFreeSurface {
  double top = 0.0;                // height of P's top along up
  double surface = 0.0;            // local free surface above P (= top when nothing covers P)
  double gap = 0.0;                // surface - top, >= 0
  std::size_t coveringGrains = 0;  // grains counted in the surface (criteria a-c above)
};

// Throws grainbridge::Error when the frame has no particle `id` or `up` is not a unit-length
// direction (to 1e-9).
LocalFreeSurface localFreeSurface(const core::data::ParticleFrame& frame, std::int64_t id, const Vec3& up);

}  // namespace grainbridge::extract::structure
