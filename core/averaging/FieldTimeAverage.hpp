#pragma once
// Time average of coarse-grained field frames, cell by cell, with block-averaging standard
// errors (BlockAverage.hpp): the steady fields of a run, and how well the run pins them down.
// Issue 5 asks for "time averaging over frames with block-averaging uncertainties" of the
// coarse-grained fields, not only of the whole-domain values.
//
// Every cell array of the frames is averaged: the gas slots (zero in a DEM frame), each solids
// phase's ep_s, u_s and theta, and every named extra field, component by component. The result
// is a field frame of the same layout holding the means, plus one extra field "<slot>_err" per
// slot with the standard errors (ep_g_err, <phase>_ep_s_err, <phase>_u_s_err, <phase>_theta_err,
// <extra>_err), so ParaView shows a field and its uncertainty side by side. Its time and step
// are the last frame's.
//
// Memory: the series of every cell value is kept until mean() (frames x cells x values doubles),
// since the blocking transformation needs the whole series.
#include <cstddef>
#include <vector>

#include "core/data/FieldFrame.hpp"

namespace grainbridge::core::averaging {

class FieldTimeAverage {
 public:
  // Throws grainbridge::Error when the frame's grid, phases or extra fields differ from the
  // first frame's (naming what differs).
  void add(const core::data::FieldFrame& frame);

  [[nodiscard]] std::size_t frames() const { return frames_; }
  // Throws grainbridge::Error when no frame was added.
  [[nodiscard]] core::data::FieldFrame mean() const;

 private:
  core::data::FieldFrame layout_;  // the first frame: grid, names, component counts
  double lastTime_ = 0.0;
  std::int64_t lastStep_ = 0;
  std::size_t frames_ = 0;
  // series_[slot][frame][value]; slots in the order of flatten().
  std::vector<std::vector<std::vector<double>>> series_;
};

}  // namespace grainbridge::core::averaging
