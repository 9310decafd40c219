#pragma once
// Scalar measures of an Eq. 2.3 stress tensor (positive in compression, as in the reference):
//  - pressure p = tr(sigma) / 3;
//  - shear stress sigma_xy, the one that matters in the simple shear of Chapter 6 (x flow,
//    y gradient); it is negative there (-sigma_xy gammadot V is the work done by the shear);
//  - deviatoric norm sqrt(s:s / 2), s = sigma - p I: the equivalent shear stress (sqrt J2),
//    which equals |sigma_xy| for a pure simple-shear stress and does not depend on axes.
#include <cmath>

#include "core/Types.hpp"

namespace grainbridge::extract::coarse {

inline double pressure(const Mat3& sigma) { return sigma.trace() / 3.0; }

inline double shearStress(const Mat3& sigma) { return sigma(0, 1); }

inline double deviatoricNorm(const Mat3& sigma) {
  // The identity as a stored matrix, not an expression: the difference is then formed with
  // vector operations, as squaredNorm reads it back (the scalar stores of an identity
  // expression stalled those reads, once per cell of a coarse-grained frame). Same values.
  static const Mat3 identity = Mat3::Identity();
  const Mat3 s = sigma - pressure(sigma) * identity;
  return std::sqrt(0.5 * s.squaredNorm());
}

}  // namespace grainbridge::extract::coarse
