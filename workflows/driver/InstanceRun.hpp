#pragma once
// What the time loop (TimeLoopDriver) needs of the instance it runs: its stage and key (messages,
// the checkpoint fingerprint), its output folder, the communicator of its ranks, the stop flag a
// SIGTERM sets, and where it registers the files it writes. The stage's full context
// (stages::StageContext: params, upstream products, closure tables, summary) extends it, so the
// driver sits below the stages and never includes them.
#include <atomic>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "core/parallel/Communicator.hpp"
#include "workflows/contract/UpstreamInstance.hpp"

namespace grainbridge::workflows::driver {

// Thrown by a stage (or the driver) that saw stopRequested() (SIGTERM, SIGINT) and stopped cleanly.
struct StageInterrupted {};

class InstanceRun {
 public:
  InstanceRun(std::string stage, std::string key, std::filesystem::path outputDir, core::parallel::Communicator& comm,
              const std::atomic<bool>& stopFlag)
      : stage_(std::move(stage)),
        key_(std::move(key)),
        outputDir_(std::move(outputDir)),
        comm_(comm),
        stopFlag_(stopFlag) {}

  [[nodiscard]] const std::string& stage() const { return stage_; }
  [[nodiscard]] const std::string& key() const { return key_; }
  [[nodiscard]] const std::filesystem::path& outputDir() const { return outputDir_; }
  // A stage that can resume keeps its checkpoint here; the executor keeps a partial folder that
  // has one (instead of starting afresh), so a killed or interrupted instance resumes.
  [[nodiscard]] std::filesystem::path checkpointDir() const { return outputDir_ / "checkpoint"; }
  [[nodiscard]] core::parallel::Communicator& comm() { return comm_; }

  // Long stages poll this between steps; when true they write a checkpoint and throw
  // StageInterrupted, as a batch system's SIGTERM before a time limit asks.
  [[nodiscard]] bool stopRequested() const { return stopFlag_.load(std::memory_order_relaxed); }

  // Registers a file (relative to outputDir) as an artifact; the executor hashes it.
  void addArtifact(std::string relativePath, std::string kind) {
    artifacts_.push_back({std::move(relativePath), std::move(kind)});
  }
  [[nodiscard]] const std::vector<contract::ArtifactEntry>& artifacts() const { return artifacts_; }

 private:
  std::string stage_;
  std::string key_;
  std::filesystem::path outputDir_;
  core::parallel::Communicator& comm_;
  const std::atomic<bool>& stopFlag_;
  std::vector<contract::ArtifactEntry> artifacts_;
};

}  // namespace grainbridge::workflows::driver
