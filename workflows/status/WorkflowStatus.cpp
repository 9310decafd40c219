#include "workflows/status/WorkflowStatus.hpp"

#include <algorithm>
#include <map>
#include <set>

#include "core/text/NumberText.hpp"
#include "db/Database.hpp"
#include "db/Leases.hpp"
#include "db/ProvenanceStore.hpp"
#include "db/Statement.hpp"
#include "workflows/exec/CacheCheck.hpp"
#include "workflows/exec/Scheduler.hpp"

namespace grainbridge::workflows::status {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

// The live holder of a key's lease as "host:pid", or "" if none is alive.
std::string liveHolder(db::Database& database, const std::string& key, std::chrono::seconds staleAfter) {
  auto st = database.prepare("SELECT host, pid, pid_start, run_id, heartbeat_at FROM leases WHERE key = ?");
  st.bind(1, key);
  if (!st.step()) return "";
  db::LeaseHolder h;
  h.host = st.columnText(0);
  h.pid = st.columnInt64(1);
  h.pidStart = st.columnText(2);
  h.runId = st.columnIsNull(3) ? 0 : st.columnInt64(3);
  if (!db::isHolderAlive(h, st.columnText(4), staleAfter)) return "";
  return h.host + ":" + std::to_string(h.pid);
}

// Most recent run of each stage key, newest last.
std::vector<db::RunRecord> runsOfStage(db::ProvenanceStore& store, const std::string& workflow,
                                       const std::string& stage) {
  std::vector<db::RunRecord> out;
  for (auto& r : store.runs(workflow)) {
    if (r.stage == stage) out.push_back(std::move(r));
  }
  std::sort(out.begin(), out.end(), [](const auto& a, const auto& b) { return a.id < b.id; });
  return out;
}

}  // namespace

std::vector<InstanceStatus> workflowStatus(const config::WorkflowConfig& config, const plan::Plan& plan,
                                           const fs::path& workDir, std::chrono::seconds staleAfter) {
  std::vector<InstanceStatus> out;
  const fs::path dbPath = exec::databasePath(config, workDir);
  if (!fs::exists(dbPath)) {
    for (const auto& inst : plan.instances)
      out.push_back({inst.label(), inst.key, "pending", "never run (no database yet)"});
    return out;
  }
  auto database = db::Database::openReadOnly(dbPath);
  db::ProvenanceStore store(database);
  const fs::path root = exec::resultsRoot(workDir);
  for (const auto& inst : plan.instances) {
    InstanceStatus s{inst.label(), inst.key, "pending", ""};
    std::string whyNot;
    if (exec::validCacheEntry(database, root, inst.key, &whyNot)) {
      s.state = "done";
    } else if (auto holder = liveHolder(database, inst.key, staleAfter); !holder.empty()) {
      s.state = "running";
      s.detail = "held by " + holder;
    } else {
      auto runs = store.runsOfKey(inst.key);
      if (!runs.empty()) {
        std::sort(runs.begin(), runs.end(), [](const auto& a, const auto& b) { return a.id < b.id; });
        const auto& last = runs.back();
        if (last.status == "failed" || last.status == "killed") {
          s.state = last.status;
          s.detail = last.error;
        } else if (last.status == "running") {
          s.state = "killed";
          s.detail = "its process " + last.host + ":" + std::to_string(last.pid) + " ended without finishing";
        } else {
          s.detail = whyNot;
        }
      } else {
        s.detail = runsOfStage(store, config.name, inst.stage).empty()
                       ? "never run"
                       : "parameters or upstream changed (status --why " + inst.stage + ")";
      }
    }
    out.push_back(std::move(s));
  }
  return out;
}

