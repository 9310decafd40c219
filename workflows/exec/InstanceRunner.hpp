#pragma once
// Runs one stage instance on the calling rank(s): writes into `<key>.partial/`, hashes the
// artifacts the stage reported, writes manifest.json, and renames the folder into place only
// when all of that is done, so a reader never sees half an instance. It never touches the
// database: the caller (rank 0) records the outcome.
#include <atomic>
#include <filesystem>

#include "core/parallel/Communicator.hpp"
#include "workflows/exec/InstanceTask.hpp"
#include "workflows/stages/StageRegistry.hpp"

namespace grainbridge::workflows::exec {

InstanceOutcome runInstance(const InstanceTask& task, const stages::StageRegistry& registry,
                            const std::filesystem::path& resultsRoot, core::parallel::Communicator& comm,
                            const std::atomic<bool>& stop);

// Reads the manifest of a completed instance folder; throws Error naming the file if absent.
nlohmann::json readManifest(const std::filesystem::path& instanceDir);

}  // namespace grainbridge::workflows::exec
