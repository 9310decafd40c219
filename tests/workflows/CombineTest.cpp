// configs/combine-smoke.json, the CI-sized grain-chaff combine (issue 29; Chapter 4, Table 4.4):
// 0.3 s of grain and chaff fed through the upper part of the left side into a 3D box of rising
// air. Each solids phase gains exactly what its feed carries, rho eps U A t, and keeps its balance
// to round-off, and so does the gas (1e-6 of its inflow, the bound); the grain falls from
// the feed and stays below the chaff; the 3D frames are written.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "tests/support/Cli.hpp"
#include "tests/support/TempDir.hpp"
#include "workflows/contract/NumericCsv.hpp"

using namespace grainbridge;
using namespace grainbridge::testing;
using nlohmann::json;
namespace fs = std::filesystem;

TEST(Combine, SmokeFeedsEachPhaseAsItsInletSaysAndKeepsEveryBalance) {
  TempDir work;
  fs::copy_file(sourceDir() / "configs/combine-smoke.json", work.path() / "combine.json");
  const auto r = runGrainbridge(work.path(), "run combine.json -q");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  fs::path run;
  for (const auto& e : fs::directory_iterator(work.path() / "results/combine-smoke/combine")) {
    if (e.is_directory() && e.path().extension() != ".partial") run = e.path();
  }
  const json summary = json::parse(readText(run / "manifest.json")).at("summary");
  // The feed: 12 cm of the left side's height over its 60 cm width, at 0.1 m/s for 0.3 s.
  const double area = 0.12 * 0.60, t = 0.3;
  const double grainFed = 1491.8 * 0.05 * 0.1 * area * t, chaffFed = 40.6 * 0.55 * 0.1 * area * t;
  EXPECT_NEAR(summary.at("mass_in_grain").get<double>(), grainFed, 1e-9 * grainFed);
  EXPECT_NEAR(summary.at("mass_in_chaff").get<double>(), chaffFed, 1e-9 * chaffFed);
  for (const char* phase : {"grain", "chaff"}) {
    EXPECT_LT(std::abs(summary.at(std::string("mass_balance_") + phase).get<double>()), 1e-12) << phase;
  }
  // Grain falls from the feed (terminal speed about 7 m/s against 0.85 m/s of air) and none of
  // it leaves; the chaff stays above it.
  EXPECT_LT(summary.at("mass_out_grain").get<double>(), 1e-9 * grainFed);
  EXPECT_GT(summary.at("mean_height_chaff").get<double>(), summary.at("mean_height_grain").get<double>());

  const auto series = workflows::contract::readNumericCsv(run / "series.csv");
  const auto& time = series.at("time");
  ASSERT_EQ(time.size(), 30u);
  EXPECT_LT(series.at("mean_height_grain").back(), series.at("mean_height_grain")[4]);
  // The gas: its balance over the run, and every step from 0.2 s on to round-off.
  const auto gasError = [&](std::size_t k) {
    return series.at("mass_gas")[k] - series.at("mass_in_gas")[k] + series.at("mass_out_gas")[k];
  };
  const std::size_t from = 19, to = time.size() - 1;  // 0.2 s and 0.3 s
  ASSERT_NEAR(time[from], 0.2, 1e-9);
  const double inflow = series.at("mass_in_gas")[to] - series.at("mass_in_gas")[from];
  EXPECT_LT(std::abs(gasError(to) - gasError(from)), 1e-9 * inflow);
  EXPECT_LT(std::abs(summary.at("mass_balance_gas").get<double>()), 1e-6);
  // 3D frames, ParaView's way in.
  EXPECT_TRUE(fs::exists(run / "fields.xmf"));
  EXPECT_TRUE(fs::exists(run / "mean/fields.xmf"));
}
