#pragma once
// Reading a finished workflow's results in tests: the one complete instance folder of a stage,
// and the sha256 of every artifact the database registered for the workflow `wf`'s done runs.
#include <filesystem>
#include <map>
#include <string>

#include "db/Database.hpp"
#include "db/ProvenanceStore.hpp"

namespace grainbridge::testing {

// The first instance folder of `stageDir` that is not a `.partial`, or an empty path.
inline std::filesystem::path onlyInstance(const std::filesystem::path& stageDir) {
  for (const auto& e : std::filesystem::directory_iterator(stageDir)) {
    if (e.is_directory() && e.path().extension() != ".partial") return e.path();
  }
  return {};
}

// Artifact path -> sha256 over the done runs of workflow "wf" under `work`/results/wf.
inline std::map<std::string, std::string> artifactDigests(const std::filesystem::path& work) {
  auto database = db::Database::openReadOnly(work / "results/wf/grainbridge.sqlite");
  db::ProvenanceStore store(database);
  std::map<std::string, std::string> out;
  for (const auto& r : store.runs("wf")) {
    if (r.status != "done") continue;
    for (const auto& a : store.artifactsOfRun(r.id)) out[a.path] = a.sha256;
  }
  return out;
}

}  // namespace grainbridge::testing
