#include "db/Migrations.hpp"

namespace grainbridge::db {

const std::vector<std::string>& migrations() {
  static const std::vector<std::string> scripts = {
      // 1: provenance (invocations, runs and their inputs, artifacts), the stage cache and the
      // leases that replace lock files. instance_dir and artifact paths are relative to the
      // results root, so a moved project keeps working. Plain CREATE TABLE (no IF NOT EXISTS):
      // running a migration twice is a bug that should fail loudly.
      R"sql(
CREATE TABLE invocations(
  id INTEGER PRIMARY KEY,
  workflow TEXT NOT NULL,
  config_path TEXT,
  config_json TEXT NOT NULL,
  code_version TEXT NOT NULL,
  code_dirty INTEGER NOT NULL,
  host TEXT NOT NULL,
  pid INTEGER NOT NULL,
  ranks INTEGER NOT NULL,
  started_at TEXT NOT NULL,
  ended_at TEXT,
  status TEXT NOT NULL CHECK(status IN ('running','done','failed','killed')));

CREATE TABLE runs(
  id INTEGER PRIMARY KEY,
  invocation_id INTEGER NOT NULL REFERENCES invocations(id),
  workflow TEXT NOT NULL,
  stage TEXT NOT NULL,
  stage_type TEXT NOT NULL,
  impl_version INTEGER NOT NULL,
  key TEXT NOT NULL,
  params_json TEXT NOT NULL,
  instance_dir TEXT NOT NULL,
  code_version TEXT NOT NULL,
  code_dirty INTEGER NOT NULL,
  host TEXT NOT NULL,
  pid INTEGER NOT NULL,
  rank INTEGER NOT NULL,
  ranks INTEGER NOT NULL,
  started_at TEXT NOT NULL,
  ended_at TEXT,
  status TEXT NOT NULL CHECK(status IN ('running','done','failed','killed')),
  error TEXT,
  summary_json TEXT);
CREATE INDEX runs_key ON runs(key);
CREATE INDEX runs_workflow_stage ON runs(workflow, stage);
CREATE INDEX runs_invocation ON runs(invocation_id);

CREATE TABLE run_inputs(
  run_id INTEGER NOT NULL REFERENCES runs(id),
  upstream_key TEXT NOT NULL,
  PRIMARY KEY(run_id, upstream_key));

CREATE TABLE artifacts(
  id INTEGER PRIMARY KEY,
  run_id INTEGER NOT NULL REFERENCES runs(id),
  key TEXT NOT NULL,
  path TEXT NOT NULL,
  kind TEXT NOT NULL,
  sha256 TEXT NOT NULL,
  bytes INTEGER NOT NULL,
  UNIQUE(run_id, path));
CREATE INDEX artifacts_key ON artifacts(key);

CREATE TABLE stage_cache(
  key TEXT PRIMARY KEY,
  run_id INTEGER NOT NULL REFERENCES runs(id),
  workflow TEXT NOT NULL,
  stage TEXT NOT NULL,
  instance_dir TEXT NOT NULL,
  completed_at TEXT NOT NULL);
CREATE INDEX stage_cache_workflow ON stage_cache(workflow, stage);

CREATE TABLE leases(
  key TEXT PRIMARY KEY,
  run_id INTEGER REFERENCES runs(id),
  host TEXT NOT NULL,
  pid INTEGER NOT NULL,
  pid_start TEXT NOT NULL,
  claimed_at TEXT NOT NULL,
  heartbeat_at TEXT NOT NULL);
CREATE INDEX leases_run ON leases(run_id);
)sql",
  };
  return scripts;
}

}  // namespace grainbridge::db
