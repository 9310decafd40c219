#include "workflows/commands/Commands.hpp"

#include <unistd.h>

#include <algorithm>
#include <cstdlib>

#include <cstdio>
#include <filesystem>
#include <iostream>
#include <map>
#include <set>

#include "core/Log.hpp"
#include "core/json/Diagnostics.hpp"
#include "core/text/NumberText.hpp"
#include "core/parallel/Communicator.hpp"
#include "db/ClosureStore.hpp"
#include "db/Database.hpp"
#include "db/ProvenanceStore.hpp"
#include "db/Statement.hpp"
#include "workflows/commands/DatabaseSource.hpp"
#include "workflows/config/WorkflowConfig.hpp"
#include "workflows/exec/CacheCheck.hpp"
#include "workflows/exec/InstanceRunner.hpp"
#include "workflows/exec/MpiDispatcher.hpp"
#include "workflows/exec/Scheduler.hpp"
#include "workflows/exec/SerialDispatcher.hpp"
#include "workflows/exec/StopSignal.hpp"
#include "workflows/plan/Plan.hpp"
#include "workflows/report/HtmlReport.hpp"
#include "workflows/report/ValidationReport.hpp"
#include "workflows/stages/StageRegistry.hpp"
#include "workflows/status/WorkflowStatus.hpp"

namespace grainbridge::workflows::commands {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

const stages::StageRegistry& registry() { return stages::StageRegistry::builtin(); }

config::WorkflowConfig load(const CommandOptions& opt) { return config::loadWorkflow(opt.config, registry()); }

// The plan, with the closure tables its stages read found in the workflow database (opened
// read-only, and only when it exists: a check changes nothing).
plan::Plan planOf(const config::WorkflowConfig& cfg, const CommandOptions& opt) {
  const fs::path path = exec::databasePath(cfg, opt.workDir);
  return plan::makePlan(cfg, [&path](const std::string& name, const std::string& quantity) -> plan::TableFound {
    if (!fs::exists(path)) return {};
    auto database = db::Database::openReadOnly(path);
    try {
      db::ClosureStore store(database);
      if (quantity == core::kRheologyQuantity) {
        const auto rheology = store.loadRheology(name);
        return {rheology.sha256, stages::Grains{rheology.diameter, rheology.density}};
      }
      const auto table = store.loadTable(name, quantity);
      return {table.sha256, std::nullopt, !table.uncertainties.empty()};
    } catch (const Error&) {
      return {};
    }
  });
}

}  // namespace

int commandCheck(const CommandOptions& opt) {
  const auto cfg = load(opt);
  const auto plan = planOf(cfg, opt);
  std::printf("%s: ok: workflow '%s', %zu stage(s), %zu stage instance(s)\n", opt.config.c_str(), cfg.name.c_str(),
              cfg.stages.size(), plan.instances.size());
  return 0;
}

int commandRun(const CommandOptions& opt) {
  // Every rank validates the config (deterministically the same verdict), so a bad config
  // makes all ranks exit 2 together before any work starts.
  const auto cfg = load(opt);
  const auto plan = planOf(cfg, opt);
  exec::installStopHandlers();
  exec::RunOptions runOptions;
  runOptions.force = opt.force;
  runOptions.keepGoing = opt.keepGoing;
  runOptions.workDir = opt.workDir;
  const int worldSize = core::parallel::worldSize();
  if (core::parallel::worldRank() != 0) {
    exec::runMpiWorker(registry(), exec::resultsRoot(opt.workDir));
    return 0;
  }
  if (worldSize > 1) {
    exec::MpiDispatcher dispatcher;
    return exec::runWorkflow(cfg, plan, runOptions, dispatcher, worldSize).exitCode();
  }
  exec::SerialDispatcher dispatcher(registry(), exec::resultsRoot(opt.workDir), exec::stopFlag());
  return exec::runWorkflow(cfg, plan, runOptions, dispatcher, 1).exitCode();
}

