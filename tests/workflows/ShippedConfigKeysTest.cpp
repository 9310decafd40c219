// The stage key of every instance of every shipped workflow (configs/*.json), pinned in
// tests/golden/config-keys.json. A refactoring of parameter declarations or of the code that
// resolves them must leave them alone, or users rerun finished campaigns for nothing
// (DESIGN.md, workflow semantics). A key that changes on purpose (an impl_version bump, a new
// parameter that does affect results) is regenerated with
//   GRAINBRIDGE_UPDATE_GOLDEN=1 build/bin/test_workflows --gtest_filter='ShippedConfigKeys*'
// and the diff of tests/golden/config-keys.json is reviewed.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "tests/support/SharedInputs.hpp"
#include "workflows/config/WorkflowConfig.hpp"
#include "workflows/plan/Plan.hpp"
#include "workflows/stages/StageRegistry.hpp"

namespace fs = std::filesystem;
using nlohmann::json;
using namespace grainbridge::workflows;

namespace {

// Input files (the LAMMPS chute bed) are named relative to the repository root, where a user
// runs the shipped configs.
class InDirectory {
 public:
  explicit InDirectory(const fs::path& dir) : previous_(fs::current_path()) { fs::current_path(dir); }
  ~InDirectory() { fs::current_path(previous_); }
  InDirectory(const InDirectory&) = delete;
  InDirectory& operator=(const InDirectory&) = delete;

 private:
  fs::path previous_;
};

json keysOfShippedConfigs() {
  const fs::path root = GRAINBRIDGE_SOURCE_DIR;
  InDirectory here(root);
  json keys = json::object();
  for (const auto& e : fs::directory_iterator(root / "configs")) {
    if (e.path().extension() != ".json") continue;
    if (grainbridge::testing::needsMissingSharedInputs(root, e.path())) {
      keys[e.path().filename().string()] = "skipped: ../shared is missing";
      continue;
    }
    const auto config =
        config::loadWorkflow(fs::path("configs") / e.path().filename(), stages::StageRegistry::builtin());
    json instances = json::object();
    for (const auto& instance : plan::makePlan(config).instances) {
      // Labels repeat for per-instance stages under a sweep upstream; the upstream keys tell
      // them apart.
      std::string label = instance.label();
      for (const auto u : instance.upstream) label += " <- " + std::to_string(u);
      instances[label] = instance.key;
    }
    keys[e.path().filename().string()] = instances;
  }
  return keys;
}

TEST(ShippedConfigKeys, StageKeysOfEveryShippedWorkflowAreUnchanged) {
  const fs::path golden = fs::path(GRAINBRIDGE_SOURCE_DIR) / "tests/golden/config-keys.json";
  const json keys = keysOfShippedConfigs();
  ASSERT_FALSE(keys.empty());
  if (std::getenv("GRAINBRIDGE_UPDATE_GOLDEN") != nullptr) {
    for (const auto& [config, instances] : keys.items())
      ASSERT_FALSE(instances.is_string()) << config << " " << instances.get<std::string>() << ": pin keys beside it";
    std::ofstream(golden) << keys.dump(2) << "\n";
    GTEST_SKIP() << "updated " << golden;
  }
  ASSERT_TRUE(fs::exists(golden)) << "no pinned keys: regenerate " << golden;
  std::ifstream in(golden);
  const json pinned = json::parse(in);
  for (const auto& [config, instances] : pinned.items()) {
    ASSERT_TRUE(keys.contains(config)) << config << " is pinned but no longer shipped: regenerate " << golden;
    if (keys.at(config).is_string()) continue;  // its inputs are in ../shared, not beside this clone
    EXPECT_EQ(keys.at(config), instances)
        << config << ": stage keys changed. If on purpose (impl_version bump), regenerate " << golden
        << " and say why in the commit";
  }
  for (const auto& [config, instances] : keys.items()) {
    EXPECT_TRUE(pinned.contains(config)) << config << " is shipped but not pinned: regenerate " << golden;
  }
}

}  // namespace
