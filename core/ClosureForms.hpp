#pragma once
// The closure forms of DESIGN.md ("Closures"), defined once: a transport quantity measured by
// extract or predicted by a kinetic-theory model, made dimensionless by the scale of its state.
//   theta-scaled (what a continuum engine uses with its own local temperature):
//     p_theta   = p  / (rho_p theta)
//     eta_theta = mu / (rho_p d sqrt(theta))
//     j_theta   = J d / (rho_p theta^(3/2))
//   shear-scaled (steady simple shear, for reports):
//     p_shear   = p   / (rho_p d^2 gammadot^2)
//     tau_shear = tau / (rho_p d^2 gammadot^2)     (tau = -sigma_xy)
//     t_shear   = T   / (d gammadot)^2
// extract writes them, tabulate tables them, compare predicts them, engines/closures'
// TabulatedClosure turns the theta forms back into SI values; all through these functions, so
// the arithmetic (and with it every recorded digit) is the same everywhere.
#include <array>
#include <optional>
#include <string_view>

namespace grainbridge::core {

enum class ClosureForm { PTheta, EtaTheta, JTheta, PShear, TauShear, TShear };

struct ClosureFormInfo {
  ClosureForm form;
  std::string_view name;   // the closure-point column and table quantity ("p_theta")
  std::string_view label;   // its definition, for a figure's title ("p / (ρ θ)", UTF-8)
  std::string_view symbol;  // for an axis or a table heading ("p*", "p/(ρθ)")
  bool thetaScaled;
  // The power of the granular temperature in the form's scale (p_theta 1, eta_theta 1/2,
  // j_theta 3/2): how the temperature's error enters the form's (0 for shear forms).
  double temperaturePower;
};

// The state a form is scaled with, in SI.
struct ClosureFormState {
  double density = 0.0;              // rho_p, material density of a grain
  double diameter = 0.0;             // d
  double granularTemperature = 0.0;  // theta (T)
  double shearRate = 0.0;            // |gammadot| (shear forms only)
};

// Every form, theta-scaled first.
[[nodiscard]] const std::array<ClosureFormInfo, 6>& closureForms();
[[nodiscard]] const ClosureFormInfo& closureFormInfo(ClosureForm form);
[[nodiscard]] std::optional<ClosureForm> closureFormFromName(std::string_view name);

// An SI value (for t_shear the temperature itself) as the form at this state.
[[nodiscard]] double toClosureForm(ClosureForm form, double value, const ClosureFormState& state);
// A theta-scaled form back to its SI value at this state (a continuum engine's use).
[[nodiscard]] double fromClosureForm(ClosureForm form, double formValue, const ClosureFormState& state);

// A time average with its block-averaging standard error.
struct MeasuredValue {
  double mean = 0.0;
  double error = 0.0;
};
// The standard error of the form of `value` at a state whose temperature is `temperature`:
// relative errors of the value and of theta^power added in quadrature (covariances neglected);
// a shear form's scale carries no measured temperature, so its error is the value's, scaled.
[[nodiscard]] double closureFormError(ClosureForm form, MeasuredValue value, MeasuredValue temperature,
                                      const ClosureFormState& state);

}  // namespace grainbridge::core
