#include "workflows/exec/InstanceTask.hpp"

namespace grainbridge::workflows::exec {

using nlohmann::json;

json InstanceTask::toJson() const {
  json ups = json::array();
  for (const auto& u : upstream)
    ups.push_back({{"stage", u.stage},
                   {"stage_type", u.stageType},
                   {"key", u.key},
                   {"dir", u.dir},
                   {"sweep_point", u.sweepPoint},
                   {"sweep_written", u.sweepWritten}});
  return {{"workflow", workflow}, {"stage", stage},   {"stage_type", stageType},
          {"key", key},           {"params", params}, {"sweep_point", sweepPoint}, {"sweep_written", sweepWritten}, {"database", database},
          {"upstream", ups},      {"units", units},   {"instance_dir", instanceDir},
          {"group", group},       {"closure_tables", closureTables}, {"rheologies", rheologies}};
}

InstanceTask InstanceTask::fromJson(const json& j) {
  InstanceTask t;
  t.workflow = j.at("workflow");
  t.stage = j.at("stage");
  t.stageType = j.at("stage_type");
  t.key = j.at("key");
  t.params = j.at("params");
  t.sweepPoint = j.at("sweep_point");
  t.sweepWritten = j.value("sweep_written", json::object());
  t.database = j.value("database", "");
  for (const auto& u : j.at("upstream"))
    t.upstream.push_back(
        {u.at("stage"), u.at("stage_type"), u.at("key"), u.at("dir"), u.at("sweep_point"), u.at("sweep_written")});
  t.units = j.at("units");
  t.instanceDir = j.at("instance_dir");
  t.group = j.at("group").get<std::vector<int>>();
  for (const auto& record : j.at("closure_tables")) t.closureTables.push_back(core::loadedClosureTableFromJson(record));
  for (const auto& record : j.at("rheologies")) t.rheologies.push_back(core::loadedRheologyFromJson(record));
  return t;
}

json InstanceOutcome::toJson() const {
  const char* s = status == Status::Done ? "done" : status == Status::Failed ? "failed" : "interrupted";
  return {{"status", s}, {"error", error}, {"manifest", manifest}};
}

InstanceOutcome InstanceOutcome::fromJson(const json& j) {
  InstanceOutcome o;
  const std::string s = j.at("status");
  o.status = s == "done" ? Status::Done : s == "failed" ? Status::Failed : Status::Interrupted;
  o.error = j.at("error");
  o.manifest = j.at("manifest");
  return o;
}

}  // namespace grainbridge::workflows::exec
