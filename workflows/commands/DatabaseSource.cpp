#include "workflows/commands/DatabaseSource.hpp"

#include "workflows/config/WorkflowConfig.hpp"
#include "workflows/exec/Scheduler.hpp"
#include "workflows/stages/StageRegistry.hpp"

namespace grainbridge::workflows::commands {

namespace fs = std::filesystem;

std::string resultsElsewhereHint(const config::WorkflowConfig& config, const fs::path& workDir) {
  const fs::path here = exec::databasePath(config, workDir);
  if (fs::exists(here) || config.database.is_absolute()) return "";
  // A config in configs/ of a project is usually run from the project's folder: try the config's
  // folder and the one above it.
  const fs::path configDir = fs::absolute(config.sourcePath).parent_path();
  for (const fs::path& dir : {configDir, configDir.parent_path()}) {
    const fs::path there = exec::databasePath(config, dir);
    if (fs::exists(there) && fs::weakly_canonical(dir) != fs::weakly_canonical(workDir)) {
      return "results are found from the current folder (or --workdir), not from the config's: no " + here.string() +
             " here, but " + there.string() + " exists; run from " + dir.string() + " or add --workdir " + dir.string();
    }
  }
  return "";
}

fs::path databaseOf(const CommandOptions& opt) {
  if (!opt.database.empty()) return opt.database;
  if (!opt.config.empty()) {
    const auto config = config::loadWorkflow(opt.config, stages::StageRegistry::builtin());
    if (const auto hint = resultsElsewhereHint(config, opt.workDir); !hint.empty()) throw UsageError(hint);
    return exec::databasePath(config, opt.workDir);
  }
  throw UsageError("say which database: --db FILE or --config WORKFLOW.json");
}

db::Database openExisting(const std::filesystem::path& path) {
  if (!std::filesystem::exists(path)) {
    throw UsageError("no database at '" + path.string() + "' (has the workflow been run?)");
  }
  return db::Database::openReadOnly(path);
}

}  // namespace grainbridge::workflows::commands
