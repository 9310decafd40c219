#include "extract/coarse/ParticleContacts.hpp"

#include <algorithm>
#include <string>

#include "core/Error.hpp"

namespace grainbridge::extract::coarse {

namespace {

[[noreturn]] void throwRepeated(const core::data::ParticleFrame& frame, std::size_t i) {
  throw Error("particle frame at step " + std::to_string(frame.step) + ": particle id " + std::to_string(frame.id[i]) +
              " appears more than once");
}

}  // namespace

void ParticleIndex::assign(const core::data::ParticleFrame& frame) {
  dense_ = false;
  smallest_ = 0;
  table_.clear();
  sorted_.clear();
  const std::size_t n = frame.size();
  if (n == 0) return;
  const auto [lo, hi] = std::minmax_element(frame.id.begin(), frame.id.end());
  smallest_ = *lo;
  // Unsigned: the span of int64 ids can exceed the int64 range.
  const std::uint64_t span = static_cast<std::uint64_t>(*hi) - static_cast<std::uint64_t>(*lo);
  // A table at most a few times the particle count; ids with gaps (deleted particles) fit too.
  dense_ = span < 4 * static_cast<std::uint64_t>(n);
  if (dense_) {
    table_.assign(static_cast<std::size_t>(span) + 1, npos);
    for (std::size_t i = 0; i < n; ++i) {
      std::size_t& slot = table_[static_cast<std::size_t>(static_cast<std::uint64_t>(frame.id[i]) -
                                                          static_cast<std::uint64_t>(smallest_))];
      if (slot != npos) throwRepeated(frame, i);
      slot = i;
    }
    return;
  }
  sorted_.reserve(n);
  for (std::size_t i = 0; i < n; ++i) sorted_.emplace_back(frame.id[i], i);
  std::sort(sorted_.begin(), sorted_.end());
  // Within a run of equal ids every entry after the first repeats it; report the earliest repeat
  // in frame order, as a scan of the frame would.
  std::size_t firstRepeat = npos;
  for (std::size_t r = 1; r < n; ++r) {
    if (sorted_[r].first == sorted_[r - 1].first) firstRepeat = std::min(firstRepeat, sorted_[r].second);
  }
  if (firstRepeat != npos) throwRepeated(frame, firstRepeat);
}

std::size_t ParticleIndex::findSorted(std::int64_t id) const {
  const auto it =
      std::lower_bound(sorted_.begin(), sorted_.end(), id,
                       [](const std::pair<std::int64_t, std::size_t>& e, std::int64_t v) { return e.first < v; });
  return it != sorted_.end() && it->first == id ? it->second : npos;
}

void ParticleIndex::throwMissing(std::int64_t id, const char* list, std::size_t entry) {
  throw Error(std::string(list) + " " + std::to_string(entry) + " refers to particle id " + std::to_string(id) +
              ", which is not in the frame");
}

ParticleContacts particleContacts(const core::data::ParticleFrame& frame, const ParticleIndex& index) {
  ParticleContacts out;
  particleContacts(frame, index, out);
  return out;
}

void particleContacts(const core::data::ParticleFrame& frame, const ParticleIndex& index, ParticleContacts& out) {
  const auto& c = frame.contacts;
  const auto& w = frame.wallContacts;
  out.first.resize(c.size());
  out.second.resize(c.size());
  for (std::size_t k = 0; k < c.size(); ++k) {
    out.first[k] = index.at(c.i[k], "contact", k);
    out.second[k] = index.at(c.j[k], "contact", k);
  }
  out.wallParticle.resize(w.size());
  for (std::size_t k = 0; k < w.size(); ++k) out.wallParticle[k] = index.at(w.particle[k], "wall contact", k);

  out.count.assign(frame.size(), 0);
  out.totalForce.assign(frame.size(), Vec3::Zero());
  for (std::size_t k = 0; k < c.size(); ++k) {
    const std::size_t i = out.first[k], j = out.second[k];
    const Vec3 f = c.forceNormal[k] + c.forceTangential[k];  // on i from j; j feels -f
    out.totalForce[i] += f;
    out.totalForce[j] -= f;
    ++out.count[i];
    ++out.count[j];
  }
  out.pairContacts = c.size();
  for (std::size_t k = 0; k < w.size(); ++k) {
    out.totalForce[out.wallParticle[k]] += w.forceNormal[k] + w.forceTangential[k];
  }
}

}  // namespace grainbridge::extract::coarse
