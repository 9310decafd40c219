// The extract stage's coarse-grained fields: one field frame per averaged frame and their time
// average with block-averaging errors (mean/fields.xmf), which is the per-cell mean of the
// frames it was made from.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "core/io/FieldFrameReader.hpp"
#include "tests/support/Cli.hpp"
#include "tests/support/TinyShear.hpp"

using namespace grainbridge;
using namespace grainbridge::testing;
using nlohmann::json;
namespace fs = std::filesystem;

namespace {

const core::data::NamedCellField& extra(const core::data::FieldFrame& f, const std::string& name) {
  for (const auto& e : f.extras) {
    if (e.name == name) return e;
  }
  throw std::runtime_error("no extra field " + name);
}

}  // namespace

TEST(ExtractFields, TheTimeAveragedFieldsAreTheCellMeansOfTheFrameFields) {
  TempDir work;
  json params = tinyShearDemParams();
  params["frames"] = 6;
  const json dem = {{"type", "dem"}, {"params", params}};
  const json x = {{"type", "extract"}, {"from", "shear"}, {"params", {{"grid_cells", {2, 2, 2}}}}};
  writeText(work.path() / "wf.json", json{{"name", "fields"}, {"stages", {{"shear", dem}, {"x", x}}}}.dump(2));
  const auto r = runGrainbridge(work.path(), "run wf.json -q");
  ASSERT_EQ(r.exitCode, 0) << r.output;

  fs::path dir;
  for (const auto& e : fs::directory_iterator(work.path() / "results/fields/x")) dir = e.path();
  const auto frames = core::io::listFieldFrames(dir);
  ASSERT_EQ(frames.size(), 7u);  // the initial frame and 6 more
  const auto means = core::io::listFieldFrames(dir / "mean");
  ASSERT_EQ(means.size(), 1u);
  EXPECT_TRUE(fs::exists(dir / "mean/fields.xmf"));
  const auto mean = core::io::readFieldFrame(means.front());

  std::vector<double> sum(8, 0.0), theta(8, 0.0);
  int thetaErrors = 0;
  for (const auto& path : frames) {
    const auto f = core::io::readFieldFrame(path);
    for (std::size_t c = 0; c < 8; ++c) {
      sum[c] += extra(f, "solid_fraction").values[c];
      theta[c] += f.solids.at(0).theta[c];
    }
  }
  for (std::size_t c = 0; c < 8; ++c) {
    EXPECT_NEAR(extra(mean, "solid_fraction").values[c], sum[c] / 7.0, 1e-12);
    EXPECT_NEAR(mean.solids.at(0).theta[c], theta[c] / 7.0, 1e-12 * std::abs(theta[c]));
    EXPECT_GE(extra(mean, "solid_fraction_err").values[c], 0.0);
    EXPECT_GE(extra(mean, "grain_theta_err").values[c], 0.0);
    thetaErrors += extra(mean, "grain_theta_err").values[c] > 0.0 ? 1 : 0;
  }
  // Grains gain temperature only by colliding, so a cell whose grains have not collided yet keeps
  // T = 0 in every frame; the others fluctuate.
  EXPECT_GT(thetaErrors, 0);
  std::ifstream manifest(dir / "manifest.json");
  const auto artifacts = json::parse(manifest).at("artifacts").dump();
  EXPECT_NE(artifacts.find("mean/fields.xmf"), std::string::npos) << artifacts;
}
