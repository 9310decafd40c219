// A FlowState written into a group of an HDF5 file comes back exactly, ghosts included (a resumed
// run continues bit for bit from it), beside another group in the same file (a coupled engine's
// checkpoint); a state of another grid or phase count is refused naming the file.
#include "engines/fluid/FlowStateIo.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "core/Error.hpp"
#include "tests/support/TempDir.hpp"

namespace grainbridge::fluid {
namespace {

core::data::GridGeometry geometry(std::array<int, 3> cells) {
  core::data::GridGeometry g;
  g.spacing = Vec3(0.01, 0.02, 0.03);
  g.cells = cells;
  return g;
}

// Distinct, non-round values in every entry of every array, so a swapped, dropped or
// truncated array shows.
void fill(FlowState& st, double seed) {
  st.time = 0.1 + seed;
  double x = seed;
  auto next = [&x] { return x += 1.0 / 7.0; };
  for (auto& p : st.pressure.values()) p = 101325.0 + next();
  for (auto& phase : st.phases) {
    for (auto& v : phase.fraction.values()) v = next() * 1e-3;
    for (auto& v : phase.granularTemperature.values()) v = next() * 1e-5;
    for (auto& component : phase.velocity)
      for (auto& v : component.values()) v = -next();
  }
}

void expectEqual(const FlowState& a, const FlowState& b) {
  EXPECT_EQ(a.time, b.time);
  EXPECT_EQ(a.pressure.values(), b.pressure.values());
  ASSERT_EQ(a.phases.size(), b.phases.size());
  for (std::size_t m = 0; m < a.phases.size(); ++m) {
    EXPECT_EQ(a.phases[m].fraction.values(), b.phases[m].fraction.values()) << m;
    EXPECT_EQ(a.phases[m].granularTemperature.values(), b.phases[m].granularTemperature.values()) << m;
    for (std::size_t axis = 0; axis < 3; ++axis)
      EXPECT_EQ(a.phases[m].velocity[axis].values(), b.phases[m].velocity[axis].values()) << m << " " << axis;
  }
}

// A three-phase state on a 4 x 3 grid, filled, and a file to write it to.
class FlowStateIo : public ::testing::Test {
 protected:
  void SetUp() override { fill(written, 0.5); }
  void writeFile(const std::vector<std::pair<std::string, const FlowState*>>& groups) const {
    core::io::H5OutputFile f(path);
    for (const auto& [group, state] : groups) writeFlowState(f, group, *state);
    f.close();
  }
  const testing::TempDir dir;
  const std::filesystem::path path = dir.path() / "state.h5";
  const StaggeredGrid grid{geometry({4, 3, 1})};
  FlowState written{grid, 3};
};

TEST_F(FlowStateIo, RoundTripInAGroupBesideAnother) {
  FlowState other(grid, 2);
  fill(other, 9.0);
  writeFile({{"/fluid", &written}, {"/", &other}});
  const core::io::H5InputFile f(path);
  FlowState read(grid, 3);
  readFlowState(f, "/fluid", read);
  expectEqual(written, read);
  FlowState readRoot(grid, 2);
  readFlowState(f, "/", readRoot);
  expectEqual(other, readRoot);
}

TEST_F(FlowStateIo, AnotherGridOrPhaseCountIsRefused) {
  writeFile({{"/fluid", &written}});
  const core::io::H5InputFile f(path);
  const StaggeredGrid finer(geometry({5, 3, 1}));
  FlowState onFiner(finer, 3);
  EXPECT_THAT([&] { readFlowState(f, "/fluid", onFiner); },
              ::testing::ThrowsMessage<Error>(::testing::HasSubstr("/fluid/pressure")));
  FlowState fewerPhases(grid, 2);
  EXPECT_THAT([&] { readFlowState(f, "/fluid", fewerPhases); },
              ::testing::ThrowsMessage<Error>(::testing::HasSubstr("holds more than the 2 phases")));
  FlowState morePhases(grid, 4);
  EXPECT_THAT([&] { readFlowState(f, "/fluid", morePhases); },
              ::testing::ThrowsMessage<Error>(::testing::HasSubstr("/fluid/phase_3_fraction")));
}

}  // namespace
}  // namespace grainbridge::fluid
