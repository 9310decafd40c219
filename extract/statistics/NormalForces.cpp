#include "extract/statistics/NormalForces.hpp"

#include <cmath>
#include <string>

#include "core/Error.hpp"

namespace grainbridge::extract::statistics {

RepulsiveForces repulsiveForces(const core::data::ParticleFrame& frame) {
  const auto& c = frame.contacts;
  const std::string where = "in frame at step " + std::to_string(frame.step);
  if (c.branch.size() != c.size() || c.forceNormal.size() != c.size() || c.contactPoint.size() != c.size()) {
    throw Error("force statistics: contact arrays of unequal length " + where);
  }
  RepulsiveForces out;
  out.contactsInFrame = c.size();
  double sum = 0.0;
  for (std::size_t k = 0; k < c.size(); ++k) {
    const double len = c.branch[k].norm();
    if (!(len > 0.0) || !std::isfinite(len)) {
      throw Error("force statistics: contact " + std::to_string(k) + " (ids " + std::to_string(c.i[k]) + ", " +
                  std::to_string(c.j[k]) + ") has a zero or non-finite branch vector " + where);
    }
    const double fn = c.forceNormal[k].dot(c.branch[k]) / len;
    if (!std::isfinite(fn))
      throw Error("force statistics: contact " + std::to_string(k) + " has a non-finite force " + where);
    if (fn <= 0.0) continue;
    out.normalForce.push_back(fn);
    out.contactPoint.push_back(c.contactPoint[k]);
    out.contact.push_back(k);
    sum += fn;
  }
  if (out.normalForce.empty()) {
    throw Error("force statistics: no contacts with F_n > 0 " + where + " (" + std::to_string(c.size()) +
                " particle-particle contacts in the frame)");
  }
  out.meanForce = sum / static_cast<double>(out.normalForce.size());
  out.f.reserve(out.normalForce.size());
  for (double fn : out.normalForce) out.f.push_back(fn / out.meanForce);
  return out;
}

std::vector<double> normalisedForces(std::span<const core::data::ParticleFrame> frames) {
  if (frames.empty()) throw Error("force statistics: no frames");
  std::vector<double> f;
  for (const auto& frame : frames) {
    const RepulsiveForces r = repulsiveForces(frame);
    f.insert(f.end(), r.f.begin(), r.f.end());
  }
  return f;
}

}  // namespace grainbridge::extract::statistics
