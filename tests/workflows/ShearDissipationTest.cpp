// The dissipation rate of a sheared closure point (extract impl_version 4). Under Lees-Edwards
// shear the closure's J is the work done by the shear, -sigma_xy gammadot: in steady state that
// is the whole dissipation. The contacts' dashpot forces account for all of it only without
// friction; with friction the Coulomb sliding loss and the tangential spring energy carried off
// by opening contacts are not in the dashpots (in the 2000-grain sweep at friction 0.5 the
// dashpots took 9-56 % of the shear work). The frictionless case is the energy balance of
// VALIDATION.md (Lees-Edwards simple shear: sigma_xy gammadot V equals the dissipation rate).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <sstream>

#include "db/ClosureStore.hpp"
#include "db/Database.hpp"
#include "tests/support/Cli.hpp"

using namespace grainbridge;
using namespace grainbridge::testing;
using nlohmann::json;

namespace {

// 300 spheres of 1 mm at solid fraction 0.1, e = 0.9, k* = 1e5, dt ~ t_c/50; friction swept
// over 0 and 0.5; 10 strain units discarded, 30 averaged.
json workflow() {
  std::ostringstream edge;
  edge.precision(6);
  edge << std::cbrt(300.0 * M_PI / 6.0 / 0.1) << " mm";
  return {
      {"name", "dissipation"},
      {"stages",
       {{"shear",
         {{"type", "dem"},
          {"params",
           {{"box_lo", {0, 0, 0}},
            {"box_hi", {edge.str(), edge.str(), edge.str()}},
            {"periodic", "xyz"},
            {"gravity", {0, 0, 0}},
            {"shear_rate", "100 1/s"},
            {"dt", "1e-6 s"},
            {"duration", "0.4 s"},
            {"frames", 200},
            {"series_points", 20},
            {"progress", false},
            {"initial_temperature", "0.01 m2/s2"},
            {"species", {{{"name", "grain"}, {"diameter", "1 mm"}, {"density", "2500 kg/m3"}, {"count", 300}}}},
            {"contact", {{"kn", "2500 N/m"}, {"restitution", 0.9}, {"mu", 0}}}}},
          {"sweep", {{"contact/mu", {0, 0.5}}}}}},
        {"closure",
         {{"type", "extract"}, {"from", "shear"}, {"params", {{"family", "simple_shear"}, {"start_strain", 10}}}}}}}};
}

}  // namespace

TEST(ShearDissipation, TheClosureDissipationIsTheShearWorkAndTheDashpotsMissTheFrictionalLosses) {
  TempDir work;
  writeText(work.path() / "wf.json", workflow().dump(2));
  const auto r = runGrainbridge(work.path(), "run wf.json -q");
  ASSERT_EQ(r.exitCode, 0) << r.output;

  auto database = db::Database::openReadOnly(work.path() / "results/dissipation/grainbridge.sqlite");
  db::ClosureStore store(database);
  const auto points = store.query({});
  ASSERT_EQ(points.size(), 2u);
  for (const auto& p : points) {
    const double mu = p["friction"].get<double>();
    const double gammadot = p["shear_rate"].get<double>();
    const double J = p["dissipation_rate"].get<double>();
    const double shearWork = p["shear_stress"].get<double>() * gammadot;
    ASSERT_GT(shearWork, 0.0);
    EXPECT_NEAR(J, shearWork, 1e-12 * shearWork);
    EXPECT_NEAR(p["dissipation_rate_err"].get<double>(), p["shear_stress_err"].get<double>() * gammadot,
                1e-12 * shearWork);
    const double d = p["diameter"].get<double>(), rho = p["density"].get<double>();
    const double T = p["granular_temperature"].get<double>();
    EXPECT_NEAR(p["j_theta"].get<double>(), J * d / (rho * std::pow(T, 1.5)), 1e-12 * p["j_theta"].get<double>());

    // The dense-flow variables (extract impl 7): I = gammadot d / sqrt(p / rho), tau / p, and
    // the ratio's error smaller than quadrature of the two relative errors would say, as the
    // frames' shear stress and pressure rise and fall together.
    const double P = p["pressure"].get<double>(), tau = p["shear_stress"].get<double>();
    const double I = p["inertial_number"].get<double>();
    EXPECT_NEAR(I, gammadot * d / std::sqrt(P / rho), 1e-12 * I);
    EXPECT_NEAR(p["inertial_number_err"].get<double>(), 0.5 * I * p["pressure_err"].get<double>() / P, 1e-12 * I);
    const double ratio = p["stress_ratio"].get<double>();
    EXPECT_NEAR(ratio, tau / P, 1e-12 * ratio);
    const double ratioErr = p["stress_ratio_err"].get<double>();
    const double quadrature = ratio * std::hypot(p["shear_stress_err"].get<double>() / tau, p["pressure_err"].get<double>() / P);
    std::printf("friction %g: I %.4g +- %.2g, tau/p %.4g +- %.2g (quadrature %.2g)\n", mu, I,
                p["inertial_number_err"].get<double>(), ratio, ratioErr, quadrature);
    EXPECT_GT(ratioErr, 0.0);
    EXPECT_LT(ratioErr, quadrature);

    const auto extra = json::parse(p["extra_json"].get<std::string>());
    EXPECT_EQ(extra.at("dissipation_rate_source"), "shear_work");
    const double dashpots = extra.at("dissipation_rate_dashpots").get<double>();
    const double dashpotsErr = extra.at("dissipation_rate_dashpots_err").get<double>();
    std::printf("friction %g: shear work %.5g +- %.2g W/m3, dashpots %.5g +- %.2g (ratio %.3f)\n", mu, shearWork,
                p["shear_stress_err"].get<double>() * gammadot, dashpots, dashpotsErr, dashpots / shearWork);
    if (mu == 0.0) {
      // Frictionless: the dashpots are the whole loss, so the two agree (energy balance) within
      // three combined standard errors.
      const double sigma = std::hypot(dashpotsErr, p["dissipation_rate_err"].get<double>());
      EXPECT_NEAR(dashpots, shearWork, 3.0 * sigma);
    } else {
      // Friction 0.5: a large part of the loss is not in the dashpots.
      EXPECT_LT(dashpots, 0.8 * shearWork);
      EXPECT_GT(dashpots, 0.0);
    }
  }
}
