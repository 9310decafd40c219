#include "workflows/exec/MpiDispatcher.hpp"

#include <algorithm>
#include <chrono>
#include <thread>

#include <spdlog/spdlog.h>

#include "core/Error.hpp"
#include "core/Log.hpp"
#include "core/parallel/Communicator.hpp"
#include "workflows/exec/InstanceRunner.hpp"
#include "workflows/exec/StopSignal.hpp"
#include "workflows/stages/StageRegistry.hpp"

namespace grainbridge::workflows::exec {

namespace {
constexpr int kTagTask = 1;
constexpr int kTagResult = 2;
constexpr int kTagStop = 3;

void sendJson(const nlohmann::json& j, int dest, int tag) {
  const std::string text = j.dump();
  MPI_Send(text.data(), static_cast<int>(text.size()), MPI_CHAR, dest, tag, MPI_COMM_WORLD);
}

std::string receiveText(MPI_Status& status) {
  int count = 0;
  MPI_Get_count(&status, MPI_CHAR, &count);
  std::string text(static_cast<std::size_t>(count), '\0');
  MPI_Recv(text.data(), count, MPI_CHAR, status.MPI_SOURCE, status.MPI_TAG, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
  return text;
}
}  // namespace

MpiDispatcher::MpiDispatcher() {
  MPI_Comm_size(MPI_COMM_WORLD, &worldSize_);
  for (int r = 1; r < worldSize_; ++r) idle_.insert(r);
}

MpiDispatcher::~MpiDispatcher() {
  GB_ASSERT(running_.empty(), "MPI dispatcher destroyed with instances still running");
  for (int r = 1; r < worldSize_; ++r) MPI_Send(nullptr, 0, MPI_CHAR, r, kTagStop, MPI_COMM_WORLD);
}

std::vector<int> MpiDispatcher::reserve(int ranks) {
  GB_ASSERT(ranks <= idleRanks(), "reserve() beyond idle ranks");
  std::vector<int> group(idle_.begin(), std::next(idle_.begin(), ranks));
  return group;
}

void MpiDispatcher::submit(std::size_t instance, const InstanceTask& task) {
  GB_ASSERT(!task.group.empty(), "MPI task without a rank group");
  nlohmann::json msg = task.toJson();
  msg["tag"] = nextTag_++;  // tag for MPI_Comm_create_group, unique per task
  for (int r : task.group) {
    idle_.erase(r);
    sendJson(msg, r, kTagTask);
  }
  running_[task.group.front()] = {instance, task.group};
}

std::optional<std::pair<std::size_t, InstanceOutcome>> MpiDispatcher::poll() {
  int flag = 0;
  MPI_Status status;
  MPI_Iprobe(MPI_ANY_SOURCE, kTagResult, MPI_COMM_WORLD, &flag, &status);
  if (flag == 0) {
    // Polling keeps rank 0 responsive to signals; 2 ms is nothing next to a stage.
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
    return std::nullopt;
  }
  const std::string text = receiveText(status);
  auto it = running_.find(status.MPI_SOURCE);
  GB_ASSERT(it != running_.end(), "result from a rank that runs nothing");
  auto [instance, group] = it->second;
  running_.erase(it);
  for (int r : group) idle_.insert(r);
  return std::make_pair(instance, InstanceOutcome::fromJson(nlohmann::json::parse(text)));
}

void runMpiWorker(const stages::StageRegistry& registry, const std::filesystem::path& resultsRoot) {
  const int me = core::parallel::worldRank();
  while (true) {
    // Waiting as rank 0 does: Open MPI's blocking probe spins, so an idle worker would take a
    // whole core from the instances still running (with more ranks than cores, each idle rank
    // halved a running stage's speed).
    MPI_Status status;
    int flag = 0;
    while (true) {
      MPI_Iprobe(0, MPI_ANY_TAG, MPI_COMM_WORLD, &flag, &status);
      if (flag != 0) break;
      std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
    if (status.MPI_TAG == kTagStop) {
      MPI_Recv(nullptr, 0, MPI_CHAR, 0, kTagStop, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
      return;
    }
    const auto msg = nlohmann::json::parse(receiveText(status));
    InstanceTask task;
    try {
      task = InstanceTask::fromJson(msg);
    } catch (const std::exception& e) {
      // A task this rank cannot rebuild (a closure table ClosureTable refuses) fails its instance
      // with the reason, as an error inside the run does; the task's first rank reports it.
      if (me == msg.at("group").front().get<int>()) {
        sendJson(InstanceOutcome{InstanceOutcome::Status::Failed, e.what(), nlohmann::json()}.toJson(), 0, kTagResult);
      }
      continue;
    }
    core::parallel::Communicator comm = core::parallel::Communicator::self();
    if (task.group.size() > 1) {
      MPI_Group world;
      MPI_Group group;
      MPI_Comm_group(MPI_COMM_WORLD, &world);
      MPI_Group_incl(world, static_cast<int>(task.group.size()), task.group.data(), &group);
      MPI_Comm raw = MPI_COMM_NULL;
      MPI_Comm_create_group(MPI_COMM_WORLD, group, msg.at("tag").get<int>(), &raw);
      MPI_Group_free(&group);
      MPI_Group_free(&world);
      comm = core::parallel::Communicator(raw, /*owned=*/true);
    }
    // The instance's other ranks run the same stage in step with its first: their progress and
    // info lines would repeat the first rank's line for line, so they log warnings and errors only.
    const auto level = spdlog::get_level();
    if (me != task.group.front()) spdlog::set_level(std::max(level, spdlog::level::warn));
    InstanceOutcome outcome = runInstance(task, registry, resultsRoot, comm, stopFlag());
    spdlog::set_level(level);
    if (me == task.group.front()) sendJson(outcome.toJson(), 0, kTagResult);
  }
}

}  // namespace grainbridge::workflows::exec
