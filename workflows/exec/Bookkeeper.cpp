#include "workflows/exec/Bookkeeper.hpp"

#include <unistd.h>

#include "core/Error.hpp"
#include "core/Log.hpp"
#include "core/Version.hpp"
#include "db/Clock.hpp"
#include "db/ClosureStore.hpp"
#include "db/Leases.hpp"
#include "db/ProvenanceStore.hpp"
#include "db/StageCache.hpp"
#include "workflows/exec/CacheCheck.hpp"

namespace grainbridge::workflows::exec {

namespace fs = std::filesystem;
using nlohmann::json;

Bookkeeper::Bookkeeper(db::Database& database, const config::WorkflowConfig& config, fs::path resultsRoot, int ranks,
                       std::chrono::seconds staleAfter, std::chrono::milliseconds heartbeatPeriod)
    : db_(database),
      config_(config),
      resultsRoot_(std::move(resultsRoot)),
      ranks_(ranks),
      staleAfter_(staleAfter),
      heartbeatPeriod_(heartbeatPeriod) {}

Bookkeeper::~Bookkeeper() = default;

int Bookkeeper::start() {
  const auto me = db::currentProcessHolder(0);
  db::InvocationRecord inv;
  inv.workflow = config_.name;
  inv.configPath = config_.sourcePath.string();
  inv.configJson = config_.document.dump();
  inv.codeVersion = core::codeVersion().gitSha;
  inv.codeDirty = core::codeVersion().dirty;
  inv.host = me.host;
  inv.pid = me.pid;
  inv.ranks = ranks_;
  inv.startedAt = db::nowUtc();
  inv.status = "running";
  int reclaimed = 0;
  db_.transaction([&](db::Database& d) {
    db::ProvenanceStore store(d);
    reclaimed = store.markOrphanedRunsKilled(staleAfter_);
    invocationId_ = store.insertInvocation(inv);
  });
  if (reclaimed > 0)
    spdlog::warn("{} stage run(s) of a process that ended without finishing were marked killed and will be rerun",
                 reclaimed);
  heartbeat_ = std::make_unique<db::Heartbeat>(db_.path(), db::currentProcessHolder(0), heartbeatPeriod_);
  return reclaimed;
}

std::optional<db::CacheEntry> Bookkeeper::validCacheEntry(const std::string& key, std::string* whyNot) {
  return exec::validCacheEntry(db_, resultsRoot_, key, whyNot);
}

namespace {
struct LeaseBusy {
  db::LeaseHolder holder;
};
}  // namespace

Bookkeeper::Begun Bookkeeper::begin(const plan::StageInstance& instance, const InstanceTask& task, int rank,
                                    int ranks) {
  db::RunRecord run;
  run.invocationId = invocationId_;
  run.workflow = config_.name;
  run.stage = instance.stage;
  run.stageType = instance.type->name();
  run.implVersion = instance.type->implVersion();
  run.key = instance.key;
  run.paramsJson = instance.params.dump();
  run.instanceDir = task.instanceDir;
  run.codeVersion = core::codeVersion().gitSha;
  run.codeDirty = core::codeVersion().dirty;
  const auto me = db::currentProcessHolder(0);
  run.host = me.host;
  run.pid = me.pid;
  run.rank = rank;
  run.ranks = ranks;
  run.startedAt = db::nowUtc();
  run.status = "running";
  for (const auto& u : task.upstream) run.upstreamKeys.push_back(u.key);
  Begun begun;
  try {
    db_.transaction([&](db::Database& d) {
      db::ProvenanceStore store(d);
      begun.runId = store.insertRun(run);
      db::Leases leases(d);
      auto claim = leases.claim(instance.key, db::currentProcessHolder(begun.runId), staleAfter_);
      if (!claim.claimed) throw LeaseBusy{claim.liveHolder.value_or(db::LeaseHolder{})};
    });
  } catch (const LeaseBusy& busy) {
    begun.claimed = false;
    begun.holder = busy.holder.host + ":" + std::to_string(busy.holder.pid);
    return begun;
  }
  begun.claimed = true;
  heartbeat_->add(instance.key);
  return begun;
}

void Bookkeeper::record(const plan::StageInstance& instance, const InstanceTask& task, std::int64_t runId,
                        InstanceOutcome& outcome) {
  const auto me = db::currentProcessHolder(runId);
  heartbeat_->remove(instance.key);
  if (outcome.status == InstanceOutcome::Status::Done) {
    try {
      recordDone(instance, task, runId, outcome, me);
      return;
    } catch (const Error& e) {
      // The closure database refused the rows the stage reported (a stage bug, or a schema
      // CHECK such as a solid fraction >= 1): nothing of the completion was committed, so the
      // run is failed and its published folder, having no cache entry, is redone next time.
      outcome.status = InstanceOutcome::Status::Failed;
      outcome.error = std::string("recording the results failed: ") + e.what();
    }
  }
  db_.transaction([&](db::Database& d) {
    const bool interrupted = outcome.status == InstanceOutcome::Status::Interrupted;
    db::ProvenanceStore(d).finishRun(runId, interrupted ? "killed" : "failed", outcome.error, "{}");
    db::Leases(d).release(instance.key, me);
  });
}

void Bookkeeper::recordDone(const plan::StageInstance& instance, const InstanceTask& task, std::int64_t runId,
                            const InstanceOutcome& outcome, const db::LeaseHolder& me) {
  db_.transaction([&](db::Database& d) {
    db::ProvenanceStore store(d);
    db::Leases leases(d);
    for (const auto& a : outcome.manifest.at("artifacts")) {
      db::ArtifactRecord rec;
      rec.runId = runId;
      rec.key = instance.key;
      rec.path = task.instanceDir + "/" + a.at("path").get<std::string>();
      rec.kind = a.at("kind");
      rec.sha256 = a.at("sha256");
      rec.bytes = a.at("bytes");
      store.addArtifact(rec);
    }
    db::ClosureStore(d).insertRecords(runId, outcome.manifest.value("records", nlohmann::json::object()));
    store.finishRun(runId, "done", "", outcome.manifest.at("summary").dump());
    db::StageCache(d).record({instance.key, runId, config_.name, instance.stage, task.instanceDir, db::nowUtc()});
    leases.release(instance.key, me);
  });
}

void Bookkeeper::finish(const std::string& status) {
  heartbeat_.reset();
  db_.transaction([&](db::Database& d) { db::ProvenanceStore(d).finishInvocation(invocationId_, status); });
}

}  // namespace grainbridge::workflows::exec
