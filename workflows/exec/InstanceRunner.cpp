#include "workflows/exec/InstanceRunner.hpp"

#include <unistd.h>

#include <chrono>

#include "core/Error.hpp"
#include "core/FailPoint.hpp"
#include "core/Files.hpp"
#include "core/Log.hpp"
#include "core/Sha256.hpp"
#include "core/Version.hpp"
#include "db/Clock.hpp"

namespace grainbridge::workflows::exec {

namespace fs = std::filesystem;
using nlohmann::json;

json readManifest(const fs::path& instanceDir) {
  const fs::path path = instanceDir / "manifest.json";
  if (!fs::exists(path)) throw Error("missing manifest '" + path.string() + "' (the instance is not complete)");
  try {
    return json::parse(core::readFile(path));
  } catch (const json::exception& e) {
    throw Error("corrupt manifest '" + path.string() + "': " + e.what());
  }
}

namespace {

// Hashes every reported artifact, refusing paths that escape the instance folder.
json hashArtifacts(const stages::StageContext& ctx, const fs::path& dir) {
  json list = json::array();
  for (const auto& a : ctx.artifacts()) {
    const fs::path rel = fs::path(a.path).lexically_normal();
    if (rel.is_absolute() || rel.empty() || *rel.begin() == "..") {
      throw Error("stage reported artifact '" + a.path + "' outside its instance folder");
    }
    const fs::path file = dir / rel;
    if (!fs::is_regular_file(file)) throw Error("stage reported artifact '" + a.path + "' but did not write it");
    list.push_back({{"path", rel.generic_string()},
                    {"kind", a.kind},
                    {"sha256", core::sha256File(file)},
                    {"bytes", static_cast<std::int64_t>(fs::file_size(file))}});
  }
  return list;
}

}  // namespace

InstanceOutcome runInstance(const InstanceTask& task, const stages::StageRegistry& registry,
                            const fs::path& resultsRoot, core::parallel::Communicator& comm,
                            const std::atomic<bool>& stop) {
  InstanceOutcome outcome;
  const bool leader = comm.rank() == 0;
  const fs::path finalDir = resultsRoot / task.instanceDir;
  const fs::path partialDir = finalDir.string() + std::string(stages::StageContext::kPartialSuffix);
  const auto started = std::chrono::steady_clock::now();
  const std::string startedAt = db::nowUtc();
  try {
    const stages::StageType* type = registry.find(task.stageType);
    if (type == nullptr) throw Error("unknown stage type '" + task.stageType + "'");
    if (leader) {
      // We hold the lease, so a leftover partial folder is from a killed or interrupted run:
      // resume it if its stage left a checkpoint, otherwise start afresh.
      if (!fs::exists(partialDir / "checkpoint")) fs::remove_all(partialDir);
      fs::create_directories(partialDir);
    }
    if (comm.isMpi() && comm.size() > 1) MPI_Barrier(comm.raw());

    std::vector<stages::UpstreamInstance> inputs;
    for (const auto& u : task.upstream) {
      const fs::path dir = resultsRoot / u.dir;
      inputs.emplace_back(u.stage, u.stageType, u.key, dir, readManifest(dir));
      inputs.back().setSweep(u.sweepPoint, u.sweepWritten);
    }
    stages::StageContext ctx(task.workflow, task.stage, task.key, task.params, partialDir, std::move(inputs), comm,
                             core::units::UnitSystem::fromJson(task.units), stop);
    ctx.setDatabasePath(task.database);
    ctx.setClosureTables(task.closureTables);
    ctx.setRheologies(task.rheologies);
    type->run(ctx);
    core::failPoint("stage.after_run");
    if (comm.isMpi() && comm.size() > 1) MPI_Barrier(comm.raw());
    if (!leader) {
      outcome.status = InstanceOutcome::Status::Done;
      return outcome;
    }

    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    char host[256] = {};
    ::gethostname(host, sizeof host - 1);
    json manifest = {
        {"key", task.key},
        {"workflow", task.workflow},
        {"stage", task.stage},
        {"stage_type", task.stageType},
        {"impl_version", type->implVersion()},
        {"params", task.params},
        {"sweep_point", task.sweepPoint},
        {"upstream",
         [&] {
           json keys = json::array();
           for (const auto& u : task.upstream) keys.push_back(u.key);
           return keys;
         }()},
        {"artifacts", hashArtifacts(ctx, partialDir)},
        {"summary", ctx.summary()},
        {"records", ctx.records()},
        {"timing", {{"started_at", startedAt}, {"ended_at", db::nowUtc()}, {"seconds", seconds}}},
        {"code_version", core::codeVersion().gitSha},
        {"code_dirty", core::codeVersion().dirty},
        {"host", host},
        {"ranks", comm.size()},
    };
    if (!ctx.findings().empty()) manifest["findings"] = ctx.findings().toJson();
    if (!task.sweepWritten.empty()) manifest["sweep_written"] = task.sweepWritten;
    core::writeFileAtomically(partialDir / "manifest.json", manifest.dump(2) + "\n");
    core::failPoint("stage.before_rename");
    // A complete folder without a database record (killed between rename and commit) is not
    // trusted: it is replaced.
    fs::remove_all(finalDir);
    fs::rename(partialDir, finalDir);
    core::syncDirectory(finalDir.parent_path());
    core::failPoint("stage.after_rename");
    outcome.status = InstanceOutcome::Status::Done;
    outcome.manifest = std::move(manifest);
  } catch (const stages::StageInterrupted&) {
    outcome.status = InstanceOutcome::Status::Interrupted;
    outcome.error = "interrupted by a stop signal (SIGTERM or SIGINT)";
  } catch (const std::exception& e) {
    outcome.status = InstanceOutcome::Status::Failed;
    outcome.error = e.what();
  }
  return outcome;
}

}  // namespace grainbridge::workflows::exec