int commandStatus(const CommandOptions& opt) {
  const auto cfg = load(opt);
  const auto plan = planOf(cfg, opt);
  if (!opt.why.empty()) {
    if (cfg.findStage(opt.why) == nullptr) throw UsageError("no stage named '" + opt.why + "' in workflow " + cfg.name);
    for (const auto& line : status::explainStage(cfg, plan, opt.why, opt.workDir)) std::printf("%s\n", line.c_str());
    return 0;
  }
  if (const auto hint = resultsElsewhereHint(cfg, opt.workDir); !hint.empty()) std::fprintf(stderr, "%s\n", hint.c_str());
  std::map<std::string, int> counts;
  for (const auto& s : status::workflowStatus(cfg, plan, opt.workDir, std::chrono::seconds(120))) {
    ++counts[s.state];
    std::printf("%-8s %-40s %s%s%s\n", s.state.c_str(), s.label.c_str(), s.key.substr(0, 12).c_str(),
                s.detail.empty() ? "" : "  ", s.detail.c_str());
  }
  std::printf("%s: %zu instance(s):", cfg.name.c_str(), plan.instances.size());
  for (const auto& [state, n] : counts) std::printf(" %d %s", n, state.c_str());
  std::printf("\n");
  return 0;
}

namespace {
// A Markdown table cell: a `|` inside one ("one of grainbridge|lammps") would end the cell on
// GitHub, so it is escaped.
std::string cell(const std::string& text) {
  std::string out;
  for (const char c : text) {
    if (c == '|') out += '\\';
    out += c;
  }
  return out;
}

// One line per parameter; nested objects list their fields as parent.field or parent[].field.
void printParams(const params::ParamSchema& schema, const std::string& prefix, bool markdown) {
  for (const auto& p : schema.specs()) {
    const std::string name = prefix + p.name();
    const std::string def = p.isRequired() ? "required" : p.defaultJson() ? p.defaultJson()->dump() : "-";
    if (markdown) {
      std::printf("| `%s` | %s | %s | %s | %s | %s |\n", name.c_str(), cell(p.typeDescription()).c_str(),
                  cell(def).c_str(), cell(p.rangeDescription()).c_str(), p.affectsResults() ? "yes" : "no",
                  cell(p.docText()).c_str());
    } else {
      std::printf("  %-30s %-28s %-14s %-18s %s%s\n", name.c_str(), p.typeDescription().c_str(), def.c_str(),
                  p.rangeDescription().c_str(), p.docText().c_str(),
                  p.affectsResults() ? "" : " (not in the stage key)");
    }
    if (p.nested() != nullptr) {
      printParams(*p.nested(), name + (p.kind() == params::ParamKind::ObjectList ? "[]." : "."), markdown);
    }
  }
}
// The key rules of a schema and of its nested objects, each with the path of its object
// ("contact.", "walls[].").
void collectRules(const params::ParamSchema& schema, const std::string& prefix, std::vector<std::string>& out) {
  for (const auto& rule : schema.rules()) out.push_back(rule.description(prefix));
  for (const auto& p : schema.specs()) {
    if (p.nested() != nullptr) {
      collectRules(*p.nested(), prefix + p.name() + (p.kind() == params::ParamKind::ObjectList ? "[]." : "."), out);
    }
  }
}

void printRules(const params::ParamSchema& schema, bool markdown) {
  std::vector<std::string> rules;
  collectRules(schema, "", rules);
  if (rules.empty()) return;
  std::printf(markdown ? "\nRules between parameters:\n\n" : "  rules:\n");
  for (const auto& r : rules) std::printf(markdown ? "- %s\n" : "    %s\n", r.c_str());
}
}  // namespace

