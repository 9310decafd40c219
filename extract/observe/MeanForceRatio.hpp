#pragma once
// The time-averaged contact-to-drag force ratio of Figs. 7.7b and 7.12b: per cell, the mean
// |sum of contact forces| over the mean |sum of drag forces|, -1 where the mean drag is zero.
// Averaging each frame's ratio instead would mix in the -1 of frames without drag and weight a
// frame where the drag nearly vanishes as heavily as any other. Each frame keeps its own ratio
// (the snapshot of Fig. 7.7a).
#include "core/data/FieldFrame.hpp"

namespace grainbridge::extract::observe {

// In a time-averaged field frame holding contact_force, drag_force and their errors (the
// FieldTimeAverage of FieldObserver's frames), replaces contact_to_drag_ratio by the ratio of the
// means and contact_to_drag_ratio_err by its first-order error, sqrt((sC/C)^2 + (sD/D)^2) |C/D|
// (the two means' correlation left out: they are sums over the same particles, so this bounds
// the error from above when they rise and fall together). A frame without drag_force (no gas)
// is left as it is.
void useRatioOfMeans(core::data::FieldFrame& mean);

}  // namespace grainbridge::extract::observe
