#include "core/data/WholeDomainStress.hpp"

#include <string>
#include <unordered_map>
#include <vector>

#include "core/Error.hpp"
#include "core/data/StreamingProfile.hpp"

namespace grainbridge::core::data {

StressSums wholeDomainStressSums(const ParticleFrame& f) {
  StressSums out;
  const std::size_t n = f.size();
  // C about the mean peculiar velocity v - u(r) (two passes): under Lees-Edwards the mean of v
  // itself would carry shear rate (<y> - y_mid) whenever the mass centre is off mid-height.
  std::vector<Vec3> peculiar(n);
  Vec3 momentum = Vec3::Zero();
  for (std::size_t i = 0; i < n; ++i) {
    peculiar[i] = f.velocity[i] - streamingVelocity(f.domain, f.position[i]);
    out.mass += f.mass[i];
    momentum += f.mass[i] * peculiar[i];
  }
  const Vec3 mean = out.mass > 0.0 ? Vec3(momentum / out.mass) : Vec3::Zero();
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3 c = peculiar[i] - mean;
    out.kinetic += f.mass[i] * c * c.transpose();
  }
  const auto& pc = f.contacts;
  for (std::size_t k = 0; k < pc.size(); ++k) {
    out.contact += pc.branch[k] * (pc.forceNormal[k] + pc.forceTangential[k]).transpose();
  }
  const auto& wc = f.wallContacts;
  if (wc.size() > 0) {
    std::unordered_map<std::int64_t, std::size_t> index;
    for (std::size_t i = 0; i < n; ++i) index[f.id[i]] = i;
    for (std::size_t k = 0; k < wc.size(); ++k) {
      const auto at = index.find(wc.particle[k]);
      if (at == index.end())
        throw Error("whole-domain stress: wall contact " + std::to_string(k) + " names particle " +
                    std::to_string(wc.particle[k]) + ", which the frame does not hold");
      const Vec3 branch = f.position[at->second] - wc.point[k];
      out.contact += branch * (wc.forceNormal[k] + wc.forceTangential[k]).transpose();
    }
  }
  return out;
}

}  // namespace grainbridge::core::data
