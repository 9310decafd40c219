#include "workflows/exec/Scheduler.hpp"

#include "core/Error.hpp"
#include "core/Log.hpp"
#include "db/ClosureStore.hpp"
#include "db/Database.hpp"
#include "workflows/exec/Bookkeeper.hpp"
#include "workflows/exec/StopSignal.hpp"

namespace grainbridge::workflows::exec {

namespace fs = std::filesystem;

fs::path resultsRoot(const fs::path& workDir) { return workDir / "results"; }

fs::path databasePath(const config::WorkflowConfig& config, const fs::path& workDir) {
  return config.database.is_absolute() ? config.database : workDir / config.database;
}

namespace {

enum class State { Pending, Running, Done, Failed, NotRun, Busy };

bool settled(State s) { return s != State::Pending && s != State::Running; }

}  // namespace

RunSummary runWorkflow(const config::WorkflowConfig& config, const plan::Plan& plan, const RunOptions& options,
                       Dispatcher& dispatcher, int ranks) {
  const fs::path root = resultsRoot(options.workDir);
  db::Database database = db::Database::open(databasePath(config, options.workDir));
  Bookkeeper books(database, config, root, ranks, options.staleAfter, options.heartbeatPeriod);
  books.start();

  const std::size_t n = plan.instances.size();
  std::vector<State> state(n, State::Pending);
  std::vector<std::string> dirs(n);  // instance folders, relative to the results root
  std::vector<InstanceTask> tasks(n);
  std::vector<std::int64_t> runIds(n, 0);
  RunSummary summary;
  bool stopScheduling = false;

  spdlog::info("workflow '{}': {} stage instance(s); results in {}, database {}", config.name, n,
               (root / config.name).string(), databasePath(config, options.workDir).string());

  auto makeTask = [&](const plan::StageInstance& inst) {
    InstanceTask t;
    t.workflow = config.name;
    t.stage = inst.stage;
    t.stageType = inst.type->name();
    t.key = inst.key;
    t.params = inst.params;
    t.sweepPoint = inst.sweepPoint;
    t.sweepWritten = inst.sweepWritten;
    t.database = databasePath(config, options.workDir).string();
    t.units = config.units.toJson();
    t.instanceDir = inst.relativeDir(config.name);
    for (auto u : inst.upstream) {
      const auto& up = plan.instances[u];
      t.upstream.push_back({up.stage, up.type->name(), up.key, dirs[u], up.sweepPoint, up.sweepWritten});
    }
    for (const auto& table : inst.tables) {
      if (table.quantity == core::kRheologyQuantity) {
        t.rheologies.push_back(db::ClosureStore(database).loadRheology(table.name, table.runKey));
      } else {
        t.closureTables.push_back(db::ClosureStore(database).loadTable(table.name, table.quantity, table.runKey));
      }
    }
    return t;
  };

  while (true) {
    bool changed = false;
    for (std::size_t i = 0; i < n; ++i) {
      if (state[i] != State::Pending) continue;
      const auto& inst = plan.instances[i];
      bool upstreamDone = true;
      bool upstreamLost = false;
      for (auto u : inst.upstream) {
        if (state[u] != State::Done) upstreamDone = false;
        if (settled(state[u]) && state[u] != State::Done) upstreamLost = true;
      }
      if (upstreamLost) {
        state[i] = State::NotRun;
        spdlog::warn("{}: not run, an upstream instance did not complete", inst.label());
        changed = true;
        continue;
      }
      if (!upstreamDone) continue;
      if (!options.force) {
        std::string whyNot;
        if (auto entry = books.validCacheEntry(inst.key, &whyNot)) {
          state[i] = State::Done;
          dirs[i] = entry->instanceDir;
          ++summary.cached;
          spdlog::info("{}: cached ({}), skipped", inst.label(), inst.key.substr(0, 12));
          changed = true;
          continue;
        }
      }
      if (stopScheduling) continue;
      if (inst.ranks > dispatcher.maxRanks()) {
        state[i] = State::Failed;
        ++summary.failed;
        spdlog::error("{}: needs {} rank(s) per instance but this run has {} worker rank(s)", inst.label(), inst.ranks,
                      dispatcher.maxRanks());
        changed = true;
        continue;
      }
      if (dispatcher.idleRanks() < inst.ranks) continue;
      try {
        tasks[i] = makeTask(inst);
      } catch (const Error& e) {
        // A closure table its upstream should have made is missing (a quantity the points lacked).
        state[i] = State::Failed;
        ++summary.failed;
        spdlog::error("{}: {}", inst.label(), e.what());
        if (!options.keepGoing) stopScheduling = true;
        changed = true;
        continue;
      }
      tasks[i].group = dispatcher.reserve(inst.ranks);
      auto begun = books.begin(inst, tasks[i], tasks[i].group.front(), inst.ranks);
      if (!begun.claimed) {
        state[i] = State::Busy;
        ++summary.busy;
        spdlog::warn("{}: being run by another live process ({}); left to it", inst.label(), begun.holder);
        changed = true;
        continue;
      }
      runIds[i] = begun.runId;
      dirs[i] = tasks[i].instanceDir;
      state[i] = State::Running;
      spdlog::info("{}: running ({})", inst.label(), inst.key.substr(0, 12));
      dispatcher.submit(i, tasks[i]);
      changed = true;
    }

    if (dispatcher.inFlight() == 0) {
      if (changed) continue;
      break;  // nothing running and nothing more can start
    }
    if (auto result = dispatcher.poll()) {
      auto [i, outcome] = std::move(*result);
      const auto& inst = plan.instances[i];
      books.record(inst, tasks[i], runIds[i], outcome);
      if (outcome.status == InstanceOutcome::Status::Done) {
        state[i] = State::Done;
        ++summary.ran;
        spdlog::info("{}: done in {:.2f} s", inst.label(), outcome.manifest["timing"]["seconds"].get<double>());
      } else {
        state[i] = State::Failed;
        ++summary.failed;
        if (outcome.status == InstanceOutcome::Status::Interrupted) summary.interrupted = true;
        spdlog::error("{}: {}: {}", inst.label(),
                      outcome.status == InstanceOutcome::Status::Interrupted ? "interrupted" : "failed", outcome.error);
        if (!options.keepGoing) stopScheduling = true;
      }
    }
    if (stopFlag().load() && !stopScheduling) {
      spdlog::warn("stop requested: no new stage instances will start");
      stopScheduling = true;
      summary.interrupted = true;
    }
  }
  for (std::size_t i = 0; i < n; ++i) {
    if (state[i] == State::Pending) {
      state[i] = State::NotRun;
    }
    if (state[i] == State::NotRun) ++summary.notRun;
  }

  const bool ok = summary.exitCode() == 0;
  books.finish(summary.interrupted ? "killed" : ok ? "done" : "failed");
  if (summary.ran == 0 && summary.cached == static_cast<int>(n)) {
    spdlog::info("workflow '{}' is up to date: all {} stage instance(s) cached, nothing to do", config.name, n);
  } else {
    spdlog::info("workflow '{}': {} ran, {} cached, {} failed, {} not run, {} busy", config.name, summary.ran,
                 summary.cached, summary.failed, summary.notRun, summary.busy);
  }
  if (summary.failed > 0 && !options.keepGoing && summary.notRun > 0) {
    spdlog::info("use --keep-going to run every instance that does not depend on a failed one");
  }
  return summary;
}

}  // namespace grainbridge::workflows::exec
