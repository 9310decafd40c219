// A binary mixture's solids stresses in the multi-fluid model (issue 55) at one cell, against hand
// evaluations: the kinetic pressure under both mixture forms of the kinetic theory (summed, MFiX's
// since 2005; per_phase, Eqs. 3.21-3.25, 5.7 as printed), and the plastic regime and Eq. 3.68's
// packed fraction under a packing limit by composition (Yu-Standish).
#include <gtest/gtest.h>

#include <cmath>

#include "engines/closures/MixturePacking.hpp"
#include "engines/fluid/SimpleStep.hpp"
#include "engines/fluid/StaggeredGrid.hpp"
#include "engines/mfm/MultiFluidModel.hpp"
#include "engines/mfm/SolidsPairs.hpp"

using namespace grainbridge;

namespace {

constexpr double kSmall = 1.52e-3, kLarge = 2.49e-3, kRho = 2524.0, kE = 0.97;

mfm::MultiFluidParams binaryParams() {
  mfm::MultiFluidParams p;
  p.solids = {mfm::SolidsPhase{"small", kSmall, kRho, kE}, mfm::SolidsPhase{"large", kLarge, kRho, kE}};
  p.radialDistribution = mfm::RadialDistributionModel::Lebowitz;
  p.solidsPairs = mfm::solidsPairsFor(p.solids, {}).pairs;
  p.plastic.params.criticalVoidFraction = 0.417;
  return p;
}

// One cell holding `small` and `large` at granular temperatures thetaSmall, thetaLarge, at rest.
struct OneCell {
  fluid::StaggeredGrid grid;
  fluid::FlowState state;
  std::size_t c;
  OneCell(double small, double large, double thetaSmall, double thetaLarge)
      : grid(core::data::GridGeometry{Vec3::Zero(), Vec3(0.01, 0.01, 0.01), {1, 1, 1}}),
        state(grid, 3),
        c(grid.index(0, 0, 0)) {
    state.phases[0].fraction[c] = 1.0 - small - large;
    state.phases[1].fraction[c] = small;
    state.phases[2].fraction[c] = large;
    state.phases[1].granularTemperature[c] = thetaSmall;
    state.phases[2].granularTemperature[c] = thetaLarge;
    state.pressure[c] = 101325.0;
  }
  fluid::FlowProperties evaluate(const mfm::MultiFluidModel& model) const {
    fluid::FlowProperties p;
    for (int m = 0; m < 3; ++m) {
      p.phases.emplace_back(grid);
      p.dragCoefficient.emplace_back(grid);
    }
    for (const auto& [l, m] : model.solidsPairs()) p.solidsDrag.emplace_back(grid, l, m);
    if (model.packedFractionByCell()) p.packedFraction.emplace(grid, 0.0);
    model.evaluate(state, p);
    return p;
  }
};

// Lebowitz (1964) as MFiX writes it: g0_lm = 1/eps_g + 3 d_l d_m / (eps_g^2 (d_l + d_m)) sum_k eps_k / d_k.
double lebowitz(double epsSmall, double epsLarge, double dl, double dm) {
  const double epsG = 1.0 - epsSmall - epsLarge;
  return 1.0 / epsG + 3.0 * dl * dm / (epsG * epsG * (dl + dm)) * (epsSmall / kSmall + epsLarge / kLarge);
}

// Lun et al.'s pressure, p = rho eps theta (1 + 4 eta S), eta = (1 + e) / 2, S the contact sum.
double lunPressure(double eps, double theta, double contactSum) {
  return kRho * eps * theta * (1.0 + 4.0 * 0.5 * (1.0 + kE) * contactSum);
}

}  // namespace

TEST(MixtureModel, TheSummedFormsPressureCountsContactsWithEveryPhase) {
  const double es = 0.2, el = 0.15, ts = 0.02, tl = 0.01;
  const OneCell cell(es, el, ts, tl);
  const mfm::MultiFluidModel model(binaryParams());
  const auto p = cell.evaluate(model);
  const double sumSmall = es * lebowitz(es, el, kSmall, kSmall) + el * lebowitz(es, el, kSmall, kLarge);
  const double sumLarge = es * lebowitz(es, el, kLarge, kSmall) + el * lebowitz(es, el, kLarge, kLarge);
  EXPECT_NEAR(p.phases[1].solidsPressure[cell.c], lunPressure(es, ts, sumSmall), 1e-12 * lunPressure(es, ts, sumSmall));
  EXPECT_NEAR(p.phases[2].solidsPressure[cell.c], lunPressure(el, tl, sumLarge), 1e-12 * lunPressure(el, tl, sumLarge));
  EXPECT_EQ(p.phases[1].plasticPressure[cell.c], 0.0);  // eps_g 0.65 > eps_g*
}

TEST(MixtureModel, ThePerPhaseFormsPressureCountsContactsWithItsOwnKind) {
  const double es = 0.2, el = 0.15, ts = 0.02, tl = 0.01;
  const OneCell cell(es, el, ts, tl);
  auto params = binaryParams();
  params.mixtureKineticTheory = mfm::MixtureKineticTheory::PerPhase;
  const mfm::MultiFluidModel model(params);
  const auto p = cell.evaluate(model);
  const double ownSmall = es * lebowitz(es, el, kSmall, kSmall);  // eps_sm g0_mm
  const double ownLarge = el * lebowitz(es, el, kLarge, kLarge);
  EXPECT_NEAR(p.phases[1].solidsPressure[cell.c], lunPressure(es, ts, ownSmall), 1e-12 * lunPressure(es, ts, ownSmall));
  EXPECT_NEAR(p.phases[2].solidsPressure[cell.c], lunPressure(el, tl, ownLarge), 1e-12 * lunPressure(el, tl, ownLarge));
  // Fewer contacts counted: a lower pressure than the summed form's.
  const auto summed = cell.evaluate(mfm::MultiFluidModel(binaryParams()));
  EXPECT_LT(p.phases[1].solidsPressure[cell.c], summed.phases[1].solidsPressure[cell.c]);
}

