// The closure forms of DESIGN.md, defined once (core/ClosureForms): each scales as written,
// the theta forms invert exactly enough for an engine, shear forms refuse to be turned into SI
// by temperature, and errors propagate as relative errors in quadrature.
#include <gtest/gtest.h>

#include <cmath>

#include "core/ClosureForms.hpp"
#include "core/Error.hpp"

using namespace grainbridge::core;

namespace {

const ClosureFormState kState{2500.0, 2e-3, 0.04, 50.0};

TEST(ClosureForms, ScaleAsDesignWritesThem) {
  EXPECT_NEAR(toClosureForm(ClosureForm::PTheta, 100.0, kState), 100.0 / (2500.0 * 0.04), 1e-15);
  EXPECT_NEAR(toClosureForm(ClosureForm::EtaTheta, 0.3, kState), 0.3 / (2500.0 * 2e-3 * 0.2), 1e-15);
  EXPECT_NEAR(toClosureForm(ClosureForm::JTheta, 900.0, kState), 900.0 * 2e-3 / (2500.0 * 0.008), 1e-13);
  const double shearScale = 2500.0 * 4e-6 * 2500.0;  // rho d^2 gammadot^2
  EXPECT_NEAR(toClosureForm(ClosureForm::PShear, 100.0, kState), 100.0 / shearScale, 1e-15);
  EXPECT_NEAR(toClosureForm(ClosureForm::TShear, 0.04, kState), 0.04 / (4e-6 * 2500.0), 1e-15);
  for (const auto& f : closureForms()) EXPECT_EQ(closureFormFromName(f.name), f.form) << f.name;
  EXPECT_FALSE(closureFormFromName("p_star").has_value());
}

TEST(ClosureForms, ThetaFormsRoundTripAndShearFormsDoNotInvert) {
  for (const auto form : {ClosureForm::PTheta, ClosureForm::EtaTheta, ClosureForm::JTheta}) {
    const double back = fromClosureForm(form, toClosureForm(form, 123.0, kState), kState);
    EXPECT_NEAR(back, 123.0, 1e-12) << closureFormInfo(form).name;
  }
  EXPECT_THROW((void)fromClosureForm(ClosureForm::PShear, 1.0, kState), grainbridge::Error);
}

TEST(ClosureForms, ErrorsAddRelativelyInQuadratureWithTheTemperaturePower) {
  // j_theta: 2 % on J and 1 % on theta (to the power 3/2): sqrt(0.02^2 + 0.015^2) = 2.5 %.
  const double j = toClosureForm(ClosureForm::JTheta, 900.0, kState);
  EXPECT_NEAR(closureFormError(ClosureForm::JTheta, {900.0, 18.0}, {0.04, 0.0004}, kState), 0.025 * j, 1e-12 * j);
  // A shear form's error is the value's, scaled: the scale holds no measured temperature.
  EXPECT_NEAR(closureFormError(ClosureForm::PShear, {100.0, 5.0}, {0.04, 0.01}, kState),
              toClosureForm(ClosureForm::PShear, 5.0, kState), 1e-18);
}

}  // namespace
