#pragma once
// Field frames reduced to what a bed's figures show, for any engine that writes them (mfm, TF-DEM):
// the solids fraction on the vertical plane (Figs. 5.2, 7.2) and against height (Fig. 5.6).
// Vertical is against the frame's gravity (its materials), horizontal is the other axis of the
// plane, and the third axis (the depth of a 2D bed) is averaged over.
#include <cstddef>
#include <vector>

#include "core/data/FieldFrame.hpp"

namespace grainbridge::fluid {

// Cell values on the plane, row by row from the bottom: values[row * columns + column].
struct PlaneMap {
  int columns = 0, rows = 0;
  double x0 = 0.0, y0 = 0.0, dx = 1.0, dy = 1.0;  // the first cell's low corner and the spacing
  std::vector<double> values;
};

// The solids fraction summed over every solids phase. Throws grainbridge::Error when the frame
// carries no materials (no gravity to tell the vertical).
[[nodiscard]] PlaneMap solidsFractionMap(const core::data::FieldFrame& frame);

// Phase m's (0-based among the solids) fraction averaged over each horizontal layer of cells,
// from the bottom layer up; heights[k] is layer k's centre above the domain's bottom. Throws as
// solidsFractionMap does, or for m out of range.
struct HeightProfile {
  std::vector<double> heights;
  std::vector<double> fraction;
};
[[nodiscard]] HeightProfile solidsFractionProfile(const core::data::FieldFrame& frame, std::size_t m);

}  // namespace grainbridge::fluid
