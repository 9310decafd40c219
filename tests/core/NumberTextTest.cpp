// Numbers for people (humanNumber, humanText) and for programs (roundTripText).
#include "core/text/NumberText.hpp"

#include <gtest/gtest.h>

#include <cstdlib>

using grainbridge::core::humanNumber;
using grainbridge::core::humanText;
using grainbridge::core::humanWithError;
using grainbridge::core::roundTripText;
using nlohmann::json;

TEST(NumberText, HumanNumberDropsBinaryNoise) {
  // 13.7823 mm converted to metres is not the double nearest 0.0137823.
  const double metres = 13.7823 * 1e-3;
  ASSERT_NE(metres, 0.0137823);
  EXPECT_EQ(humanNumber(metres), "0.0137823");
  EXPECT_EQ(humanNumber(0.1 + 0.2), "0.3");
  EXPECT_EQ(humanNumber(2500.0), "2500");
  EXPECT_EQ(humanNumber(-0.0), "0");
}

TEST(NumberText, HumanNumberShortensExponents) {
  EXPECT_EQ(humanNumber(1e-6), "1e-6");
  EXPECT_EQ(humanNumber(5.0963e-5), "5.0963e-5");
  EXPECT_EQ(humanNumber(1.5e7), "1.5e7");
  EXPECT_EQ(humanNumber(-2.25e-12), "-2.25e-12");
  EXPECT_EQ(humanNumber(123456789.0, 3), "1.23e8");
}

TEST(NumberText, RoundTripTextParsesBackExactly) {
  for (double v : {13.7823 * 1e-3, 0.1 + 0.2, 1.0 / 3.0, 6.02214076e23, 5e-324}) {
    const std::string s = roundTripText(v);
    EXPECT_EQ(std::strtod(s.c_str(), nullptr), v) << s;
  }
  EXPECT_EQ(roundTripText(0.25), "0.25");
}

TEST(NumberText, HumanWithErrorRoundsToTheError) {
  EXPECT_EQ(humanWithError(0.9265255584587488, 0.02371388719535832), "0.927 ± 0.024");
  EXPECT_EQ(humanWithError(6.261380592514366, 0.07088067392045917), "6.261 ± 0.071");
  EXPECT_EQ(humanWithError(641.7817705645383, 37.59329853770395), "642 ± 38");
  EXPECT_EQ(humanWithError(123456.0, 4100.0), "1.235e5 ± 4.1e3");
  // A rounding-level error (a constant box's solid fraction) is not shown.
  EXPECT_EQ(humanWithError(0.30000367119878024, 1.2735131497718753e-17), "0.300004");
  EXPECT_EQ(humanWithError(2.5e-9, 1.2e-10), "2.5e-9 ± 1.2e-10");
  EXPECT_EQ(humanWithError(0.5, 0.0), "0.5");
}

TEST(NumberText, HumanTextShowsValuesAsWritten) {
  EXPECT_EQ(humanText(json("13.7823 mm")), "13.7823 mm");
  EXPECT_EQ(humanText(json(0.8)), "0.8");
  EXPECT_EQ(humanText(json(3)), "3");
  EXPECT_EQ(humanText(json::array({"13.7823 mm", "13.7823 mm", "13.7823 mm"})), "13.7823 mm (×3)");
  EXPECT_EQ(humanText(json::array({0.0137823 * 1.0000000000000002, 0.02})), "[0.0137823, 0.02]");
  EXPECT_EQ(humanText(json::array()), "[]");
  EXPECT_EQ(humanText(json(true)), "true");
}
