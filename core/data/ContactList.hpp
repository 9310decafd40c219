#pragma once
// Particle-particle contacts of one frame, as per-property arrays. This list is what makes
// the contact part of Eq. 2.3, force PDFs, force networks and the MST possible: engines must
// never drop it, and writers store every array.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/Types.hpp"

namespace grainbridge::core::data {

struct ContactList {
  std::vector<std::int64_t> i, j;  // global particle ids
  // r_i - r_j under the minimum image (periodic / Lees-Edwards), so a contact across the
  // box has a short branch even though the two positions are a box length apart.
  std::vector<Vec3> branch;
  std::vector<Vec3> contactPoint;
  // Force on i from j; j receives the opposite.
  std::vector<Vec3> forceNormal, forceTangential;
  // Elastic + dissipative = total; dissipation rate and the stress split need both parts.
  std::vector<Vec3> forceNormalElastic, forceNormalDissipative;
  std::vector<Vec3> forceTangentialElastic, forceTangentialDissipative;

  [[nodiscard]] std::size_t size() const { return i.size(); }
  // Throws grainbridge::Error naming the first array whose length differs from i's.
  void validate() const;

  bool operator==(const ContactList&) const = default;
};

}  // namespace grainbridge::core::data