int commandStages(const CommandOptions& opt) {
  if (!opt.stageType.empty() && registry().find(opt.stageType) == nullptr) {
    std::vector<std::string> names;
    std::string list;
    for (const auto& type : registry().all()) {
      names.push_back(type->name());
      list += (list.empty() ? "" : ", ") + type->name();
    }
    const auto hint = core::json::closestMatch(opt.stageType, names);
    throw UsageError("no stage type \"" + opt.stageType + "\"" + (hint.empty() ? "" : " (did you mean \"" + hint + "\"?)") +
                     "; stage types: " + list);
  }
  for (const auto& type : registry().all()) {
    if (!opt.stageType.empty() && type->name() != opt.stageType) continue;
    if (opt.markdown) {
      std::printf(
          "## `%s` (impl_version %d)\n\n%s.\n\n| parameter | type | default | range | affects key | description "
          "|\n|---|---|---|---|---|---|\n",
          type->name().c_str(), type->implVersion(), type->summary().c_str());
    } else {
      std::printf("%s (impl_version %d): %s\n", type->name().c_str(), type->implVersion(), type->summary().c_str());
    }
    printParams(type->params(), "", opt.markdown);
    printRules(type->params(), opt.markdown);
    std::printf("\n");
  }
  return 0;
}

int commandReportValidation(const CommandOptions& opt) {
  report::ValidationSources sources;
  sources.recordsDir = opt.records;
  for (const auto& d : opt.databases) {
    if (!fs::exists(d)) throw UsageError("--db " + d + ": no such database");
    sources.databases.emplace_back(d);
  }
  if (!fs::is_directory(sources.recordsDir) && sources.databases.empty()) {
    throw UsageError("no validation records in '" + opt.records +
                     "' and no --db: run the physics tests (scripts/test.sh) or name a workflow database");
  }
  const fs::path out = opt.output.empty() ? fs::path("validation.html") : fs::path(opt.output);
  const auto summary = report::writeValidationReport(sources, out);
  std::printf("%s: %d figures, %d pass, %d fail, %d reported\n", fs::absolute(out).string().c_str(), summary.checks,
              summary.passed, summary.failed, summary.reported);
  return summary.failed > 0 ? 1 : 0;
}

namespace {

// The system's browser, as a desktop user expects: $BROWSER, else xdg-open, else
// sensible-browser. Without one (a headless node) it says so and where the page is.
void openInBrowser(const fs::path& page) {
  std::vector<std::string> candidates;
  if (const char* b = std::getenv("BROWSER"); b != nullptr && *b != '\0') candidates.emplace_back(b);
  candidates.insert(candidates.end(), {"xdg-open", "sensible-browser"});
  for (const auto& c : candidates) {
    const std::string probe = "command -v '" + c + "' >/dev/null 2>&1";
    if (std::system(probe.c_str()) != 0) continue;
    const std::string cmd = "'" + c + "' '" + page.string() + "' >/dev/null 2>&1 &";
    if (std::system(cmd.c_str()) == 0) return;
  }
  spdlog::warn("--open: no browser found ($BROWSER, xdg-open, sensible-browser); open {} yourself", page.string());
}

}  // namespace

int commandReport(const CommandOptions& opt) {
  if (opt.config.empty()) throw UsageError("report: give a workflow config, or `report validation`");
  const auto cfg = load(opt);
  const auto plan = planOf(cfg, opt);
  if (const auto hint = resultsElsewhereHint(cfg, opt.workDir); !hint.empty()) throw UsageError(hint);
  auto database = openExisting(exec::databasePath(cfg, opt.workDir));
  const fs::path root = fs::absolute(exec::resultsRoot(opt.workDir)).lexically_normal();
  std::vector<stages::UpstreamInstance> done;
  std::size_t missing = 0;
  for (const auto& inst : plan.instances) {
    auto entry = exec::validCacheEntry(database, root, inst.key);
    if (!entry) {
      ++missing;
      continue;
    }
    const fs::path dir = root / entry->instanceDir;
    done.emplace_back(inst.stage, inst.type->name(), inst.key, dir, exec::readManifest(dir));
    // The sweep point as the plan gives it now (a cached instance may predate the wording).
    done.back().setSweep(inst.sweepPoint, inst.sweepWritten);
  }
  const fs::path out = root / cfg.name / "report";
  fs::create_directories(out);
  const auto written = report::writeHtmlReport(
      {"grainbridge report: " + cfg.name, exec::databasePath(cfg, opt.workDir).string(),
       stages::StageRegistry::builtin().reportView()},
      done, out, out);
  // The page's path first (scripts read it), then on a terminal what the page leads with.
  const fs::path page = out / "report.html";
  std::printf("%s\n", page.c_str());
  if (::isatty(STDOUT_FILENO) != 0) {
    for (const auto& f : written.findings) std::printf("\n%s", contract::findingsText(f).c_str());
    if (written.findings.empty()) std::printf("(no comparing stage in this workflow: the page lists each stage)\n");
  }
  std::fflush(stdout);
  if (missing > 0)
    spdlog::warn("{} of {} stage instance(s) are not complete and are not in the report", missing,
                 plan.instances.size());
  if (opt.open) openInBrowser(page);
  return 0;
}

