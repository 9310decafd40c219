#include "core/ClosureForms.hpp"

#include <cmath>

#include "core/Error.hpp"

namespace grainbridge::core {

const std::array<ClosureFormInfo, 6>& closureForms() {
  static const std::array<ClosureFormInfo, 6> forms = {{
      {ClosureForm::PTheta, "p_theta", "p / (ρ θ)", "p/(ρθ)", true, 1.0},
      {ClosureForm::EtaTheta, "eta_theta", "μ / (ρ d √θ)", "μ/(ρd√θ)", true, 0.5},
      {ClosureForm::JTheta, "j_theta", "J d / (ρ θ^(3/2))", "Jd/(ρθ^(3/2))", true, 1.5},
      {ClosureForm::PShear, "p_shear", "p* = p / (ρ d² γ̇²)", "p*", false, 0.0},
      {ClosureForm::TauShear, "tau_shear", "τ* = −σxy / (ρ d² γ̇²)", "τ*", false, 0.0},
      {ClosureForm::TShear, "t_shear", "T* = θ / (d γ̇)²", "T*", false, 0.0},
  }};
  return forms;
}

const ClosureFormInfo& closureFormInfo(ClosureForm form) { return closureForms()[static_cast<std::size_t>(form)]; }

std::optional<ClosureForm> closureFormFromName(std::string_view name) {
  for (const auto& f : closureForms()) {
    if (f.name == name) return f.form;
  }
  return std::nullopt;
}

double toClosureForm(ClosureForm form, double value, const ClosureFormState& s) {
  const double rho = s.density, d = s.diameter, T = s.granularTemperature, g = s.shearRate;
  switch (form) {
    case ClosureForm::PTheta:
      return value / (rho * T);
    case ClosureForm::EtaTheta:
      return value / (rho * d * std::sqrt(T));
    case ClosureForm::JTheta:
      return value * d / (rho * std::pow(T, 1.5));
    case ClosureForm::PShear:
    case ClosureForm::TauShear:
      return value / (rho * d * d * g * g);
    case ClosureForm::TShear:
      return value / (d * d * g * g);
  }
  GB_ASSERT(false, "unknown closure form");
  return 0.0;
}

double fromClosureForm(ClosureForm form, double formValue, const ClosureFormState& s) {
  const double rho = s.density, theta = s.granularTemperature;
  switch (form) {
    case ClosureForm::PTheta:
      return formValue * (rho * theta);
    case ClosureForm::EtaTheta:
      return formValue * (rho * s.diameter * std::sqrt(theta));
    case ClosureForm::JTheta:
      return formValue * (rho * theta * std::sqrt(theta) / s.diameter);
    default:
      throw Error(std::string("closure form ") + std::string(closureFormInfo(form).name) +
                  " is shear-scaled: a continuum engine uses the theta-scaled forms");
  }
}

double closureFormError(ClosureForm form, MeasuredValue value, MeasuredValue temperature, const ClosureFormState& s) {
  const auto& info = closureFormInfo(form);
  if (!info.thetaScaled) return toClosureForm(form, value.error, s);
  // Relative errors add in quadrature for a product of powers.
  double sum = 0.0;
  for (const auto& [a, power] : {std::pair{value, 1.0}, std::pair{temperature, info.temperaturePower}}) {
    if (a.mean != 0.0) sum += std::pow(power * a.error / a.mean, 2);
  }
  return std::abs(toClosureForm(form, value.mean, s)) * std::sqrt(sum);
}

}  // namespace grainbridge::core
