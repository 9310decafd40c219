// The multi-fluid engine as the driver runs it: a checkpointed and resumed run repeats the
// uninterrupted one bit for bit (the adaptive step's state travels in the checkpoint), and a
// column of gas alone at rest stays at rest under gravity (the hydrostatic pressure is a
// discrete solution, not an approximate one).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "engines/mfm/MfmEngine.hpp"
#include "tests/engines/mfm/GrainBed.hpp"
#include "tests/support/TempDir.hpp"

using namespace grainbridge;
using namespace grainbridge::testing;

namespace {

// The 4-wide fluidized grain bed as the driver runs it, output every 10 ms.
mfm::MultiFluidSetup fluidizedSetup() {
  GrainBedSpec spec;
  spec.nx = 4;
  spec.inflow = 1.2;
  spec.perturbation = 0.02;
  mfm::MultiFluidSetup setup = grainBed(spec).setup;
  setup.interval = 0.01;
  return setup;
}

std::function<void(mfm::MultiFluidEngine&)> fluidizedInitial() {
  return [](mfm::MultiFluidEngine& e) {
    GrainBedSpec spec;
    spec.nx = 4;
    spec.inflow = 1.2;
    spec.perturbation = 0.02;
    mfm::initialise(e, grainBed(spec).initial);
  };
}

void expectSameState(const fluid::FlowState& a, const fluid::FlowState& b) {
  EXPECT_EQ(a.time, b.time);
  EXPECT_EQ(a.pressure.values(), b.pressure.values());
  for (std::size_t m = 0; m < a.phases.size(); ++m) {
    EXPECT_EQ(a.phases[m].fraction.values(), b.phases[m].fraction.values()) << "phase " << m;
    EXPECT_EQ(a.phases[m].granularTemperature.values(), b.phases[m].granularTemperature.values()) << "phase " << m;
    for (std::size_t ax = 0; ax < 3; ++ax)
      EXPECT_EQ(a.phases[m].velocity[ax].values(), b.phases[m].velocity[ax].values()) << "phase " << m;
  }
}

}  // namespace

TEST(MfmEngine, ResumedRunRepeatsTheUninterruptedOneBitForBit) {
  TempDir dir;
  const auto setup = fluidizedSetup();
  const core::io::ArtifactStamp stamp{"test"};

  mfm::MfmEngine straight(setup, fluidizedInitial(), dir.path() / "a", stamp);
  for (int s = 0; s < 20; ++s) straight.advance(false);

  mfm::MfmEngine first(setup, fluidizedInitial(), dir.path() / "b", stamp);
  for (int s = 0; s < 10; ++s) first.advance(false);
  first.saveState(dir.path() / "state.h5", "key");
  auto resumed = mfm::MfmEngine::restore(setup, dir.path() / "state.h5", "key", dir.path() / "c", stamp);
  EXPECT_EQ(resumed->step(), 10);
  for (int s = 0; s < 10; ++s) resumed->advance(false);

  EXPECT_EQ(resumed->step(), straight.step());
  expectSameState(resumed->engine().state(), straight.engine().state());
  EXPECT_EQ(resumed->engine().statistics().steps, straight.engine().statistics().steps);
  EXPECT_THROW(mfm::MfmEngine::restore(setup, dir.path() / "state.h5", "another key", dir.path() / "d", stamp), Error);
}

// The same for a binary mixture (issue 26): the solids-solids drag and the mixture closures carry
// no state beyond the phases' fields, so the resumed run is the uninterrupted one.
TEST(MfmEngine, ABinaryBedResumesBitForBit) {
  TempDir dir;
  GrainBedSpec spec;
  spec.nx = 4;
  spec.inflow = 1.2;
  spec.perturbation = 0.02;
  GrainBed bed = binaryGrainBed(spec);
  bed.setup.interval = 0.01;
  const auto initial = [&](mfm::MultiFluidEngine& e) { mfm::initialise(e, bed.initial); };
  const core::io::ArtifactStamp stamp{"test"};

  mfm::MfmEngine straight(bed.setup, initial, dir.path() / "a", stamp);
  for (int s = 0; s < 20; ++s) straight.advance(false);
  mfm::MfmEngine first(bed.setup, initial, dir.path() / "b", stamp);
  for (int s = 0; s < 10; ++s) first.advance(false);
  first.saveState(dir.path() / "state.h5", "key");
  auto resumed = mfm::MfmEngine::restore(bed.setup, dir.path() / "state.h5", "key", dir.path() / "c", stamp);
  for (int s = 0; s < 10; ++s) resumed->advance(false);

  ASSERT_EQ(resumed->engine().state().phases.size(), 3u);
  expectSameState(resumed->engine().state(), straight.engine().state());
  EXPECT_EQ(resumed->engine().statistics().steps, straight.engine().statistics().steps);
}

