#pragma once
// Which database a `grainbridge db ...` command reads: --db FILE, or the one of --config's
// workflow under --workdir. Shared by the provenance and closure commands.
#include <filesystem>
#include <string>

#include "db/Database.hpp"
#include "workflows/commands/Commands.hpp"
#include "workflows/config/WorkflowConfig.hpp"

namespace grainbridge::workflows::commands {

// Results (and the database) are found from the current folder or --workdir, as make and
// snakemake find theirs, never from the config's folder. Where the workflow's database is missing
// there but exists beside the config (its folder or the one above), this says so and how to reach
// it; otherwise "".
std::string resultsElsewhereHint(const config::WorkflowConfig& config, const std::filesystem::path& workDir);

// Throws UsageError when neither --db nor --config is given, or (with the hint above) when the
// config's database is beside the config rather than under --workdir.
std::filesystem::path databaseOf(const CommandOptions& opt);
// Opens read-only; a missing file is a UsageError saying so.
db::Database openExisting(const std::filesystem::path& path);

}  // namespace grainbridge::workflows::commands
