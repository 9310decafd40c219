// The closure loop end to end (VALIDATION.md, "Kinetic theory against DEM"): Lees-Edwards
// simple shear of frictionless spheres (e = 0.9, k* = 1e5, dt ~ t_c/50) at solid fractions
// 0.05, 0.1 and 0.2 -> extract -> compare. DEM pressure, shear stress and granular temperature
// in shear units agree with lun1984 within 15 %. A reduced version of the configs/ workflow
// (500 grains, 20 strain units discarded and 60 averaged, instead of 2000, 50 and 200) so it
// runs in CI; the closure points land in the database with their provenance.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>

#include "db/ClosureStore.hpp"
#include "db/Database.hpp"
#include "tests/support/Cli.hpp"
#include "tests/support/ValidationNote.hpp"
#include "tests/support/ValidationRecord.hpp"

using namespace grainbridge;
using namespace grainbridge::testing;
using nlohmann::json;
using ::testing::HasSubstr;

namespace {

// Box edge for 500 spheres of 1 mm at solid fraction phi.
std::string edge(double phi) {
  const double volume = 500.0 * M_PI / 6.0 / phi;  // mm^3
  std::ostringstream out;
  out.precision(6);
  out << std::cbrt(volume) << " mm";
  return out.str();
}

json workflow() {
  json boxes = json::array();
  for (double phi : {0.05, 0.1, 0.2}) boxes.push_back({edge(phi), edge(phi), edge(phi)});
  return {{"name", "kt"},
          {"stages",
           {{"shear",
             {{"type", "dem"},
              {"params",
               {{"box_lo", {0, 0, 0}},
                {"periodic", "xyz"},
                {"gravity", {0, 0, 0}},
                {"shear_rate", "100 1/s"},
                {"dt", "1e-6 s"},  // t_c = 5.09e-5 s: about t_c/50
                {"duration", "0.8 s"},
                {"frames", 320},
                {"series_points", 40},
                {"progress", false},
                {"species", {{{"name", "grain"}, {"diameter", "1 mm"}, {"density", "2500 kg/m3"}, {"count", 500}}}},
                // k* = k_n / (rho d^3 gammadot^2) = 2500 / (2500 * 1e-9 * 1e4) = 1e5
                {"contact", {{"kn", "2500 N/m"}, {"restitution", 0.9}, {"mu", 0}}}}},
              {"sweep", {{"box_hi", boxes}}}}},
            {"closure",
             {{"type", "extract"}, {"from", "shear"}, {"params", {{"family", "simple_shear"}, {"start_strain", 20}}}}},
            {"kt", {{"type", "compare"}, {"from", "closure"}}}}}};
}

}  // namespace

TEST(KineticTheoryAgreement, DiluteFrictionlessShearMatchesLun1984Within15Percent) {
  TempDir work;
  writeText(work.path() / "wf.json", workflow().dump(2));
  const auto r = runGrainbridge(work.path(), "run wf.json -q");
  ASSERT_EQ(r.exitCode, 0) << r.output;

  auto database = db::Database::openReadOnly(work.path() / "results/kt/grainbridge.sqlite");
  db::ClosureStore store(database);
  const auto points = store.query({});
  ASSERT_EQ(points.size(), 3u);
  for (const auto& p : points) {
    EXPECT_EQ(p["family"], "simple_shear");
    EXPECT_DOUBLE_EQ(p["restitution"].get<double>(), 0.9);
    EXPECT_EQ(p["stage"], "closure");
    EXPECT_EQ(p["frames"], 241);
  }

  // The comparison CSV: every lun1984 row in shear units within 15 %.
  std::string csv;
  for (const auto& e : std::filesystem::recursive_directory_iterator(work.path() / "results/kt/kt")) {
    if (e.path().filename() == "comparison.csv") csv = readText(e.path());
  }
  ASSERT_FALSE(csv.empty());
  std::istringstream lines(csv);
  std::string line;
  std::getline(lines, line);
  int checked = 0;
  while (std::getline(lines, line)) {
    std::vector<std::string> f;
    std::istringstream in(line);
    for (std::string c; std::getline(in, c, ',');) f.push_back(c);
    // solid_fraction,restitution,friction,shear_rate,quantity,dem,dem_err,model,prediction,deviation
    if (f[7] != "lun1984") continue;
    if (f[4] != "p_shear" && f[4] != "tau_shear" && f[4] != "t_shear") continue;
    const double deviation = std::stod(f[9]);
    RecordProperty(f[4] + "_" + f[0], f[9]);
    std::printf("solid fraction %s  %-9s DEM %s +- %s  lun1984 %s  deviation %+.3f\n", f[0].c_str(), f[4].c_str(),
                f[5].c_str(), f[6].c_str(), f[8].c_str(), deviation);
    EXPECT_LT(std::abs(deviation), 0.15) << line;
    const std::map<std::string, std::string> names = {
        {"p_shear", "pressure p* = p / (rho_p d^2 gammadot^2)"},
        {"tau_shear", "shear stress tau* = -sigma_xy / (rho_p d^2 gammadot^2)"},
        {"t_shear", "granular temperature T* = T / (d gammadot)^2"}};
    const double phi = std::stod(f[0]);  // the box edge is rounded: 0.0499996 for 0.05
    recordValidation({formatNote("kt.lun1984.%s.phi%.3g", f[4].c_str(), phi), "Kinetic theory against DEM",
                      formatNote("Lees-Edwards simple shear of frictionless spheres, e = 0.9, solid fraction %.3g: "
                                 "DEM %s against lun1984",
                                 phi, names.at(f[4]).c_str()),
                      "Lun et al. 1984 (kinetic + collisional), model lun1984", std::stod(f[8]), std::stod(f[5]),
                      "15 %", std::abs(deviation) < 0.15,
                      formatNote("DEM standard error %s; solid fraction %s; reduced CI run: 500 spheres, k* = 1e5, "
                                 "dt ~ t_c/50, 20 strain units discarded, 60 averaged (the configs/ workflow: 2000, "
                                 "50, 200)",
                                 f[6].c_str(), f[0].c_str())});
    ++checked;
  }
  EXPECT_EQ(checked, 9);
}
