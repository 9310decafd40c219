// Time-averaged coarse-grained fields: each cell value is the block average of its series
// (BlockAverage.hpp), errors come as "<slot>_err" extras, and frames that do not share a layout
// are refused.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "core/Error.hpp"
#include "core/averaging/BlockAverage.hpp"
#include "core/averaging/FieldTimeAverage.hpp"

namespace grainbridge::core::averaging {
namespace {

using core::data::FieldFrame;

const core::data::NamedCellField* extra(const FieldFrame& f, const std::string& name) {
  for (const auto& e : f.extras) {
    if (e.name == name) return &e;
  }
  return nullptr;
}

// A 2 x 1 x 2 grid with one phase "grain" and a scalar and a tensor extra, every value drawn
// from a correlated random walk (so the block errors are not the naive ones).
FieldFrame frame(std::int64_t step, std::mt19937_64& rng, std::vector<double>& state) {
  std::normal_distribution<double> noise(0.0, 1.0);
  for (double& s : state) s = 0.8 * s + noise(rng);
  std::size_t k = 0;
  auto next = [&] { return state[k++ % state.size()]; };
  FieldFrame f;
  f.time = 0.01 * static_cast<double>(step);
  f.step = step;
  f.grid.cells = {2, 1, 2};
  const std::size_t n = 4;
  for (std::size_t c = 0; c < n; ++c) {
    f.ep_g.push_back(0.6 + 0.01 * next());
    f.p_g.push_back(0.0);
    f.u_g.push_back(Vec3::Zero());
  }
  core::data::SolidsPhaseFields phase;
  phase.name = "grain";
  for (std::size_t c = 0; c < n; ++c) {
    phase.ep_s.push_back(0.4 + 0.01 * next());
    phase.u_s.push_back(Vec3(next(), next(), next()));
    phase.theta.push_back(2.0 + 0.1 * next());
  }
  f.solids.push_back(phase);
  core::data::NamedCellField pressure{"pressure", 1, {}}, stress{"stress", 9, {}};
  for (std::size_t c = 0; c < n; ++c) pressure.values.push_back(10.0 + next());
  for (std::size_t c = 0; c < 9 * n; ++c) stress.values.push_back(next());
  f.extras = {pressure, stress};
  return f;
}

TEST(FieldTimeAverage, EveryCellValueIsTheBlockAverageOfItsSeriesWithItsError) {
  std::mt19937_64 rng(5);
  std::vector<double> state(7, 0.0);
  FieldTimeAverage average;
  std::vector<FieldFrame> frames;
  for (std::int64_t s = 0; s < 64; ++s) {
    frames.push_back(frame(s, rng, state));
    average.add(frames.back());
  }
  const FieldFrame mean = average.mean();
  EXPECT_NO_THROW(mean.validate());
  EXPECT_EQ(mean.step, 63);
  EXPECT_EQ(mean.grid, frames.front().grid);

  auto series = [&](auto&& value) {
    std::vector<double> out;
    for (const auto& f : frames) out.push_back(value(f));
    return out;
  };
  // A scalar extra, a tensor component, a phase's temperature and velocity component, ep_g.
  for (std::size_t c = 0; c < 4; ++c) {
    const auto p = blockAverage(series([&](const FieldFrame& f) { return f.extras[0].values[c]; }));
    EXPECT_DOUBLE_EQ(extra(mean, "pressure")->values[c], p.mean);
    EXPECT_DOUBLE_EQ(extra(mean, "pressure_err")->values[c], p.standardError);
    const auto s = blockAverage(series([&](const FieldFrame& f) { return f.extras[1].values[9 * c + 5]; }));
    EXPECT_DOUBLE_EQ(extra(mean, "stress")->values[9 * c + 5], s.mean);
    EXPECT_DOUBLE_EQ(extra(mean, "stress_err")->values[9 * c + 5], s.standardError);
    const auto t = blockAverage(series([&](const FieldFrame& f) { return f.solids[0].theta[c]; }));
    EXPECT_DOUBLE_EQ(mean.solids[0].theta[c], t.mean);
    EXPECT_DOUBLE_EQ(extra(mean, "grain_theta_err")->values[c], t.standardError);
    const auto u = blockAverage(series([&](const FieldFrame& f) { return f.solids[0].u_s[c].y(); }));
    EXPECT_DOUBLE_EQ(mean.solids[0].u_s[c].y(), u.mean);
    EXPECT_DOUBLE_EQ(extra(mean, "grain_u_s_err")->values[3 * c + 1], u.standardError);
    const auto e = blockAverage(series([&](const FieldFrame& f) { return f.ep_g[c]; }));
    EXPECT_DOUBLE_EQ(mean.ep_g[c], e.mean);
    EXPECT_DOUBLE_EQ(extra(mean, "ep_g_err")->values[c], e.standardError);
    EXPECT_GT(extra(mean, "pressure_err")->values[c], 0.0);
  }
  ASSERT_NE(extra(mean, "grain_ep_s_err"), nullptr);
  EXPECT_EQ(extra(mean, "stress_err")->components, 9);
}

TEST(FieldTimeAverage, FramesOfAnotherLayoutAreRefusedNamingWhatDiffers) {
  std::mt19937_64 rng(1);
  std::vector<double> state(3, 0.0);
  FieldTimeAverage average;
  EXPECT_THAT([&] { (void)average.mean(); }, ::testing::ThrowsMessage<Error>(::testing::HasSubstr("no frame")));
  average.add(frame(0, rng, state));

  FieldFrame grid = frame(1, rng, state);
  grid.grid.spacing = Vec3(2, 1, 1);
  EXPECT_THAT([&] { average.add(grid); }, ::testing::ThrowsMessage<Error>(::testing::HasSubstr("different grid")));
  FieldFrame renamed = frame(2, rng, state);
  renamed.extras[1].name = "contact_stress";
  EXPECT_THAT([&] { average.add(renamed); },
              ::testing::ThrowsMessage<Error>(::testing::HasSubstr("extra field 'contact_stress'")));
  FieldFrame phase = frame(3, rng, state);
  phase.solids[0].name = "large";
  EXPECT_THAT([&] { average.add(phase); }, ::testing::ThrowsMessage<Error>(::testing::HasSubstr("phase 'large'")));
  EXPECT_EQ(average.frames(), 1u);  // a refused frame changes nothing
}

}  // namespace
}  // namespace grainbridge::core::averaging
