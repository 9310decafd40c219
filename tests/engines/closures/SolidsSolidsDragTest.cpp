// Solids-solids drag, Eq. 3.18 (engines/closures/SolidsSolidsDrag): a hand value (python3) for
// the Goldschmidt binary bed, symmetry between the phases, linearity in the relative speed and
// in (1 + e_lm), the friction term, refusals.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "core/Error.hpp"
#include "engines/closures/SolidsSolidsDrag.hpp"

using namespace grainbridge;
using namespace grainbridge::closures;

namespace {

const SolidsSolidsDrag::Phase kSmall{0.2915, 2526.0, 1.52e-3};
const SolidsSolidsDrag::Phase kLarge{0.2915, 2526.0, 2.49e-3};
constexpr double kG0 = 7.427151803736866;  // Lebowitz g0_lm of this mixture

TEST(SolidsSolidsDrag, GoldschmidtBinaryHandValue) {
  const SolidsSolidsDrag drag{{0.15, 0.97}};
  EXPECT_NEAR(drag.evaluate(kSmall, kLarge, kG0, 0.3), 670235.7935338629, 1e-6);
}

TEST(SolidsSolidsDrag, SymmetricAndLinearWhereEq318IsLinear) {
  const SolidsSolidsDrag drag{{0.15, 0.97}};
  EXPECT_DOUBLE_EQ(drag.evaluate(kSmall, kLarge, kG0, 0.3), drag.evaluate(kLarge, kSmall, kG0, 0.3));
  EXPECT_NEAR(drag.evaluate(kSmall, kLarge, kG0, 0.6), 2.0 * drag.evaluate(kSmall, kLarge, kG0, 0.3), 1e-6);
  EXPECT_EQ(drag.evaluate(kSmall, kLarge, kG0, 0.0), 0.0);
  const SolidsSolidsDrag elastic{{0.15, 1.0}};
  EXPECT_NEAR(elastic.evaluate(kSmall, kLarge, kG0, 0.3) / drag.evaluate(kSmall, kLarge, kG0, 0.3), 2.0 / 1.97, 1e-14);
  // Friction adds C_f pi^2 / 8 to pi / 2.
  const SolidsSolidsDrag smooth{{0.0, 0.97}};
  EXPECT_NEAR(drag.evaluate(kSmall, kLarge, kG0, 0.3) / smooth.evaluate(kSmall, kLarge, kG0, 0.3),
              (M_PI / 2 + 0.15 * M_PI * M_PI / 8) / (M_PI / 2), 1e-14);
}

TEST(SolidsSolidsDrag, RefusesValuesOutOfRange) {
  const SolidsSolidsDrag drag{{0.15, 0.97}};
  EXPECT_THROW((void)drag.evaluate({0.3, -1.0, 1e-3}, kLarge, kG0, 0.3), Error);
  EXPECT_THROW((void)drag.evaluate(kSmall, kLarge, 0.0, 0.3), Error);
  EXPECT_THROW((void)drag.evaluate(kSmall, kLarge, kG0, -0.1), Error);
  try {
    (void)SolidsSolidsDrag{{0.1, 0.0}}.evaluate(kSmall, kLarge, kG0, 0.3);
    FAIL();
  } catch (const Error& e) {
    EXPECT_THAT(e.what(), ::testing::HasSubstr("e_lm must be in (0, 1]"));
  }
}

}  // namespace
