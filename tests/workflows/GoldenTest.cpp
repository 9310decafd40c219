// One golden case per stage type (DESIGN.md, workflow semantics): changing what a stage
// computes must come with an impl_version bump, or cached results of the old code would be
// reused as if they were the new code's. Each tests/golden/<type>.json holds a small workflow,
// the impl_version it was recorded with and a digest of every artifact's content. Particle
// and field frames are digested by their data (read back), not their bytes, because every
// file also carries the git SHA of the build that wrote it.
//
// After an intended change: bump the stage's impl_version, then regenerate with
//   GRAINBRIDGE_UPDATE_GOLDEN=1 build/bin/test_workflows_cli --gtest_filter='Golden*'
// and review the diff of tests/golden/.
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <iterator>
#include <sstream>

#include "core/Sha256.hpp"
#include "core/io/FieldFrameReader.hpp"
#include "core/io/ParticleFrameReader.hpp"
#include "db/Database.hpp"
#include "db/ProvenanceStore.hpp"
#include "tests/support/Cli.hpp"
#include "workflows/stages/StageRegistry.hpp"

namespace fs = std::filesystem;
using namespace grainbridge;
using namespace grainbridge::testing;
using nlohmann::json;

namespace {

template <class T>
void digestArray(std::ostringstream& out, const std::vector<T>& v) {
  out.write(reinterpret_cast<const char*>(v.data()), static_cast<std::streamsize>(v.size() * sizeof(T)));
}

void digestMaterials(std::ostringstream& out, const core::data::Materials& m) {
  for (const auto& sp : m.species) {
    out << sp.name << ' ';
    out.write(reinterpret_cast<const char*>(&sp.diameter), sizeof(double));
    out.write(reinterpret_cast<const char*>(&sp.density), sizeof(double));
  }
  for (const auto* list : {&m.pairs, &m.walls}) {
    for (const auto& c : *list) {
      out << c.speciesA << ' ' << c.speciesB << ' ' << c.wall << ' ';
      out.write(reinterpret_cast<const char*>(&c.restitution), sizeof(double));
      out.write(reinterpret_cast<const char*>(&c.friction), sizeof(double));
      out.write(reinterpret_cast<const char*>(&c.stiffness), sizeof(double));
      out.write(reinterpret_cast<const char*>(&c.tangentialStiffness), sizeof(double));
    }
  }
}

std::string fieldFrameDigest(const fs::path& file) {
  const auto f = core::io::readFieldFrame(file);
  std::ostringstream out;
  out << f.time << ' ' << f.step << ' ' << f.units << ' ' << f.grid.cells[0] << ' ' << f.grid.cells[1] << ' '
      << f.grid.cells[2] << ' ';
  out.write(reinterpret_cast<const char*>(f.grid.origin.data()), 3 * sizeof(double));
  out.write(reinterpret_cast<const char*>(f.grid.spacing.data()), 3 * sizeof(double));
  digestArray(out, f.ep_g);
  digestArray(out, f.p_g);
  for (const auto& v : f.u_g) out.write(reinterpret_cast<const char*>(v.data()), 3 * sizeof(double));
  for (const auto& phase : f.solids) {
    out << phase.name << ' ';
    digestArray(out, phase.ep_s);
    digestArray(out, phase.theta);
    for (const auto& v : phase.u_s) out.write(reinterpret_cast<const char*>(v.data()), 3 * sizeof(double));
  }
  for (const auto& extra : f.extras) {
    out << extra.name << ' ' << extra.components << ' ';
    digestArray(out, extra.values);
  }
  // The materials, where the frame carries them (a frame without digests as before).
  if (!f.materials.empty()) {
    digestMaterials(out, f.materials);
    out.write(reinterpret_cast<const char*>(f.materials.gravity.data()), 3 * sizeof(double));
  }
  return core::sha256Hex(out.str());
}

// A report page's footer names the build that wrote it (git SHA, library versions) and the
// database path: digested without it, as frames are by their data.
std::string reportPageDigest(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::string page((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const auto begin = page.find("<footer>");
  const auto end = page.find("</footer>");
  if (begin != std::string::npos && end != std::string::npos && end > begin) page.erase(begin, end - begin);
  return core::sha256Hex(page);
}

std::string contentDigest(const fs::path& file, const std::string& kind) {
  if (kind == "field_frame" || kind == "mean_field_frame") return fieldFrameDigest(file);
  if (kind == "report_html") return reportPageDigest(file);
  // A PNG is the raster of the SVG beside it (report/Plot draws both from one script), and its
  // bytes depend on the machine's fonts and cairo: the SVG carries the figure's content.
  if (kind == "png") return "raster of the svg beside it";
  if (kind != "particle_frame") return core::sha256File(file);
  const auto f = core::io::readParticleFrame(file);
  std::ostringstream out;
  out << f.time << ' ' << f.step << ' ' << f.units << ' ';
  digestArray(out, f.id);
  digestArray(out, f.species);
  digestArray(out, f.radius);
  digestArray(out, f.mass);
  auto digestVectors = [&out](std::initializer_list<const std::vector<Vec3>*> arrays) {
    for (const auto* vs : arrays) {
      for (const auto& v : *vs) out.write(reinterpret_cast<const char*>(v.data()), 3 * sizeof(double));
    }
  };
  digestVectors({&f.position, &f.velocity, &f.angularVelocity, &f.externalForce});
  // The materials the frame carries for its readers.
  digestMaterials(out, f.materials);
  out.write(reinterpret_cast<const char*>(f.materials.gravity.data()), 3 * sizeof(double));
  // The contact lists carry the contact law's forces: a changed law must show even where the
  // trajectory is not yet different. (A frame without contacts digests as before.)
  const auto& c = f.contacts;
  digestArray(out, c.i);
  digestArray(out, c.j);
  digestVectors({&c.branch, &c.contactPoint, &c.forceNormal, &c.forceTangential, &c.forceNormalElastic,
                 &c.forceNormalDissipative, &c.forceTangentialElastic, &c.forceTangentialDissipative});
  const auto& w = f.wallContacts;
  digestArray(out, w.particle);
  digestArray(out, w.wall);
  digestVectors({&w.point, &w.forceNormal, &w.forceTangential});
  return core::sha256Hex(out.str());
}

class Golden : public ::testing::TestWithParam<std::string> {};

TEST_P(Golden, OutputUnchangedUnlessImplVersionBumped) {
  const fs::path goldenFile = sourceDir() / "tests/golden" / (GetParam() + ".json");
  ASSERT_TRUE(fs::exists(goldenFile)) << "every stage type needs a golden case: add " << goldenFile;
  json golden = json::parse(readText(goldenFile));
  const auto* type = workflows::stages::StageRegistry::builtin().find(GetParam());
  ASSERT_NE(type, nullptr);

  TempDir work;
  writeText(work.path() / "wf.json", golden.at("workflow").dump(2));
  const auto r = runGrainbridge(work.path(), "run wf.json -q");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  auto database = db::Database::openReadOnly(work.path() / "results" / golden["workflow"]["name"].get<std::string>() /
                                             "grainbridge.sqlite");
  db::ProvenanceStore store(database);
  json digests = json::object();
  for (const auto& run : store.runs("")) {
    if (run.stageType != GetParam()) continue;
    json entry = {{"summary", json::parse(run.summaryJson.empty() ? "{}" : run.summaryJson)},
                  {"artifacts", json::object()}};
    for (const auto& a : store.artifactsOfRun(run.id)) {
      const std::string rel = a.path.substr(run.instanceDir.size() + 1);
      entry["artifacts"][rel] = contentDigest(work.path() / "results" / a.path, a.kind);
    }
    // Keyed by stage and sweep point: a new parameter with a default changes every key, not
    // the output, and must not look like an output change.
    const json manifest = json::parse(readText(work.path() / "results" / run.instanceDir / "manifest.json"));
    digests[run.stage + " " + manifest.at("sweep_point").dump()] = entry;
  }
  ASSERT_FALSE(digests.empty()) << "the golden workflow has no instance of " << GetParam();

  // The impl_version of every stage type the golden workflow uses: a downstream type's output
  // also changes when an upstream type's does.
  json versions = json::object();
  for (const auto& [name, stage] : golden.at("workflow").at("stages").items()) {
    const auto* t = workflows::stages::StageRegistry::builtin().find(stage.at("type"));
    ASSERT_NE(t, nullptr) << name;
    versions[t->name()] = t->implVersion();
  }
  if (std::getenv("GRAINBRIDGE_UPDATE_GOLDEN") != nullptr) {
    golden["impl_versions"] = versions;
    golden["digests"] = digests;
    writeText(goldenFile, golden.dump(2) + "\n");
    GTEST_SKIP() << "updated " << goldenFile;
  }
  // A golden case recorded with other versions guards nothing until it is regenerated: fail, so
  // a bump cannot silently retire it.
  ASSERT_EQ(golden.value("impl_versions", json::object()), versions)
      << "impl_versions are now " << versions.dump()
      << " (golden: " << golden.value("impl_versions", json::object()).dump()
      << "): regenerate the golden case (see the top of "
      << "tests/workflows/GoldenTest.cpp) and review the diff";
  EXPECT_EQ(digests, golden.at("digests"))
      << GetParam() << " output changed but its impl_version did not: bump impl_version (so cached results of the "
      << "old code are not reused) and regenerate the golden case";
}

std::vector<std::string> stageTypes() { return workflows::stages::StageRegistry::builtin().names(); }

INSTANTIATE_TEST_SUITE_P(EveryStageType, Golden, ::testing::ValuesIn(stageTypes()),
                         [](const auto& p) { return p.param; });

}  // namespace
