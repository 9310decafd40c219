#pragma once
// `grainbridge status`: the state of every stage instance of a workflow (done, running,
// failed, killed, pending) read from the database and the results folder, and `--why STAGE`:
// what changed since the stage last ran (parameters, impl_version, upstream keys).
#include <chrono>
#include <filesystem>
#include <string>
#include <vector>

#include "workflows/config/WorkflowConfig.hpp"
#include "workflows/plan/Plan.hpp"

namespace grainbridge::workflows::status {

struct InstanceStatus {
  std::string label;
  std::string key;
  std::string state;   // done | running | failed | killed | pending
  std::string detail;  // error, holder, or why it is pending
};

std::vector<InstanceStatus> workflowStatus(const config::WorkflowConfig& config, const plan::Plan& plan,
                                           const std::filesystem::path& workDir, std::chrono::seconds staleAfter);

// Human-readable lines explaining, for each instance of `stage`, whether it is up to date and
// if not what differs from its most recent run.
std::vector<std::string> explainStage(const config::WorkflowConfig& config, const plan::Plan& plan,
                                      const std::string& stage, const std::filesystem::path& workDir);

}  // namespace grainbridge::workflows::status