TEST(MfmEngine, GasAloneAtRestStaysAtRest) {
  GrainBedSpec spec;
  spec.nx = 3;
  spec.bedCells = 0;  // no solids
  spec.inflow = 0.0;
  auto column = makeGrainBed(spec);
  column->advanceTo(0.2);
  double fastest = 0.0;
  for (const auto& phase : column->state().phases)
    for (const auto& v : phase.velocity)
      for (double u : v.values()) fastest = std::max(fastest, std::abs(u));
  // Round-off: the pressure, about 1e5 Pa, carries an error of machine epsilon times itself,
  // which accelerates the gas by at most that over rho h for the time run.
  const double roundOff = std::numeric_limits<double>::epsilon() * kOutletPressure * 0.2 / (kAirDensity * spec.cell);
  std::printf("largest velocity after 0.2 s: %.2e m/s (round-off scale %.2e m/s)\n", fastest, roundOff);
  EXPECT_LT(fastest, roundOff);
  // The pressure is hydrostatic: rho_g g per metre.
  const auto& p = column->state().pressure;
  EXPECT_NEAR(p(1, 0, 0) - p(1, 1, 0), kAirDensity * kGravity * spec.cell, 1e-9);
}

// An ideal gas fed through the bottom of a closed column: the mass it holds, rho V with
// rho = P M / (R T), grows by the inflow rho U A, so dP/dt = P U / H and P = P0 exp(U t / H)
// (the gas enters at the density of the cells it enters).
TEST(MfmEngine, AnIdealGasFedIntoAClosedColumnCompressesAsItsMassBalanceSays) {
  core::data::GridGeometry g;
  g.cells = {2, 8, 1};
  g.spacing = Vec3(0.01, 0.01, 0.01);
  fluid::BoundaryPatch inlet;
  inlet.kind = fluid::BoundaryKind::VelocityInlet;
  inlet.side = fluid::YLow;
  inlet.phases = {fluid::PhaseInflow{1.0, Vec3(0.0, 0.01, 0.0)}};
  mfm::MultiFluidParams model;
  model.gas.ideal = true;
  fluid::SimpleSettings settings;  // no gravity: a uniform pressure
  // The continuity residual bounds each step's error as a fraction of a cell's mass; this column
  // gains 1.25e-4 of its mass per 1 ms step, so the default 1e-4 would leave 4 % of the rise
  // unconverged (measured: 106309 Pa). A slow compression wants a tolerance well below its
  // relative change per step.
  settings.tolerance = 1e-8;
  fluid::TimeStepLimits limits;
  limits.initial = 1e-3;
  mfm::MultiFluidEngine column(g, {inlet}, model, settings, limits);
  for (std::size_t c = 0; c < column.grid().paddedCount(); ++c) column.state().pressure[c] = 101325.0;
  column.advanceTo(0.4);
  double mean = 0.0;
  for (int j = 0; j < 8; ++j)
    for (int i = 0; i < 2; ++i) mean += column.state().pressure(i, j, 0) / 16.0;
  const double expected = 101325.0 * std::exp(0.01 * 0.4 / 0.08);
  std::printf("closed ideal-gas column after 0.4 s: %.3f Pa against %.3f Pa\n", mean, expected);
  EXPECT_NEAR(mean, expected, 1e-4 * (expected - 101325.0));
}

// MFiX's stall detection (SimpleSettings::stallWindow): a step whose residual no longer falls is
// given up before max_iterations and retried at half the step; the step that cannot be retried
// (half of it below dt_min) runs to max_iterations, as MFiX forces the iterations at DT_MIN.
// A tolerance below round-off makes every step fail: 1e-4 and 5e-5 s are retried, 2.5e-5 s stops.
TEST(MfmEngine, AStalledStepIsGivenUpEarlyExceptAtTheSmallestStep) {
  const auto triedIterations = [](int stallWindow) {
    GrainBedSpec spec;
    spec.nx = 4;
    spec.inflow = 1.2;
    spec.perturbation = 0.02;
    const GrainBed bed = grainBed(spec);
    fluid::SimpleSettings settings = bed.setup.settings;
    settings.tolerance = 1e-300;
    settings.stallWindow = stallWindow;
    fluid::TimeStepLimits limits = bed.setup.limits;
    limits.initial = 1e-4;
    limits.minimum = 2.5e-5;
    mfm::MultiFluidEngine engine(bed.setup.geometry, bed.setup.patches, bed.setup.model, settings, limits);
    mfm::initialise(engine, bed.initial);
    std::string message;
    try {
      engine.advanceTo(1e-3);
    } catch (const Error& e) {
      message = e.what();
    }
    EXPECT_NE(message.find("after 50 iterations"), std::string::npos) << message;
    EXPECT_EQ(engine.statistics().retries, 3);  // the last one counted too, though not retried
    return engine.statistics().retriedIterations;
  };
  const long withoutDetection = triedIterations(0);
  const long withDetection = triedIterations(5);
  EXPECT_EQ(withoutDetection, 3 * 50);
  // Two steps given up at a multiple of 5 past the 10th, below the 50th; the third runs to 50.
  EXPECT_GE(withDetection, 2 * 15 + 50);
  EXPECT_LT(withDetection, 2 * 50 + 50);
  EXPECT_EQ((withDetection - 50) % 5, 0);
}
