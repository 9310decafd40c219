#pragma once
// Exact volume of the intersection of a sphere and an axis-aligned box, in closed form. The
// reference deposits each particle's whole volume into the cell holding its centre (Eqs.
// 7.35-7.36) and lists exact overlap as future work; this is that extension.
//
// Method: inclusion-exclusion over the box corners reduces the box to eight "corner" regions
// {x > a, y > b, z > c} of the sphere; the corner volume of a unit ball with a, b, c >= 0 is
// integrated in closed form (slice area of a disc cut by two perpendicular lines, then
// integrated along the third axis by parts), and negative a, b or c follow from reflection
// symmetry: V(a < 0, b, c) = 2 V(0, b, c) - V(-a, b, c).
#include "core/Types.hpp"

namespace grainbridge::core::grid {

// Volume of {x in box} intersected with the ball |x - centre| <= radius, in the units of
// radius cubed. A box of zero or negative extent on an axis gives 0.
double sphereBoxOverlapVolume(const Vec3& centre, double radius, const Vec3& boxLo, const Vec3& boxHi);

// Volume of the unit ball intersected with {x > a, y > b, z > c}, for any a, b, c (values
// beyond +-1 make the constraint empty or inactive). Exposed for tests.
double unitBallCornerVolume(double a, double b, double c);

}  // namespace grainbridge::core::grid