std::vector<std::string> explainStage(const config::WorkflowConfig& config, const plan::Plan& plan,
                                      const std::string& stage, const fs::path& workDir) {
  std::vector<std::string> lines;
  const fs::path dbPath = exec::databasePath(config, workDir);
  std::optional<db::Database> database;
  if (fs::exists(dbPath)) database.emplace(db::Database::openReadOnly(dbPath));
  std::vector<db::RunRecord> history;
  if (database) {
    db::ProvenanceStore store(*database);
    history = runsOfStage(store, config.name, stage);
  }
  // Upstream stage name of every key this workflow plans, for naming what changed.
  std::map<std::string, std::string> labelOfKey;
  for (const auto& inst : plan.instances) labelOfKey[inst.key] = inst.label();

  std::set<std::string> overlaid;  // the params the stage's replicas overlay (closure_draw)
  for (const auto& inst : plan.instances) {
    if (inst.stage != stage) continue;
    for (const auto& [k, v] : inst.replica.overlay.items()) overlaid.insert(k);
  }
  for (const auto& inst : plan.instances) {
    if (inst.stage != stage) continue;
    std::string whyNot;
    if (database && exec::validCacheEntry(*database, exec::resultsRoot(workDir), inst.key, &whyNot)) {
      lines.push_back(inst.label() + ": up to date (key " + inst.key.substr(0, 12) + ")");
      continue;
    }
    // Compare with the newest run of this stage at the same sweep point and of the same replica
    // (the same values, or none, of the params its replicas overlay: a closure sample's draw). A
    // sweep point without one has never run: its siblings' runs are other instances, not its
    // history (comparing with one reported the sweep value as a change).
    const db::RunRecord* previous = nullptr;
    for (auto it = history.rbegin(); it != history.rend() && previous == nullptr; ++it) {
      const json old = json::parse(it->paramsJson);
      bool samePoint = true;
      for (const auto& [k, v] : inst.sweepPoint.items()) samePoint = samePoint && old.contains(k) && old[k] == v;
      for (const auto& k : overlaid) samePoint = samePoint && old.value(k, json()) == inst.params.value(k, json());
      if (samePoint) previous = &*it;
    }
    if (previous == nullptr) {
      lines.push_back(inst.label() + ": never run" +
                      (history.empty() ? "" : " (other sweep points of " + stage + " have run, none at this one)"));
      continue;
    }
    if (previous->key == inst.key) {
      lines.push_back(inst.label() + ": same key as run " + std::to_string(previous->id) + ", but " +
                      (whyNot.empty() ? "it did not complete (" + previous->status + ")" : whyNot));
      continue;
    }
    std::string head = inst.label() + ": key changed since run " + std::to_string(previous->id) + " (" +
                       previous->key.substr(0, 12) + " -> " + inst.key.substr(0, 12) + ")";
    lines.push_back(head);
    if (previous->implVersion != inst.type->implVersion()) {
      lines.push_back("  impl_version of " + inst.type->name() + ": " + std::to_string(previous->implVersion) + " -> " +
                      std::to_string(inst.type->implVersion()));
    }
    const json oldParams = inst.type->params().keyParams(json::parse(previous->paramsJson));
    const json newParams = inst.type->params().keyParams(inst.params);
    // For people, unless the change hides below six digits: then every digit.
    auto change = [](const json& before, const json& after) {
      const bool distinct = core::humanText(before) != core::humanText(after);
      return (distinct ? core::humanText(before) : before.dump()) + " -> " +
             (distinct ? core::humanText(after) : after.dump());
    };
    for (const auto& [k, v] : newParams.items()) {
      if (!oldParams.contains(k))
        lines.push_back("  parameter " + k + ": (absent) -> " + core::humanText(v));
      else if (oldParams[k] != v)
        lines.push_back("  parameter " + k + ": " + change(oldParams[k], v));
    }
    for (const auto& [k, v] : oldParams.items()) {
      if (!newParams.contains(k)) lines.push_back("  parameter " + k + ": " + core::humanText(v) + " -> (absent)");
    }
    for (auto u : inst.upstream) {
      const auto& up = plan.instances[u];
      if (std::find(previous->upstreamKeys.begin(), previous->upstreamKeys.end(), up.key) ==
          previous->upstreamKeys.end()) {
        lines.push_back("  upstream " + up.label() + " changed (now key " + up.key.substr(0, 12) + ")");
      }
    }
    if (previous->upstreamKeys.size() != inst.upstream.size()) {
      lines.push_back("  number of upstream instances: " + std::to_string(previous->upstreamKeys.size()) + " -> " +
                      std::to_string(inst.upstream.size()));
    }
  }
  if (lines.empty()) lines.push_back("no stage named '" + stage + "' in workflow " + config.name);
  return lines;
}

}  // namespace grainbridge::workflows::status
