// Figs. 7.7b / 7.12b's time-averaged force ratio: the ratio of the mean forces per cell, not the
// mean of each frame's ratio (which counts the -1 of a frame without drag as a value).
#include "extract/observe/MeanForceRatio.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "core/averaging/FieldTimeAverage.hpp"

namespace grainbridge::extract::observe {
namespace {

// A one-row frame of three cells with the force fields FieldObserver writes.
core::data::FieldFrame forces(double time, std::vector<double> contact, std::vector<double> drag) {
  core::data::FieldFrame f;
  f.time = time;
  f.units = "SI";
  f.grid.cells = {3, 1, 1};
  f.grid.spacing = Vec3(0.01, 0.01, 0.01);
  f.ep_g.assign(3, 1.0);
  f.p_g.assign(3, 0.0);
  f.u_g.assign(3, Vec3::Zero());
  std::vector<double> ratio(3);
  for (std::size_t c = 0; c < 3; ++c) ratio[c] = drag[c] > 0.0 ? contact[c] / drag[c] : -1.0;
  f.extras.push_back({"contact_force", 1, std::move(contact)});
  f.extras.push_back({"drag_force", 1, std::move(drag)});
  f.extras.push_back({"contact_to_drag_ratio", 1, std::move(ratio)});
  return f;
}

const std::vector<double>& extra(const core::data::FieldFrame& f, const std::string& name) {
  for (const auto& e : f.extras) {
    if (e.name == name) return e.values;
  }
  throw std::runtime_error("no extra field " + name);
}

TEST(MeanForceRatio, IsTheRatioOfTheMeanForces) {
  core::averaging::FieldTimeAverage average;
  // Cell 0: drag in every frame; cell 1: drag in half of them; cell 2: never any drag.
  for (int k = 0; k < 8; ++k) {
    const bool even = k % 2 == 0;
    average.add(forces(0.1 * k, {even ? 1.0 : 3.0, 3.0, 2.0}, {1.0, even ? 1.0 : 0.0, 0.0}));
  }
  core::data::FieldFrame mean = average.mean();
  // The mean of the frames' ratios: (1 + 3) / 2 in cell 0, (3 - 1) / 2 in cell 1, -1 in cell 2.
  EXPECT_DOUBLE_EQ(extra(mean, "contact_to_drag_ratio")[1], 1.0);
  useRatioOfMeans(mean);
  const auto& ratio = extra(mean, "contact_to_drag_ratio");
  EXPECT_DOUBLE_EQ(ratio[0], 2.0);      // mean contact 2 over mean drag 1
  EXPECT_DOUBLE_EQ(ratio[1], 6.0);      // 3 over 0.5
  EXPECT_DOUBLE_EQ(ratio[2], -1.0);     // no drag at all
  const auto& error = extra(mean, "contact_to_drag_ratio_err");
  const auto& contactErr = extra(mean, "contact_force_err");
  const auto& dragErr = extra(mean, "drag_force_err");
  EXPECT_GT(error[0], 0.0);
  EXPECT_DOUBLE_EQ(error[0], 2.0 * std::abs(contactErr[0] / 2.0));  // the drag is constant there
  EXPECT_DOUBLE_EQ(error[1], 6.0 * std::abs(dragErr[1] / 0.5));     // the contact force is
  EXPECT_EQ(error[2], 0.0);
}

TEST(MeanForceRatio, LeavesAFrameWithoutDragAsItIs) {
  core::data::FieldFrame f = forces(0.0, {1.0, 2.0, 3.0}, {1.0, 1.0, 1.0});
  f.extras.resize(1);  // contact_force only: a DEM run without gas
  const core::data::FieldFrame before = f;
  useRatioOfMeans(f);
  EXPECT_EQ(f.extras, before.extras);
}

}  // namespace
}  // namespace grainbridge::extract::observe
