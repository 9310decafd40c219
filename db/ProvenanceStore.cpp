#include "db/ProvenanceStore.hpp"

#include "core/Error.hpp"
#include "db/Clock.hpp"
#include "db/Database.hpp"
#include "db/Leases.hpp"

namespace grainbridge::db {

namespace {

constexpr const char* kRunColumns =
    "id, invocation_id, workflow, stage, stage_type, impl_version, key, params_json, instance_dir, code_version, "
    "code_dirty, host, pid, rank, ranks, started_at, ended_at, status, error, summary_json";

RunRecord readRun(const Statement& row) {
  RunRecord run;
  run.id = row.columnInt64(0);
  run.invocationId = row.columnInt64(1);
  run.workflow = row.columnText(2);
  run.stage = row.columnText(3);
  run.stageType = row.columnText(4);
  run.implVersion = static_cast<int>(row.columnInt64(5));
  run.key = row.columnText(6);
  run.paramsJson = row.columnText(7);
  run.instanceDir = row.columnText(8);
  run.codeVersion = row.columnText(9);
  run.codeDirty = row.columnInt64(10) != 0;
  run.host = row.columnText(11);
  run.pid = row.columnInt64(12);
  run.rank = static_cast<int>(row.columnInt64(13));
  run.ranks = static_cast<int>(row.columnInt64(14));
  run.startedAt = row.columnText(15);
  run.endedAt = row.columnText(16);
  run.status = row.columnText(17);
  run.error = row.columnText(18);
  run.summaryJson = row.columnText(19);
  return run;
}

const std::string& orDefault(const std::string& value, const std::string& fallback) {
  return value.empty() ? fallback : value;
}

}  // namespace

ProvenanceStore::ProvenanceStore(Database& db) : db_(db) {}

std::int64_t ProvenanceStore::insertInvocation(const InvocationRecord& invocation) {
  Statement insert = db_.prepare(
      "INSERT INTO invocations(workflow, config_path, config_json, code_version, code_dirty, host, pid, ranks, "
      "started_at, ended_at, status) VALUES(?,?,?,?,?,?,?,?,?,?,?)");
  insert.bind(1, invocation.workflow)
      .bindTextOrNull(2, invocation.configPath)
      .bind(3, invocation.configJson)
      .bind(4, invocation.codeVersion)
      .bind(5, invocation.codeDirty ? 1 : 0)
      .bind(6, invocation.host)
      .bind(7, invocation.pid)
      .bind(8, invocation.ranks)
      .bind(9, orDefault(invocation.startedAt, nowUtc()))
      .bindTextOrNull(10, invocation.endedAt)
      .bind(11, orDefault(invocation.status, "running"));
  insert.step();
  return db_.lastInsertRowId();
}

void ProvenanceStore::finishInvocation(std::int64_t id, const std::string& status) {
  Statement update = db_.prepare("UPDATE invocations SET status=?, ended_at=? WHERE id=?");
  update.bind(1, status).bind(2, nowUtc()).bind(3, id);
  update.step();
  if (db_.changes() != 1)
    throw Error("database " + db_.path().string() + ": no invocation with id " + std::to_string(id) + " to finish");
}

std::int64_t ProvenanceStore::insertRun(const RunRecord& run) {
  Statement insert = db_.prepare(
      "INSERT INTO runs(invocation_id, workflow, stage, stage_type, impl_version, key, params_json, instance_dir, "
      "code_version, code_dirty, host, pid, rank, ranks, started_at, ended_at, status, error, summary_json) "
      "VALUES(?,?,?,?,?,?,?,?,?,?,?,?,?,?,?,?,?,?,?)");
  insert.bind(1, run.invocationId)
      .bind(2, run.workflow)
      .bind(3, run.stage)
      .bind(4, run.stageType)
      .bind(5, run.implVersion)
      .bind(6, run.key)
      .bind(7, run.paramsJson)
      .bind(8, run.instanceDir)
      .bind(9, run.codeVersion)
      .bind(10, run.codeDirty ? 1 : 0)
      .bind(11, run.host)
      .bind(12, run.pid)
      .bind(13, run.rank)
      .bind(14, run.ranks)
      .bind(15, orDefault(run.startedAt, nowUtc()))
      .bindTextOrNull(16, run.endedAt)
      .bind(17, orDefault(run.status, "running"))
      .bindTextOrNull(18, run.error)
      .bindTextOrNull(19, run.summaryJson);
  insert.step();
  const std::int64_t runId = db_.lastInsertRowId();
  // OR IGNORE: the same upstream key listed twice is one input, not a constraint error.
  Statement input = db_.prepare("INSERT OR IGNORE INTO run_inputs(run_id, upstream_key) VALUES(?,?)");
  for (const std::string& upstream : run.upstreamKeys) {
    input.bind(1, runId).bind(2, upstream);
    input.step();
    input.reset();
  }
  return runId;
}

void ProvenanceStore::finishRun(std::int64_t runId, const std::string& status, const std::string& error,
                                const std::string& summaryJson) {
  Statement update = db_.prepare("UPDATE runs SET status=?, error=?, summary_json=?, ended_at=? WHERE id=?");
  update.bind(1, status).bindTextOrNull(2, error).bindTextOrNull(3, summaryJson).bind(4, nowUtc()).bind(5, runId);
  update.step();
  if (db_.changes() != 1)
    throw Error("database " + db_.path().string() + ": no run with id " + std::to_string(runId) + " to finish");
}

void ProvenanceStore::addArtifact(const ArtifactRecord& artifact) {
  Statement insert = db_.prepare("INSERT INTO artifacts(run_id, key, path, kind, sha256, bytes) VALUES(?,?,?,?,?,?)");
  insert.bind(1, artifact.runId)
      .bind(2, artifact.key)
      .bind(3, artifact.path)
      .bind(4, artifact.kind)
      .bind(5, artifact.sha256)
      .bind(6, artifact.bytes);
  insert.step();
}

std::vector<ArtifactRecord> ProvenanceStore::artifactsOfRun(std::int64_t runId) {
  Statement query =
      db_.prepare("SELECT id, run_id, key, path, kind, sha256, bytes FROM artifacts WHERE run_id=? ORDER BY id");
  query.bind(1, runId);
  std::vector<ArtifactRecord> result;
  while (query.step()) {
    ArtifactRecord& artifact = result.emplace_back();
    artifact.id = query.columnInt64(0);
    artifact.runId = query.columnInt64(1);
    artifact.key = query.columnText(2);
    artifact.path = query.columnText(3);
    artifact.kind = query.columnText(4);
    artifact.sha256 = query.columnText(5);
    artifact.bytes = query.columnInt64(6);
  }
  return result;
}

std::vector<std::string> ProvenanceStore::upstreamKeysOf(std::int64_t runId) {
  // rowid order = insertion order, so the record round-trips exactly.
  Statement query = db_.prepare("SELECT upstream_key FROM run_inputs WHERE run_id=? ORDER BY rowid");
  query.bind(1, runId);
  std::vector<std::string> keys;
  while (query.step()) keys.push_back(query.columnText(0));
  return keys;
}

std::vector<RunRecord> ProvenanceStore::queryRuns(const std::string& where, const std::string& argument) {
  Statement query = db_.prepare(std::string("SELECT ") + kRunColumns + " FROM runs" + where + " ORDER BY id");
  if (!where.empty()) query.bind(1, argument);
  std::vector<RunRecord> result;
  while (query.step()) result.push_back(readRun(query));
  for (RunRecord& run : result) run.upstreamKeys = upstreamKeysOf(run.id);
  return result;
}

std::optional<RunRecord> ProvenanceStore::run(std::int64_t id) {
  Statement query = db_.prepare(std::string("SELECT ") + kRunColumns + " FROM runs WHERE id=?");
  query.bind(1, id);
  if (!query.step()) return std::nullopt;
  RunRecord result = readRun(query);
  result.upstreamKeys = upstreamKeysOf(id);
  return result;
}

std::vector<RunRecord> ProvenanceStore::runs(const std::string& workflow) {
  return workflow.empty() ? queryRuns("", "") : queryRuns(" WHERE workflow=?", workflow);
}

std::vector<RunRecord> ProvenanceStore::runsOfKey(const std::string& key) { return queryRuns(" WHERE key=?", key); }

std::vector<InvocationRecord> ProvenanceStore::invocations(const std::string& workflow) {
  Statement query = db_.prepare(
      "SELECT id, workflow, config_path, config_json, code_version, code_dirty, host, pid, ranks, started_at, "
      "ended_at, status FROM invocations" +
      std::string(workflow.empty() ? "" : " WHERE workflow=?") + " ORDER BY id");
  if (!workflow.empty()) query.bind(1, workflow);
  std::vector<InvocationRecord> result;
  while (query.step()) {
    InvocationRecord& invocation = result.emplace_back();
    invocation.id = query.columnInt64(0);
    invocation.workflow = query.columnText(1);
    invocation.configPath = query.columnText(2);
    invocation.configJson = query.columnText(3);
    invocation.codeVersion = query.columnText(4);
    invocation.codeDirty = query.columnInt64(5) != 0;
    invocation.host = query.columnText(6);
    invocation.pid = query.columnInt64(7);
    invocation.ranks = static_cast<int>(query.columnInt64(8));
    invocation.startedAt = query.columnText(9);
    invocation.endedAt = query.columnText(10);
    invocation.status = query.columnText(11);
  }
  return result;
}

int ProvenanceStore::markOrphanedRunsKilled(std::chrono::seconds staleAfter) {
  struct Candidate {
    std::int64_t id;
    std::string host;
    std::int64_t pid;
  };
  // LEFT JOIN: a run with no lease at all (released without finishing, or never claimed)
  // comes back with NULL lease columns and counts as orphaned.
  Statement query = db_.prepare(
      "SELECT r.id, r.host, r.pid, l.host, l.pid, l.pid_start, l.heartbeat_at "
      "FROM runs r LEFT JOIN leases l ON l.key = r.key "
      "AND (l.run_id = r.id OR (l.run_id IS NULL AND l.host = r.host AND l.pid = r.pid)) "
      "WHERE r.status = 'running' ORDER BY r.id");
  std::vector<Candidate> orphans;
  while (query.step()) {
    bool alive = false;
    if (!query.columnIsNull(3)) {
      const LeaseHolder holder{query.columnText(3), query.columnInt64(4), query.columnText(5), 0};
      alive = isHolderAlive(holder, query.columnText(6), staleAfter);
    }
    if (!alive) orphans.push_back({query.columnInt64(0), query.columnText(1), query.columnInt64(2)});
  }
  Statement update =
      db_.prepare("UPDATE runs SET status='killed', ended_at=?, error=? WHERE id=? AND status='running'");
  int marked = 0;
  for (const Candidate& orphan : orphans) {
    update.bind(1, nowUtc())
        .bind(2, "process " + orphan.host + ":" + std::to_string(orphan.pid) + " ended without finishing")
        .bind(3, orphan.id);
    update.step();
    marked += db_.changes();
    update.reset();
  }
  return marked;
}

}  // namespace grainbridge::db
