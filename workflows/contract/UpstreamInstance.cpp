#include "workflows/contract/UpstreamInstance.hpp"

#include <cmath>
#include <limits>

#include "core/Error.hpp"
#include "core/io/H5InputFile.hpp"
#include "core/io/MaterialsIo.hpp"
#include "workflows/contract/NumericCsv.hpp"

namespace grainbridge::workflows::contract {

using nlohmann::json;
namespace fs = std::filesystem;

UpstreamInstance::UpstreamInstance(std::string stage, std::string stageType, std::string key, fs::path dir,
                                   json manifest)
    : stage_(std::move(stage)),
      stageType_(std::move(stageType)),
      key_(std::move(key)),
      dir_(std::move(dir)),
      manifest_(std::move(manifest)) {
  summary_ = manifest_.value("summary", json::object());
  setSweep(manifest_.value("sweep_point", json::object()), manifest_.value("sweep_written", json::object()));
}

void UpstreamInstance::setSweep(json point, json written) {
  sweepPoint_ = std::move(point);
  sweepWritten_ = written.empty() ? sweepPoint_ : std::move(written);
}

bool UpstreamInstance::hasSummary(const std::string& key) const { return summary_.contains(key); }

std::optional<SummaryValue> UpstreamInstance::summaryValue(const std::string& key) const {
  const auto it = summary_.find(key);
  if (it == summary_.end() || !it->is_number()) return std::nullopt;
  SummaryValue v{it->get<double>(), std::numeric_limits<double>::quiet_NaN()};
  if (const auto err = summary_.find(key + "_err"); err != summary_.end() && err->is_number()) {
    v.error = err->get<double>();
  }
  return v;
}

std::string UpstreamInstance::summaryText(const std::string& key, const std::string& fallback) const {
  const auto it = summary_.find(key);
  return it != summary_.end() && it->is_string() ? it->get<std::string>() : fallback;
}

std::vector<ArtifactEntry> UpstreamInstance::artifacts() const {
  std::vector<ArtifactEntry> out;
  for (const auto& a : manifest_.value("artifacts", json::array())) {
    out.push_back({a.value("path", ""), a.value("kind", "")});
  }
  return out;
}

std::vector<fs::path> UpstreamInstance::artifactsOfKind(const std::string& kind) const {
  std::vector<fs::path> out;
  for (const auto& a : artifacts()) {
    if (a.kind == kind) out.push_back(dir_ / a.path);
  }
  return out;
}

std::map<std::string, std::vector<double>> UpstreamInstance::seriesColumns() const {
  for (const auto& a : artifacts()) {
    if (a.path == "series.csv") return contract::readNumericCsv(dir_ / a.path);
  }
  throw Error("upstream " + stage_ + " (" + shortKey() + ") wrote no series.csv");
}

core::data::Materials UpstreamInstance::fieldMaterials() const {
  auto frames = artifactsOfKind("field_frame");
  if (frames.empty()) frames = artifactsOfKind("mean_field_frame");
  if (frames.empty()) throw Error("upstream " + stage_ + " (" + shortKey() + ") wrote no field frame");
  const core::io::H5InputFile file(frames.front());
  auto materials = core::io::readMaterials(file);
  if (materials.species.empty()) {
    throw Error("field frame '" + frames.front().string() +
                "' carries no materials (written by an older grainbridge: rerun " + stage_ + ")");
  }
  return materials;
}

std::vector<json> UpstreamInstance::records(const std::string& table) const {
  std::vector<json> out;
  const json all = manifest_.value("records", json::object());
  for (const auto& row : all.value(table, json::array())) out.push_back(row);
  return out;
}

std::optional<contract::Findings> UpstreamInstance::findings() const {
  if (!manifest_.contains("findings")) return std::nullopt;
  return contract::Findings::fromJson(manifest_.at("findings"));
}

}  // namespace grainbridge::workflows::contract
