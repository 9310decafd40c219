#include "workflows/commands/DatabaseSource.hpp"

#include "workflows/config/WorkflowConfig.hpp"
#include "workflows/exec/Scheduler.hpp"
#include "workflows/stages/StageRegistry.hpp"

namespace grainbridge::workflows::commands {

std::filesystem::path databaseOf(const CommandOptions& opt) {
  if (!opt.database.empty()) return opt.database;
  if (!opt.config.empty()) {
    return exec::databasePath(config::loadWorkflow(opt.config, stages::StageRegistry::builtin()), opt.workDir);
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
