#pragma once
// Vector and tensor aliases shared by every module. Double precision throughout: DEM contact
// overlaps are ~1e-4 of a diameter and Eq. 2.3 sums many cancelling contributions.
#include <Eigen/Core>
#include <Eigen/Geometry>  // cross products
#include <cstdint>

namespace grainbridge {
using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;
using Vec3i = Eigen::Vector3i;
using Index = std::int64_t;  // particle and contact counts may exceed 2^31 on big runs
}  // namespace grainbridge