int commandDbRuns(const CommandOptions& opt) {
  auto database = openExisting(databaseOf(opt));
  db::ProvenanceStore store(database);
  const auto runs = store.runs(opt.workflowFilter);
  if (opt.format == "json") {
    json out = json::array();
    for (const auto& r : runs) {
      out.push_back({{"id", r.id},
                     {"workflow", r.workflow},
                     {"stage", r.stage},
                     {"stage_type", r.stageType},
                     {"key", r.key},
                     {"status", r.status},
                     {"started_at", r.startedAt},
                     {"ended_at", r.endedAt},
                     {"host", r.host},
                     {"code_version", r.codeVersion},
                     {"error", r.error}});
    }
    std::printf("%s\n", out.dump(2).c_str());
  } else if (opt.format == "csv") {
    std::printf("id,workflow,stage,stage_type,key,status,started_at,ended_at,host,code_version\n");
    for (const auto& r : runs) {
      std::printf("%lld,%s,%s,%s,%s,%s,%s,%s,%s,%s\n", static_cast<long long>(r.id), r.workflow.c_str(),
                  r.stage.c_str(), r.stageType.c_str(), r.key.c_str(), r.status.c_str(), r.startedAt.c_str(),
                  r.endedAt.c_str(), r.host.c_str(), r.codeVersion.c_str());
    }
  } else {
    std::printf("%5s  %-16s %-14s %-8s %-12s %-24s %s\n", "id", "workflow", "stage", "status", "key", "started",
                "error");
    for (const auto& r : runs) {
      std::printf("%5lld  %-16s %-14s %-8s %-12s %-24s %s\n", static_cast<long long>(r.id), r.workflow.c_str(),
                  r.stage.c_str(), r.status.c_str(), r.key.substr(0, 12).c_str(), r.startedAt.c_str(), r.error.c_str());
    }
  }
  return 0;
}

namespace {
// A run's artifacts: with --files each with its sha256; else one line per kind (a DEM run has a
// frame file per output, hundreds of lines), with the first file and the total size.
void printArtifacts(const std::vector<db::ArtifactRecord>& artifacts, bool eachFile) {
  if (eachFile) {
    for (const auto& a : artifacts) {
      std::printf("  artifact   %-14s %s  sha256 %s  %lld bytes\n", a.kind.c_str(), a.path.c_str(), a.sha256.c_str(),
                  static_cast<long long>(a.bytes));
    }
    return;
  }
  struct Kind {
    std::size_t files = 0;
    std::uintmax_t bytes = 0;
    std::string first;
  };
  std::vector<std::pair<std::string, Kind>> kinds;  // in the order recorded
  for (const auto& a : artifacts) {
    auto it = std::find_if(kinds.begin(), kinds.end(), [&](const auto& k) { return k.first == a.kind; });
    if (it == kinds.end()) it = kinds.insert(kinds.end(), {a.kind, Kind{0, 0, a.path}});
    ++it->second.files;
    it->second.bytes += static_cast<std::uintmax_t>(a.bytes);
  }
  for (const auto& [kind, k] : kinds) {
    std::printf("  artifacts  %-14s %s%s, %s\n", kind.c_str(), k.first.c_str(),
                k.files > 1 ? (" and " + std::to_string(k.files - 1) + " more").c_str() : "",
                core::humanBytes(k.bytes).c_str());
  }
  if (!artifacts.empty()) std::printf("             (--files lists each file with its sha256)\n");
}
}  // namespace

