// The dem stage's inputs as a user gives them: a start from a saved frame, refusal of an
// overlapping initial state, per-pair contact coefficients (Eqs. 6.9-6.10 per pair).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <sstream>

#include <nlohmann/json.hpp>

#include "core/data/ParticleFrame.hpp"
#include "core/io/ParticleFrameReader.hpp"
#include "core/io/ParticleFrameWriter.hpp"
#include "tests/support/Cli.hpp"
#include "tests/support/OneGrainData.hpp"

namespace fs = std::filesystem;
using namespace grainbridge;
using namespace grainbridge::testing;
using nlohmann::json;

namespace {

json bed() {
  return json::parse(R"({
    "name": "wf",
    "units": {"system": "reduced", "d0": "1 mm", "m0": "1e-6 kg", "g": "9.81 m/s2"},
    "stages": {"bed": {"type": "dem", "params": {
      "box_lo": [0, 0, 0], "box_hi": [6, 6, 10], "periodic": "xy", "gravity": [0, 0, -1],
      "dt": 2e-4, "duration": 0.2, "frames": 1, "series_points": 2, "progress": false,
      "species": [{"name": "small", "diameter": 1, "density": 1.91, "count": 30},
                  {"name": "large", "diameter": 2, "density": 1.91, "count": 2}],
      "contact": {"kn": 2e5, "gamma_n": 40, "mu": 0.5},
      "walls": [{"kind": "plane", "point": [0, 0, 0], "direction": [0, 0, 1], "kn": 2e5, "gamma_n": 40}]}}}
  })");
}

fs::path lastFrame(const fs::path& work) {
  fs::path last;
  for (const auto& e : fs::recursive_directory_iterator(work / "results/wf/bed")) {
    if (e.path().extension() == ".h5" && e.path().string() > last.string()) last = e.path();
  }
  return last;
}

// One column of the run's series.csv, by name (empty if the file or the column is missing).
std::vector<double> seriesColumn(const fs::path& work, const std::string& name) {
  for (const auto& e : fs::recursive_directory_iterator(work / "results/wf/bed")) {
    if (e.path().filename() != "series.csv") continue;
    std::istringstream lines(readText(e.path()));
    auto fields = [](const std::string& line) {
      std::vector<std::string> out;
      std::istringstream in(line);
      for (std::string c; std::getline(in, c, ',');) out.push_back(c);
      return out;
    };
    std::string line;
    std::getline(lines, line);
    const auto names = fields(line);
    const auto column = static_cast<std::size_t>(std::find(names.begin(), names.end(), name) - names.begin());
    if (column == names.size()) return {};
    std::vector<double> values;
    while (std::getline(lines, line)) values.push_back(std::stod(fields(line).at(column)));
    return values;
  }
  return {};
}

}  // namespace

TEST(DemStage, StartsFromASavedFrame) {
  TempDir work;
  writeText(work.path() / "wf.json", bed().dump());
  ASSERT_EQ(runGrainbridge(work.path(), "run wf.json").exitCode, 0);
  const fs::path frame = lastFrame(work.path());
  ASSERT_FALSE(frame.empty());
  fs::copy_file(frame, work.path() / "start.h5");
  json next = bed();
  next["stages"]["bed"]["params"]["initial_frame"] = "start.h5";
  next["stages"]["bed"]["params"]["species"][0]["count"] = 0;
  next["stages"]["bed"]["params"]["species"][1]["count"] = 0;
  writeText(work.path() / "wf.json", next.dump());
  const auto r = runGrainbridge(work.path(), "run wf.json");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  const auto first = core::io::readParticleFrame(work.path() / "start.h5");
  const auto continued = core::io::readParticleFrame(lastFrame(work.path()));
  EXPECT_EQ(continued.size(), first.size());
  EXPECT_EQ(continued.id, first.id);
}

TEST(DemStage, RefusesAnOverlappingInitialStateNamingThePair) {
  TempDir work;
  core::data::ParticleFrame f;
  f.units = "SI";
  f.domain.lo = Vec3::Zero();
  f.domain.hi = Vec3(0.006, 0.006, 0.01);
  for (int i = 0; i < 2; ++i) {
    f.id.push_back(10 + i);
    f.species.push_back(0);
    f.radius.push_back(0.0005);
    f.mass.push_back(1e-6);
    f.position.emplace_back(0.003 + 0.0008 * i, 0.003, 0.002);  // 20 % of a diameter overlap
    f.velocity.emplace_back(Vec3::Zero());
    f.angularVelocity.emplace_back(Vec3::Zero());
  }
  core::io::ParticleFrameWriter writer(work.path() / "made", core::io::ArtifactStamp{"test"});
  const fs::path file = writer.write(f);
  json cfg = bed();
  cfg["stages"]["bed"]["params"]["initial_frame"] = file.string();
  cfg["stages"]["bed"]["params"]["species"][0]["count"] = 0;
  cfg["stages"]["bed"]["params"]["species"][1]["count"] = 0;
  writeText(work.path() / "wf.json", cfg.dump());
  const auto r = runGrainbridge(work.path(), "run wf.json");
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_NE(r.output.find("/stages/bed/params/initial_frame: particles 10 and 11 overlap by 0.2"), std::string::npos)
      << r.output;
}

