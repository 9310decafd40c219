#include "core/averaging/FieldTimeAverage.hpp"

#include <string>

#include "core/Error.hpp"
#include "core/averaging/BlockAverage.hpp"

namespace grainbridge::core::averaging {

namespace {

std::vector<double> components(const std::vector<Vec3>& v) {
  std::vector<double> out;
  out.reserve(3 * v.size());
  for (const Vec3& x : v) out.insert(out.end(), {x[0], x[1], x[2]});
  return out;
}

std::vector<Vec3> vectors(const std::vector<double>& v) {
  std::vector<Vec3> out(v.size() / 3);
  for (std::size_t c = 0; c < out.size(); ++c) out[c] = Vec3(v[3 * c], v[3 * c + 1], v[3 * c + 2]);
  return out;
}

// Every cell array of a frame, in a fixed order: ep_g, p_g, u_g, then per phase ep_s, u_s,
// theta, then the extras.
std::vector<std::vector<double>> flatten(const core::data::FieldFrame& f) {
  std::vector<std::vector<double>> out = {f.ep_g, f.p_g, components(f.u_g)};
  for (const auto& phase : f.solids) {
    out.push_back(phase.ep_s);
    out.push_back(components(phase.u_s));
    out.push_back(phase.theta);
  }
  for (const auto& extra : f.extras) out.push_back(extra.values);
  return out;
}

// Writes flattened slot values back into a frame of the same layout.
void unflatten(const std::vector<std::vector<double>>& slots, core::data::FieldFrame& f) {
  std::size_t s = 0;
  f.ep_g = slots[s++];
  f.p_g = slots[s++];
  f.u_g = vectors(slots[s++]);
  for (auto& phase : f.solids) {
    phase.ep_s = slots[s++];
    phase.u_s = vectors(slots[s++]);
    phase.theta = slots[s++];
  }
  for (auto& extra : f.extras) extra.values = slots[s++];
}

void requireSameLayout(const core::data::FieldFrame& first, const core::data::FieldFrame& f) {
  const std::string where = "field time average: the frame at step " + std::to_string(f.step);
  if (!(f.grid == first.grid)) throw Error(where + " has a different grid from the first frame's");
  if (f.solids.size() != first.solids.size()) {
    throw Error(where + " has " + std::to_string(f.solids.size()) + " solids phases, the first frame " +
                std::to_string(first.solids.size()));
  }
  for (std::size_t p = 0; p < f.solids.size(); ++p) {
    if (f.solids[p].name != first.solids[p].name) {
      throw Error(where + " has phase '" + f.solids[p].name + "' where the first frame has '" + first.solids[p].name +
                  "'");
    }
  }
  if (f.extras.size() != first.extras.size()) {
    throw Error(where + " has " + std::to_string(f.extras.size()) + " extra fields, the first frame " +
                std::to_string(first.extras.size()));
  }
  for (std::size_t e = 0; e < f.extras.size(); ++e) {
    if (f.extras[e].name != first.extras[e].name || f.extras[e].components != first.extras[e].components) {
      throw Error(where + " has extra field '" + f.extras[e].name + "' where the first frame has '" +
                  first.extras[e].name + "'");
    }
  }
}

}  // namespace

void FieldTimeAverage::add(const core::data::FieldFrame& frame) {
  frame.validate();
  if (frames_ == 0) {
    layout_ = frame;
    series_.assign(flatten(frame).size(), {});
  } else {
    requireSameLayout(layout_, frame);
  }
  auto slots = flatten(frame);
  for (std::size_t s = 0; s < slots.size(); ++s) series_[s].push_back(std::move(slots[s]));
  lastTime_ = frame.time;
  lastStep_ = frame.step;
  ++frames_;
}

core::data::FieldFrame FieldTimeAverage::mean() const {
  if (frames_ == 0) throw Error("field time average: no frame was added");
  std::vector<std::vector<double>> means(series_.size()), errors(series_.size());
  for (std::size_t s = 0; s < series_.size(); ++s) {
    for (const BlockAverage& b : blockAverageCells(series_[s])) {
      means[s].push_back(b.mean);
      errors[s].push_back(b.standardError);
    }
  }
  core::data::FieldFrame out = layout_;
  out.time = lastTime_;
  out.step = lastStep_;
  unflatten(means, out);
  // The errors, named after their slots, in the order of flatten() (p_g and u_g have none: no
  // engine that writes gas fields averages them here yet, and a DEM frame's are zero).
  std::size_t s = 0;
  const auto err = [&](const std::string& name, int components) {
    out.extras.push_back({name + "_err", components, errors[s++]});
  };
  err("ep_g", 1);
  s += 2;
  for (const auto& phase : layout_.solids) {
    err(phase.name + "_ep_s", 1);
    err(phase.name + "_u_s", 3);
    err(phase.name + "_theta", 1);
  }
  for (const auto& extra : layout_.extras) err(extra.name, extra.components);
  return out;
}

}  // namespace grainbridge::core::averaging
