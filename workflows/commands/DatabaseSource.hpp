#pragma once
// Which database a `grainbridge db ...` command reads: --db FILE, or the one of --config's
// workflow under --workdir. Shared by the provenance and closure commands.
#include <filesystem>

#include "db/Database.hpp"
#include "workflows/commands/Commands.hpp"

namespace grainbridge::workflows::commands {

// Throws UsageError when neither --db nor --config is given.
std::filesystem::path databaseOf(const CommandOptions& opt);
// Opens read-only; a missing file is a UsageError saying so.
db::Database openExisting(const std::filesystem::path& path);

}  // namespace grainbridge::workflows::commands
