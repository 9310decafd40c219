#include "extract/structure/LocalFreeSurface.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <unordered_set>

#include "core/Error.hpp"
#include "extract/geometry/PeriodicBox.hpp"

namespace grainbridge::extract::structure {

LocalFreeSurface localFreeSurface(const core::data::ParticleFrame& frame, std::int64_t id, const Vec3& up) {
  if (!(std::abs(up.norm() - 1.0) < 1e-9)) {
    throw Error("local free surface: the up direction must be a unit vector, got |up| = " + std::to_string(up.norm()));
  }
  const auto found = std::find(frame.id.begin(), frame.id.end(), id);
  if (found == frame.id.end()) {
    throw Error("local free surface: the frame at step " + std::to_string(frame.step) + " has no particle " +
                std::to_string(id));
  }
  const auto p = static_cast<std::size_t>(found - frame.id.begin());

  // Grains touching anything: the bed, as opposed to grains in flight.
  std::unordered_set<std::int64_t> touching;
  touching.reserve(2 * frame.contacts.size() + frame.wallContacts.particle.size());
  for (std::size_t k = 0; k < frame.contacts.size(); ++k) {
    touching.insert(frame.contacts.i[k]);
    touching.insert(frame.contacts.j[k]);
  }
  touching.insert(frame.wallContacts.particle.begin(), frame.wallContacts.particle.end());

  const geometry::PeriodicBox box(frame.domain);
  const double centre = frame.position[p].dot(up);
  LocalFreeSurface out;
  out.top = centre + frame.radius[p];
  out.surface = out.top;
  for (std::size_t j = 0; j < frame.size(); ++j) {
    if (j == p || !touching.contains(frame.id[j])) continue;
    const Vec3 d = box.minimumImage(frame.position[j] - frame.position[p]);
    const double along = d.dot(up);
    if (along <= 0.0) continue;
    const double reach = frame.radius[p] + frame.radius[j];
    if ((d - along * up).squaredNorm() >= reach * reach) continue;
    ++out.coveringGrains;
    out.surface = std::max(out.surface, centre + along + frame.radius[j]);
  }
  out.gap = out.surface - out.top;
  return out;
}

}  // namespace grainbridge::extract::structure
