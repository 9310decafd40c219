// Table 7.1 gives TF-DEM's damping as dimensional dashpot coefficients (F = -eta v_n, in
// dyne s/cm), not as gamma_n (VALIDATION.md): with gamma_n = eta / m_eff, Eqs. 6.9-6.10 give
// the restitutions and contact times VALIDATION.md quotes. The units go through the config's
// unit system, so "18 dyne s/cm" is the value a config would write.
#include <gtest/gtest.h>

#include <cmath>
#include <variant>

#include "core/units/Quantity.hpp"
#include "engines/dem/Material.hpp"
#include "tests/engines/dem/DemTestSupport.hpp"

using namespace grainbridge;
using core::units::Dimension;

namespace {

double si(const char* text, Dimension dim) {
  return std::get<double>(core::units::parseQuantity(text, dim, core::units::UnitSystem::si()));
}

double sphereMass(double d, double density) { return density * M_PI / 6.0 * d * d * d; }

TEST(Table71Damping, RestitutionsAndContactTimesImpliedByTheDashpots) {
  const Dimension dashpot{0, 1, -1};  // kg/s
  const double k = si("8e5 dyne/cm", Dimension::stiffness());
  const double kWall = si("1.2e6 dyne/cm", Dimension::stiffness());
  const double jet = sphereMass(si("4 mm", Dimension::lengthDim()), si("2.7 g/cm3", Dimension::density()));
  const double uniform = sphereMass(si("2.5 mm", Dimension::lengthDim()), si("2.526 g/cm3", Dimension::density()));
  // Particle pairs (m_eff = m/2) and walls (m_eff = m), central jet then uniform inflow.
  const struct {
    const char* eta;
    double stiffness, meff, restitution;
  } cases[] = {{"18 dyne s/cm", k, jet / 2, 0.862},
               {"1.77 dyne s/cm", k, uniform / 2, 0.970},
               {"22 dyne s/cm", kWall, jet, 0.900},
               {"3.93 dyne s/cm", kWall, uniform, 0.962}};
  for (const auto& c : cases) {
    const double gammaN = si(c.eta, dashpot) / c.meff;
    EXPECT_NEAR(dem::linearRestitution(c.stiffness, gammaN, c.meff), c.restitution, 0.002) << c.eta;
  }
  // Contact times of the particle pairs: 7.48e-4 s (jet) and 3.57e-4 s (uniform).
  EXPECT_NEAR(dem::linearContactTime(k, si("18 dyne s/cm", dashpot) / (jet / 2), jet / 2), 7.48e-4, 0.01e-4);
  EXPECT_NEAR(dem::linearContactTime(k, si("1.77 dyne s/cm", dashpot) / (uniform / 2), uniform / 2), 3.57e-4, 0.01e-4);
}

// damping_model "dimensional" takes these coefficients as they are printed: with a linear spring,
// eta = gamma m_eff gives the same collision as mass_scaled damping (an oblique, spinning one, so
// both dashpots and the Coulomb cap act), to round-off.
TEST(Table71Damping, DimensionalDashpotsEqualMassScaledOnesWithALinearSpring) {
  const double m = dem::testing::sphereMass(1.0, 1.91);
  const double meff = 0.5 * m;
  auto collide = [&](const std::string& damping) {
    dem::PairMaterial mat = dem::testing::table61Particle();
    mat.gammaT = 20.0;
    if (damping == "dimensional") {
      mat.etaN = mat.gammaN * meff;
      mat.etaT = mat.gammaT * meff;
      mat.gammaN = mat.gammaT = 0.0;
    }
    dem::SimulationSetup setup = dem::testing::openBox(mat, 1, 1e-5);
    setup.contact.damping = damping;
    dem::Particles p;
    p.addOwned(0, 0, 0.5, m, Vec3(-0.51, 0.3, 0), Vec3(1, 0, 0), Vec3(0, 0, 5), false);
    p.addOwned(1, 0, 0.5, m, Vec3(0.51, 0, 0), Vec3(-1, 0, 0), Vec3::Zero(), false);
    dem::Simulation sim(setup, p);
    sim.run(4000);
    return sim.particles();
  };
  const auto a = collide("mass_scaled");
  const auto b = collide("dimensional");
  for (std::size_t i = 0; i < 2; ++i) {
    EXPECT_NEAR((a.v[i] - b.v[i]).norm(), 0.0, 1e-12) << i;
    EXPECT_NEAR((a.omega[i] - b.omega[i]).norm(), 0.0, 1e-10) << i;
  }
  EXPECT_GT((a.v[0] - Vec3(1, 0, 0)).norm(), 0.1);  // they did collide
}

}  // namespace