TEST(MixtureModel, AYuStandishCellIsViscousWhereTheFixedLimitIsPlastic) {
  // 0.3 + 0.3: eps_g 0.4, below the fixed 0.417 but above the mixture's 0.385 (maxima 0.6).
  const OneCell cell(0.3, 0.3, 1e-4, 1e-4);
  const auto fixed = cell.evaluate(mfm::MultiFluidModel(binaryParams()));
  EXPECT_GT(fixed.phases[1].plasticPressure[cell.c], 0.0);
  EXPECT_FALSE(fixed.packedFraction.has_value());  // the settings' eps_p holds

  auto params = binaryParams();
  params.packingLimit = closures::PackingLimit::YuStandish;
  const mfm::MultiFluidModel model(params);
  ASSERT_TRUE(model.packedFractionByCell());
  const double expected = closures::yuStandishPacking(
      std::array<double, 2>{0.3, 0.3}, std::vector<double>{kSmall, kLarge}, std::vector<double>{0.6, 0.6});
  EXPECT_DOUBLE_EQ(model.criticalVoidFraction(cell.state, cell.c), 1.0 - expected);
  const auto p = cell.evaluate(model);
  EXPECT_EQ(p.phases[1].plasticPressure[cell.c], 0.0);
  EXPECT_EQ(p.phases[2].plasticPressure[cell.c], 0.0);
  ASSERT_TRUE(p.packedFraction.has_value());
  EXPECT_DOUBLE_EQ((*p.packedFraction)[cell.c], expected);  // Eq. 3.68's eps_p of the cell

  // Packed past the mixture's limit (0.32 + 0.32: eps_g 0.36): P* of the cell's eps_g*, Eq. 3.26.
  const OneCell dense(0.32, 0.32, 1e-4, 1e-4);
  const double epsGStar = model.criticalVoidFraction(dense.state, dense.c);
  const auto q = dense.evaluate(model);
  const double pStar = 1e24 * std::pow(epsGStar - 0.36, 10.0);
  EXPECT_NEAR(q.phases[1].plasticPressure[dense.c], 0.32 * pStar, 1e-9 * 0.32 * pStar);
}

TEST(MixtureModel, OnePhaseUnderAPackingLimitKeepsTheFixedOne) {
  auto params = binaryParams();
  params.solids.resize(1);
  params.solidsPairs.clear();
  params.radialDistribution = mfm::RadialDistributionModel::CarnahanStarling;
  params.packingLimit = closures::PackingLimit::YuStandish;
  const mfm::MultiFluidModel model(params);
  EXPECT_FALSE(model.packedFractionByCell());
  const fluid::StaggeredGrid grid(core::data::GridGeometry{Vec3::Zero(), Vec3(0.01, 0.01, 0.01), {1, 1, 1}});
  fluid::FlowState state(grid, 2);
  state.phases[0].fraction[grid.index(0, 0, 0)] = 0.4;
  state.phases[1].fraction[grid.index(0, 0, 0)] = 0.6;
  EXPECT_EQ(model.criticalVoidFraction(state, grid.index(0, 0, 0)), 0.417);
}

// plastic_pressure per_phase (issue 56's diagnostic): a cell packed past eps_g* by a mostly-large
// mixture (0.55 + 0.05: eps_g 0.40 < 0.417). Shared, both phases feel P* of the cell (Eq. 3.26,
// eps_sm P*); per phase, each is at its own packing, eps_g of 1 - 0.55 and 1 - 0.05, both above
// eps_g*, so neither is plastic: the small phase is no longer pushed by the large one's packing.
TEST(MixtureModel, APerPhasePlasticPressureIsOfEachPhasesOwnPacking) {
  const OneCell cell(0.05, 0.55, 1e-4, 1e-4);
  const auto shared = cell.evaluate(mfm::MultiFluidModel(binaryParams()));
  const double pStar = 1e24 * std::pow(0.417 - 0.40, 10.0);
  EXPECT_NEAR(shared.phases[1].plasticPressure[cell.c], 0.05 * pStar, 1e-9 * 0.05 * pStar);
  EXPECT_NEAR(shared.phases[2].plasticPressure[cell.c], 0.55 * pStar, 1e-9 * 0.55 * pStar);
  auto params = binaryParams();
  params.plasticPressure = mfm::PlasticPressure::PerPhase;
  const auto perPhase = cell.evaluate(mfm::MultiFluidModel(params));
  EXPECT_EQ(perPhase.phases[1].plasticPressure[cell.c], 0.0);
  EXPECT_EQ(perPhase.phases[2].plasticPressure[cell.c], 0.0);
  EXPECT_LT(perPhase.phases[1].solidsPressure[cell.c], shared.phases[1].solidsPressure[cell.c]);

  // The large phase alone past eps_g* (0.60 + 0.01): P* of its own void fraction 0.40.
  const OneCell packed(0.01, 0.60, 1e-4, 1e-4);
  const auto own = packed.evaluate(mfm::MultiFluidModel(params));
  EXPECT_EQ(own.phases[1].plasticPressure[packed.c], 0.0);
  EXPECT_NEAR(own.phases[2].plasticPressure[packed.c], 0.60 * pStar, 1e-9 * 0.60 * pStar);
}
