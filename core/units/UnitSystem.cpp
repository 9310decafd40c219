#include "core/units/UnitSystem.hpp"

#include <cmath>

#include "core/Error.hpp"

namespace grainbridge::core::units {

UnitSystem UnitSystem::reduced(double d0, double m0, double g) {
  GB_ASSERT(d0 > 0 && m0 > 0 && g > 0, "reduced units need positive d0, m0 and g (validated by the caller)");
  UnitSystem u;
  u.reduced_ = true;
  u.d0_ = d0;
  u.m0_ = m0;
  u.t0_ = std::sqrt(d0 / g);
  return u;
}

double UnitSystem::toSI(double value, const Dimension& dim) const {
  if (!reduced_) return value;
  return value * std::pow(d0_, dim.length) * std::pow(m0_, dim.mass) * std::pow(t0_, dim.time);
}

nlohmann::json UnitSystem::toJson() const {
  if (!reduced_) return {{"system", "SI"}};
  return {{"system", "reduced"}, {"d0", d0_}, {"m0", m0_}, {"t0", t0_}};
}

UnitSystem UnitSystem::fromJson(const nlohmann::json& j) {
  if (j.at("system") == "SI") return si();
  const double t0 = j.at("t0").get<double>();
  return reduced(j.at("d0").get<double>(), j.at("m0").get<double>(), j.at("d0").get<double>() / (t0 * t0));
}

}  // namespace grainbridge::core::units