TEST(DemStage, PairContactsOverrideOnePair) {
  TempDir work;
  json cfg = bed();
  cfg["stages"]["bed"]["params"]["pair_contacts"] =
      json::parse(R"([{"species": "large", "with": "small", "kn": 2e5, "restitution": 0.5, "mu": 0.3}])");
  writeText(work.path() / "wf.json", cfg.dump());
  const auto r = runGrainbridge(work.path(), "run wf.json");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_NE(r.output.find("pair small-large: e_n = 0.5000"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("pair small-small: e_n = 0.9054"), std::string::npos) << r.output;
}

// Physical inputs instead of coefficients: a contact time and a restitution set k_n and gamma_n
// per pair (Eqs. 6.9-6.10 inverted with each pair's m_eff), as the log shows; a Hertzian
// restitution at a stated impact speed is met at that speed.
TEST(DemStage, ContactTimeAndRestitutionSetTheCoefficients) {
  TempDir work;
  json cfg = bed();
  // 0.01 t0 in the reduced units of bed(); the log speaks SI: t0 = sqrt(1 mm / g) = 0.0101 s.
  cfg["stages"]["bed"]["params"]["contact"] = json::parse(R"({"contact_time": 0.01, "restitution": 0.7})");
  writeText(work.path() / "wf.json", cfg.dump());
  auto r = runGrainbridge(work.path(), "run wf.json");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  for (const char* pair :
       {"pair small-small: e_n = 0.7000, t_c = 0.000101 s", "pair small-large: e_n = 0.7000, t_c = 0.000101 s",
        "pair large-large: e_n = 0.7000, t_c = 0.000101 s"})
    EXPECT_NE(r.output.find(pair), std::string::npos) << pair << "\n" << r.output;
  cfg = bed();
  cfg["stages"]["bed"]["params"]["normal_model"] = "hertz";
  cfg["stages"]["bed"]["params"]["contact"] = json::parse(R"({"kn": 2e5, "restitution": 0.7, "impact_velocity": 0.5})");
  writeText(work.path() / "wf.json", cfg.dump());
  r = runGrainbridge(work.path(), "run wf.json");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_NE(r.output.find("pair small-small: e_n = 0.7000"), std::string::npos) << r.output;
  // The wall keeps its gamma_n: with no impact speed, its Hertzian e_n is the linear estimate, and the log says so.
  EXPECT_NE(r.output.find("pair small-wall 0: e_n = 0.8688, t_c = 7.1e-5 s, largest safe dt (t_c/10) = 7.1e-6 s "
                          "(linear-spring estimate"),
            std::string::npos)
      << r.output;
}

TEST(DemStage, AParticleLeavingTheDomainStopsTheRunNamingStepAndParticle) {
  // No floor: the bed falls out of the bottom of the (non-periodic in z) box.
  TempDir work;
  json cfg = bed();
  cfg["stages"]["bed"]["params"].erase("walls");
  cfg["stages"]["bed"]["params"]["duration"] = 20.0;
  writeText(work.path() / "wf.json", cfg.dump());
  const auto r = runGrainbridge(work.path(), "run wf.json");
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_NE(r.output.find("left the domain at step"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("DEM: particle "), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("are kept in"), std::string::npos) << r.output;
  // The state at the failing step was written beside the periodic frames.
  int frames = 0;
  for (const auto& e : fs::recursive_directory_iterator(work.path() / "results/wf/bed")) {
    if (e.path().extension() == ".h5") ++frames;
  }
  EXPECT_GE(frames, 2);
}

TEST(DemStage, SeriesRecordsTheHeightOfTrackedParticles) {
  TempDir work;
  json config = bed();
  config["stages"]["bed"]["params"]["species"][1]["count"] = 1;
  config["stages"]["bed"]["params"]["track_ids"] = json::array({30});  // the one large particle
  config["stages"]["bed"]["params"]["series_points"] = 5;
  writeText(work.path() / "wf.json", config.dump());
  const auto r = runGrainbridge(work.path(), "run wf.json");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  const auto nut = seriesColumn(work.path(), "z_id30");
  const auto large = seriesColumn(work.path(), "com_z_large");
  ASSERT_EQ(nut.size(), 5u);
  ASSERT_EQ(large.size(), 5u);
  // The large species is that one particle, so its centre of mass is its height.
  for (std::size_t k = 0; k < nut.size(); ++k) EXPECT_NEAR(nut[k], large[k], 1e-12);
}

namespace {

// A sheared fcc lattice at solid fraction 0.1 (SI units as configs/shear-closures.json): its
// lattice planes normal to y are 1.38 d apart, so on the bare streaming profile they slide past
// each other for ever without a collision.
json shearedLattice(const char* initialTemperature) {
  json p = {{"box_lo", {0, 0, 0}},
            {"box_hi", {"13.78 mm", "13.78 mm", "13.78 mm"}},
            {"periodic", "xyz"},
            {"gravity", {0, 0, 0}},
            {"shear_rate", "100 1/s"},
            {"dt", "1e-6 s"},
            {"duration", "0.02 s"},
            {"frames", 1},
            {"series_points", 20},
            {"progress", false},
            {"insertion", "fcc_lattice"},
            {"species", {{{"name", "grain"}, {"diameter", "1 mm"}, {"density", "2500 kg/m3"}, {"count", 500}}}},
            {"contact", {{"kn", "2500 N/m"}, {"restitution", 0.9}, {"mu", 0.0}}}};
  if (initialTemperature != nullptr) p["initial_temperature"] = initialTemperature;
  return {{"name", "wf"}, {"stages", {{"bed", {{"type", "dem"}, {"params", p}}}}}};
}

// Largest contact count in series.csv (-1 without the column).
double mostContacts(const fs::path& work) {
  const auto contacts = seriesColumn(work, "contacts");
  return contacts.empty() ? -1.0 : *std::max_element(contacts.begin(), contacts.end());
}

}  // namespace

TEST(DemStage, InitialTemperatureGivesMaxwellianFluctuationsAboutTheStreamingProfile) {
  TempDir work;
  writeText(work.path() / "wf.json", shearedLattice("0.01 m2/s2").dump());
  const auto r = runGrainbridge(work.path(), "run wf.json");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  fs::path first;
  for (const auto& e : fs::recursive_directory_iterator(work.path() / "results/wf/bed")) {
    if (e.path().extension() == ".h5" && (first.empty() || e.path().string() < first.string())) first = e.path();
  }
  // T = <C^2>/3 (Eq. 3.38) about the imposed profile u_x = gammadot (y - y_mid).
  const auto f = core::io::readParticleFrame(first);
  ASSERT_EQ(f.step, 0);
  ASSERT_EQ(f.size(), 500u);
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  double c2 = 0.0;
  for (std::size_t i = 0; i < f.size(); ++i) {
    const Eigen::Vector3d c = f.velocity[i] - Eigen::Vector3d(100.0 * (f.position[i][1] - 0.5 * 13.78e-3), 0, 0);
    mean += c / 500.0;
    c2 += c.squaredNorm() / 500.0;
  }
  EXPECT_LT(mean.norm(), 1e-12);  // zero total momentum about the profile
  // T = <C^2>/3 of 500 draws: relative standard error sqrt(2/1500) = 3.7 %.
  EXPECT_NEAR(c2 / 3.0, 0.01, 0.01 * 0.15);
  // and the lattice starts colliding
  EXPECT_GT(mostContacts(work.path()), 0.0);
}

TEST(DemStage, AShearedDiluteLatticeWithoutInitialTemperatureNeverCollides) {
  // Why initial_temperature exists: the bare profile keeps the lattice intact.
  TempDir work;
  writeText(work.path() / "wf.json", shearedLattice(nullptr).dump());
  ASSERT_EQ(runGrainbridge(work.path(), "run wf.json").exitCode, 0);
  EXPECT_EQ(mostContacts(work.path()), 0.0);
}

TEST(DemStage, InitialTemperatureIsRefusedForAStateReadFromAFile) {
  TempDir work;
  writeText(work.path() / "wf.json", bed().dump());
  ASSERT_EQ(runGrainbridge(work.path(), "run wf.json").exitCode, 0);
  fs::copy_file(lastFrame(work.path()), work.path() / "start.h5");
  json config = bed();
  config["stages"]["bed"]["params"]["initial_frame"] = "start.h5";
  config["stages"]["bed"]["params"]["species"][0]["count"] = 0;
  config["stages"]["bed"]["params"]["species"][1]["count"] = 0;
  config["stages"]["bed"]["params"]["initial_temperature"] = "1e-4 m2/s2";
  writeText(work.path() / "wf.json", config.dump());
  const auto r = runGrainbridge(work.path(), "run wf.json");
  EXPECT_NE(r.exitCode, 0);
  EXPECT_NE(r.output.find("/stages/bed/params/initial_temperature"), std::string::npos) << r.output;
}

// pressure_control on a sheared box (docs/dem.md): series.csv gains the box length along y, the
// solid fraction and the stress the control saw; the box shrinks towards the target from a
// dilute start, and stress_yy (Eq. 2.3 of the frame, over the box as it now is) follows it.
TEST(DemStage, PressureControlledBoxRecordsItsBoxAndStress) {
  TempDir work;
  json wf = json::parse(R"({
    "name": "wf",
    "stages": {"bed": {"type": "dem", "params": {
      "box_lo": [0, 0, 0], "box_hi": ["8 mm", "8 mm", "8 mm"], "periodic": "xyz", "gravity": [0, 0, 0],
      "shear_rate": "100 1/s", "dt": "2e-6 s", "duration": "0.1 s", "frames": 0, "series_points": 20,
      "progress": false,
      "species": [{"name": "grain", "diameter": "1 mm", "density": "2500 kg/m3", "count": 108}],
      "contact": {"kn": "2500 N/m", "restitution": 0.9},
      "pressure_control": {"stress": "3 Pa", "relaxation_time": "0.01 s"}}}}
  })");
  writeText(work.path() / "wf.json", wf.dump());
  const auto r = runGrainbridge(work.path(), "run wf.json");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  const auto length = seriesColumn(work.path(), "box_length_y");
  const auto phi = seriesColumn(work.path(), "solid_fraction");
  const auto controlled = seriesColumn(work.path(), "controlled_stress_yy");
  const auto stressYY = seriesColumn(work.path(), "stress_yy");
  ASSERT_EQ(length.size(), 20u);
  std::printf("box %.4g -> %.4g m, phi %.4f -> %.4f, p_yy %.4g (frame %.4g) Pa\n", length.front(), length.back(), phi.front(),
              phi.back(), controlled.back(), stressYY.back());
  ASSERT_EQ(phi.size(), length.size());
  ASSERT_EQ(controlled.size(), length.size());
  EXPECT_LT(length.back(), 0.9 * length.front());  // a dilute start (phi 0.11) is compressed
  EXPECT_GT(length.back(), 2.6e-3);                // never below twice the interaction range
  EXPECT_GT(phi.back(), phi.front());
  EXPECT_NEAR(phi.front() * length.front(), phi.back() * length.back(), 1e-5 * phi.front() * length.front());  // series digits
  // The step's p_yy, from the frame (stress_yy) and from the engine's own sum. Samples fall on
  // steps where the box was just adjusted: the frame is of the scaled state, hence 1 %, not 1e-12.
  EXPECT_NEAR(stressYY.back(), controlled.back(), 0.01 * std::abs(controlled.back()));
}

// A LAMMPS data file carries no units: a reduced config reads it in d0, m0 and t0 as it reads its
// own bare numbers (issue 54: the positions were taken as metres and refused as outside the box).
TEST(DemStage, LammpsDataIsReadInTheConfigsUnits) {
  TempDir work;
  writeText(work.path() / "one.data", oneGrainLammpsData("4 4 4", "0.5 0 0 0 0 2"));
  json cfg = json::parse(R"({
    "name": "wf",
    "units": {"system": "reduced", "d0": "2 mm", "m0": "1e-5 kg", "g": "9.81 m/s2"},
    "stages": {"bed": {"type": "dem", "params": {
      "box_lo": [0, 0, 0], "box_hi": [8, 8, 8], "gravity": [0, 0, 0],
      "dt": 2e-4, "duration": 0.1, "frames": 1, "series_points": 2, "progress": false,
      "species": [{"name": "grain", "diameter": 1, "density": 1.91}],
      "lammps_data": "one.data", "lammps_types": [{"type": 1, "species": "grain"}],
      "contact": {"kn": 2e5, "gamma_n": 40, "mu": 0.5}}}}
  })");
  writeText(work.path() / "wf.json", cfg.dump());
  const auto r = runGrainbridge(work.path(), "run wf.json");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  const double d0 = 0.002, m0 = 1e-5, t0 = std::sqrt(d0 / 9.81);
  const auto f = core::io::readParticleFrame(lastFrame(work.path()));
  ASSERT_EQ(f.size(), 1u);
  // Free flight for 0.1 t0 at 0.5 d0/t0 along x: 4.05 d0.
  EXPECT_NEAR(f.position[0][0], 4.05 * d0, 1e-9 * d0);
  EXPECT_NEAR(f.position[0][1], 4.0 * d0, 1e-12);
  EXPECT_NEAR(f.radius[0], 0.5 * d0, 1e-15);
  EXPECT_NEAR(f.mass[0], m0, 1e-12 * m0);  // 1.91 m0/d0^3 x pi/6 d0^3
  EXPECT_NEAR(f.velocity[0][0], 0.5 * d0 / t0, 1e-9 * d0 / t0);
  EXPECT_NEAR(f.angularVelocity[0][2], 2.0 / t0, 1e-9 / t0);
}
