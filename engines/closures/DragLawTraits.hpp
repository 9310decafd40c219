#pragma once
// What a gas-solids drag law declares beside its evaluate(): its parameters, a condition on
// them, and where it switches branch. The closure catalog (`grainbridge closures`), the mfm and
// tfdem stages and the generic drag tests (tests/engines/closures/DragLawsTest.cpp) read these
// declarations, so each is written once (STYLE.md 5; docs/adding-a-drag-law.md).
#include <string>

#include "engines/closures/DragState.hpp"

namespace grainbridge::closures {

// One parameter of a law whose parameters are `Params`: a double member, its default being the
// law's default-constructed value.
template <class Params>
struct DragParameter {
  const char* key;         // its name in `grainbridge closures eval LAW key=...`
  double Params::*member;  // the member of Params it sets
  bool positive;           // range: > 0 when true, any number otherwise
  const char* doc;         // one line, citing the equation it enters
  // The key of the mfm and tfdem stages that sets it ("drag_c"), or nullptr when the stages run
  // the law's default.
  const char* stageKey = nullptr;
};

// Why a law cannot use a parameter set (a condition its parameters must meet beyond their
// ranges, such as Eq. 3.14): the parameter to change and the reason; `why` empty when usable.
struct DragParamsProblem {
  std::string key;
  std::string why;
};

// A void fraction at which a law switches branch (Eq. 3.13 at 0.85, Eq. 7.30 at 0.8), and the
// relative jump of beta there, (beta(eps_g+) - beta(eps_g)) / beta(eps_g), at
// switchReferenceState() with the law's default parameters: 0 for a switch that is continuous
// by construction, the documented size for one that is not (the tests assert it).
struct DragSwitch {
  double voidFraction;
  double relativeJump;
};

// The state a DragSwitch's jump is stated at: 2.5 mm particles slipping at 1 m/s through air
// (VALIDATION.md's 1.2 kg/m^3 and 1.8e-5 Pa s), eps_s = 1 - eps_g; Re = 167 eps_g at most, so
// no Reynolds-number switch (Eq. 7.31 at 1000) lies near it.
[[nodiscard]] constexpr DragState switchReferenceState(double voidFraction) {
  return {voidFraction, 1.0 - voidFraction, 2.5e-3, 1.2, 1.8e-5, 1.0};
}

// The law's own check when it declares one (static DragParamsProblem check(const Params&)).
template <class Law>
[[nodiscard]] DragParamsProblem paramsProblem(const typename Law::Params& params) {
  if constexpr (requires { Law::check(params); }) {
    return Law::check(params);
  } else {
    return {};
  }
}

}  // namespace grainbridge::closures
