#include "extract/observe/MeanForceRatio.hpp"

#include <cmath>
#include <string>

#include "core/Error.hpp"

namespace grainbridge::extract::observe {

namespace {

core::data::NamedCellField* find(core::data::FieldFrame& frame, const std::string& name) {
  for (auto& f : frame.extras) {
    if (f.name == name) return &f;
  }
  return nullptr;
}

}  // namespace

void useRatioOfMeans(core::data::FieldFrame& mean) {
  auto* ratio = find(mean, "contact_to_drag_ratio");
  auto* ratioErr = find(mean, "contact_to_drag_ratio_err");
  if (ratio == nullptr) return;
  const auto* contact = find(mean, "contact_force");
  const auto* drag = find(mean, "drag_force");
  const auto* contactErr = find(mean, "contact_force_err");
  const auto* dragErr = find(mean, "drag_force_err");
  if (contact == nullptr || drag == nullptr || contactErr == nullptr || dragErr == nullptr)
    throw Error("extract: a time-averaged frame with contact_to_drag_ratio lacks contact_force or drag_force");
  for (std::size_t c = 0; c < ratio->values.size(); ++c) {
    const double C = contact->values[c], D = drag->values[c];
    if (!(D > 0.0)) {
      ratio->values[c] = -1.0;
      if (ratioErr != nullptr) ratioErr->values[c] = 0.0;
      continue;
    }
    const double r = C / D;
    ratio->values[c] = r;
    if (ratioErr != nullptr) {
      const double relativeDrag = dragErr->values[c] / D;
      const double relativeContact = C > 0.0 ? contactErr->values[c] / C : 0.0;
      ratioErr->values[c] = std::abs(r) * std::sqrt(relativeContact * relativeContact + relativeDrag * relativeDrag);
    }
  }
}

}  // namespace grainbridge::extract::observe
