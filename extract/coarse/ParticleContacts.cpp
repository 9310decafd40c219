#include "extract/coarse/ParticleContacts.hpp"

#include <string>

#include "core/Error.hpp"

namespace grainbridge::extract::coarse {

std::unordered_map<std::int64_t, std::size_t> indexById(const core::data::ParticleFrame& frame) {
  std::unordered_map<std::int64_t, std::size_t> index;
  index.reserve(frame.size());
  for (std::size_t i = 0; i < frame.size(); ++i) {
    if (!index.emplace(frame.id[i], i).second) {
      throw Error("particle frame at step " + std::to_string(frame.step) + ": particle id " +
                  std::to_string(frame.id[i]) + " appears more than once");
    }
  }
  return index;
}

namespace {
std::size_t lookup(const std::unordered_map<std::int64_t, std::size_t>& index, std::int64_t id, const char* list,
                   std::size_t k) {
  const auto it = index.find(id);
  if (it == index.end()) {
    throw Error(std::string(list) + " " + std::to_string(k) + " refers to particle id " + std::to_string(id) +
                ", which is not in the frame");
  }
  return it->second;
}
}  // namespace

ParticleContacts particleContacts(const core::data::ParticleFrame& frame,
                                  const std::unordered_map<std::int64_t, std::size_t>& index) {
  ParticleContacts out;
  out.count.assign(frame.size(), 0);
  out.totalForce.assign(frame.size(), Vec3::Zero());
  const auto& c = frame.contacts;
  for (std::size_t k = 0; k < c.size(); ++k) {
    const std::size_t i = lookup(index, c.i[k], "contact", k);
    const std::size_t j = lookup(index, c.j[k], "contact", k);
    const Vec3 f = c.forceNormal[k] + c.forceTangential[k];  // on i from j; j feels -f
    out.totalForce[i] += f;
    out.totalForce[j] -= f;
    ++out.count[i];
    ++out.count[j];
  }
  out.pairContacts = c.size();
  const auto& w = frame.wallContacts;
  for (std::size_t k = 0; k < w.size(); ++k) {
    out.totalForce[lookup(index, w.particle[k], "wall contact", k)] += w.forceNormal[k] + w.forceTangential[k];
  }
  return out;
}

}  // namespace grainbridge::extract::coarse
