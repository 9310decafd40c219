#include "workflows/exec/CacheCheck.hpp"

#include "core/Sha256.hpp"
#include "db/ProvenanceStore.hpp"
#include "db/StageCache.hpp"

namespace grainbridge::workflows::exec {

namespace fs = std::filesystem;

std::optional<db::CacheEntry> validCacheEntry(db::Database& database, const fs::path& resultsRoot,
                                              const std::string& key, std::string* whyNot) {
  auto say = [whyNot](std::string s) {
    if (whyNot != nullptr) *whyNot = std::move(s);
  };
  auto entry = db::StageCache(database).lookup(key);
  if (!entry) {
    say("no completed run with this key");
    return std::nullopt;
  }
  db::ProvenanceStore store(database);
  auto run = store.run(entry->runId);
  if (!run || run->status != "done") {
    say("its recorded run is not complete");
    return std::nullopt;
  }
  if (!fs::exists(resultsRoot / entry->instanceDir / "manifest.json")) {
    say("its folder " + entry->instanceDir + " is missing");
    return std::nullopt;
  }
  for (const auto& a : store.artifactsOfRun(entry->runId)) {
    const fs::path file = resultsRoot / a.path;
    if (!fs::is_regular_file(file)) {
      say("artifact " + a.path + " is missing");
      return std::nullopt;
    }
    if (core::sha256File(file) != a.sha256) {
      say("artifact " + a.path + " changed on disk");
      return std::nullopt;
    }
  }
  return entry;
}

}  // namespace grainbridge::workflows::exec
