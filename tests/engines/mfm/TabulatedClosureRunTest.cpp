// The `table` closure path of the multi-fluid model against the `ktgf` one (issue 18): a bed
// run with closure tables made from lun1984's own theta-scaled forms (p_theta, eta_theta,
// j_theta; gas coupling off, so they are exactly theta-scaled) reproduces the lun1984 run
// within the tables' interpolation error, which shrinks as the tables get finer.
#include <gtest/gtest.h>

#include <cmath>

#include "core/ClosureForms.hpp"
#include "engines/closures/Lun1984.hpp"
#include "engines/mfm/InitialRegions.hpp"
#include "tests/engines/mfm/GrainBed.hpp"

using namespace grainbridge;
using namespace grainbridge::testing;

namespace {

// One column of grains settling from a loose, agitated state onto a gas flow below minimum
// fluidization: one-dimensional, so it is not chaotic and two closures of nearly equal values
// give nearly equal fields.
GrainBed settlingColumn() {
  GrainBedSpec spec;
  spec.nx = 1;
  spec.ny = 16;
  spec.bedCells = 10;
  spec.voidFraction = 0.55;
  spec.inflow = 0.25;
  GrainBed bed = grainBed(spec);
  auto& model = bed.setup.model;
  model.granularEnergy = mfm::GranularEnergyForm::Pde;
  model.granularGasCoupling = false;
  for (auto& r : bed.initial.regions) r.granularTemperature = 0.05;
  return bed;
}

// lun1984's theta-scaled quantity `form` at solid fractions 0, h, 2h, ... up to 0.64.
core::ClosureTable lunTable(core::ClosureForm form, const std::string& quantity, double h) {
  std::vector<double> xs, values;
  const closures::Lun1984 lun;
  for (int k = 0; k * h <= 0.64 + 1e-12; ++k) {
    const double eps = k * h;
    const closures::KineticState s{eps, 1.0, kGrainDiameter, kGrainDensity, 0.9, 0.0};
    const auto t = lun.evaluate(s);
    const double si = form == core::ClosureForm::PTheta     ? t.pressure
                      : form == core::ClosureForm::EtaTheta ? t.shearViscosity
                                                            : t.dissipationRate;
    xs.push_back(eps);
    values.push_back(core::toClosureForm(form, si, {kGrainDensity, kGrainDiameter, 1.0}));
  }
  return core::ClosureTable(quantity, xs, "", {}, values);
}

closures::ClosureModel lunTables(double h) {
  using P = closures::OutOfRangePolicy;
  return closures::ClosureModel::tabulated(
      closures::KineticModelName::Lun1984,
      closures::TabulatedClosure(lunTable(core::ClosureForm::PTheta, "p_theta", h), P::Error),
      closures::TabulatedClosure(lunTable(core::ClosureForm::EtaTheta, "eta_theta", h), P::Error),
      closures::TabulatedClosure(lunTable(core::ClosureForm::JTheta, "j_theta", h), P::Error));
}

struct Difference {
  double fraction = 0.0;     // largest |eps_s(table) - eps_s(ktgf)|
  double temperature = 0.0;  // largest |theta difference| over the largest theta
};

Difference runAgainstKineticTheory(const closures::ClosureModel& closure) {
  GrainBed bed = settlingColumn();
  auto run = [&bed](const closures::ClosureModel& c) {
    bed.setup.model.closure = c;
    auto e = std::make_unique<mfm::MultiFluidEngine>(bed.setup.geometry, bed.setup.patches, bed.setup.model,
                                                     bed.setup.settings, bed.setup.limits);
    mfm::initialise(*e, bed.initial);
    e->advanceTo(0.15);
    return e;
  };
  const auto kt = run(closures::ClosureModel::kineticTheory());
  const auto table = run(closure);
  Difference d;
  double hottest = 0.0;
  const auto& a = kt->state().phases[1];
  const auto& b = table->state().phases[1];
  for (std::size_t c = 0; c < a.fraction.values().size(); ++c) {
    if (!kt->grid().interior(c)) continue;
    d.fraction = std::max(d.fraction, std::abs(a.fraction[c] - b.fraction[c]));
    d.temperature = std::max(d.temperature, std::abs(a.granularTemperature[c] - b.granularTemperature[c]));
    hottest = std::max(hottest, a.granularTemperature[c]);
  }
  d.temperature /= hottest;
  return d;
}

}  // namespace

TEST(TabulatedClosureRun, TablesOfLunsOwnFormsReproduceTheKineticTheoryRun) {
  const Difference coarse = runAgainstKineticTheory(lunTables(0.04));
  const Difference fine = runAgainstKineticTheory(lunTables(0.01));
  // Monotone cubic interpolation: a four times finer table cuts the difference about a hundred
  // times (measured at 0.15 s: theta 4.8e-3 -> 4.3e-5 of the largest, eps_s 6.5e-6 -> 2.0e-7),
  // so the runs differ by the tables' interpolation error and nothing else.
  EXPECT_LT(fine.fraction, 1e-6);
  EXPECT_LT(fine.temperature, 2e-4);
  EXPECT_LT(fine.temperature, 0.05 * coarse.temperature);
  EXPECT_GT(coarse.temperature, 0.0);
  std::printf("coarse (h 0.04): d eps %.3g, d theta/theta %.3g; fine (h 0.01): %.3g, %.3g\n", coarse.fraction,
              coarse.temperature, fine.fraction, fine.temperature);
}
