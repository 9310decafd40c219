#pragma once
// Reading a pressure-drop curve the way Fig. 4.5 is read: below minimum fluidization the drop
// rises with the inflow as a packed bed's does (Ergun's form, a U + b U^2), above it the drop
// stays at a plateau, the bed's weight. The plateau is the mean of the points past the
// fluidization velocity, and the fluidization velocity is where the packed branch (a least-squares
// fit of a U + b U^2 to the points below 90 % of the plateau) reaches the plateau; the two are
// found together by a few alternations from the largest drop. The curve itself decides: the drag
// law's own U_mf is what the result is compared with, never an input.
#include <vector>

namespace grainbridge::mfm {

struct CurvePoint {
  double inflow = 0.0;        // superficial gas velocity U [m/s]
  double pressureDrop = 0.0;  // time-averaged [Pa]
  double error = 0.0;         // its block-averaging standard error [Pa]
};

struct FluidizationReading {
  bool found = false;         // false: fewer than two packed points, or fewer than two past the meeting
  double plateau = 0.0;       // [Pa]
  double plateauError = 0.0;  // standard error of that mean (from the points' errors) [Pa]
  int plateauPoints = 0;
  double fluidizationVelocity = 0.0;  // [m/s]
};

[[nodiscard]] FluidizationReading readFluidizationCurve(std::vector<CurvePoint> points);

}  // namespace grainbridge::mfm