int commandDbShow(const CommandOptions& opt) {
  auto database = openExisting(databaseOf(opt));
  db::ProvenanceStore store(database);
  // Walk from the run up through the runs that produced its inputs: the provenance chain.
  std::vector<std::int64_t> queue{opt.runId};
  std::set<std::int64_t> seen;
  bool first = true;
  while (!queue.empty()) {
    const auto id = queue.front();
    queue.erase(queue.begin());
    if (!seen.insert(id).second) continue;
    auto run = store.run(id);
    if (!run) {
      if (first) throw UsageError("no run with id " + std::to_string(id));
      continue;
    }
    std::printf("%srun %lld: %s/%s (%s, impl_version %d) %s\n", first ? "" : "\n", static_cast<long long>(run->id),
                run->workflow.c_str(), run->stage.c_str(), run->stageType.c_str(), run->implVersion,
                run->status.c_str());
    std::printf("  key        %s\n  folder     results/%s\n  code       %s%s\n  host       %s pid %lld rank %d of %d\n",
                run->key.c_str(), run->instanceDir.c_str(), run->codeVersion.c_str(), run->codeDirty ? " (dirty)" : "",
                run->host.c_str(), static_cast<long long>(run->pid), run->rank, run->ranks);
    std::printf("  time       %s -> %s\n  params     %s\n", run->startedAt.c_str(), run->endedAt.c_str(),
                run->paramsJson.c_str());
    if (!run->summaryJson.empty()) std::printf("  summary    %s\n", run->summaryJson.c_str());
    if (!run->error.empty()) std::printf("  error      %s\n", run->error.c_str());
    printArtifacts(store.artifactsOfRun(run->id), opt.files);
    {
      // What this run put in the closure database (db query --run shows the rows).
      db::ClosureStore closures(database);
      std::string records;
      for (const auto& table : {"closure_points", "force_statistics", "structure_statistics", "rheology"}) {
        db::ClosureQuery q;
        q.table = table;
        q.runId = run->id;
        const auto n = closures.query(q).size();
        if (n > 0) records += (records.empty() ? "" : ", ") + std::to_string(n) + " " + table;
      }
      auto tables = database.prepare("SELECT name || '/' || quantity FROM closure_tables WHERE run_id = ?1");
      tables.bind(1, run->id);
      while (tables.step()) records += (records.empty() ? "table " : ", table ") + tables.columnText(0);
      if (!records.empty()) std::printf("  records    %s\n", records.c_str());
    }
    for (const auto& up : run->upstreamKeys) {
      const auto producers = store.runsOfKey(up);
      std::int64_t producer = 0;
      for (const auto& p : producers) {
        if (p.status == "done") producer = p.id;
      }
      std::printf("  input      key %s%s\n", up.substr(0, 12).c_str(),
                  producer ? (" from run " + std::to_string(producer)).c_str() : " (no completed run recorded)");
      if (producer) queue.push_back(producer);
    }
    if (first) {
      for (const auto& inv : store.invocations(run->workflow)) {
        if (inv.id == run->invocationId) {
          std::printf("  invocation %lld: config %s, %d rank(s), started %s\n", static_cast<long long>(inv.id),
                      inv.configPath.c_str(), inv.ranks, inv.startedAt.c_str());
          std::printf("  config     %s\n", inv.configJson.c_str());
        }
      }
    }
    first = false;
  }
  return 0;
}

int commandDbIntegrity(const CommandOptions& opt) {
  auto database = openExisting(databaseOf(opt));
  const std::string result = database.integrityCheck();
  std::printf("%s\n", result.c_str());
  return result == "ok" ? 0 : 1;
}

}  // namespace grainbridge::workflows::commands
