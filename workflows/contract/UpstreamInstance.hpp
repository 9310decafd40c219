#pragma once
// The run-time half of the stage contract (DESIGN.md, "Stage contracts"): what a downstream
// stage, or the report, reads of a completed upstream instance. It reads the instance's
// products — its summary values (per phase where there are phases: mean_height_<phase>), its
// artifacts by kind, the columns of its series, the materials its field frames carry — never the
// params the upstream ran with, so a comparing stage takes any engine that produces what it
// needs (mfm, tfdem, one still to come). The manifest stays private to this class.
//
// stages/ (the stage types) and report/ (the workflow report) both include this header and
// neither includes the other's.
#include <filesystem>
#include <functional>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "core/data/Materials.hpp"
#include "workflows/contract/Findings.hpp"

namespace grainbridge::workflows::contract {

// One file an instance wrote, as it registers it.
struct ArtifactEntry {
  std::string path;  // relative to the instance folder
  std::string kind;  // "particle_frame", "field_frame", "mean_field_frame", "xdmf", "csv", "svg", ...
};

// A summary value worth a column (and a plot along a sweep) in the report, with its SI unit
// ("–" when dimensionless). Its block-averaging error, if any, is the summary's <key>_err.
struct ResultColumn {
  std::string key;
  std::string unit;
};

// What a report shows of a stage type (its declared key results, the SI unit of a swept
// parameter, the summary values that tell the replicas of a sweep point apart), handed to report/
// by the caller that knows the types (stages::StageRegistry).
struct StageTypeView {
  std::vector<ResultColumn> keyResults;
  std::function<std::string(const std::string& param)> sweptUnit;  // "" when dimensionless or unknown
  // Summary values shown beside the sweep point: which replica an instance is (closure_sample, ...).
  std::vector<std::string> replicaKeys;
};
using StageTypeLookup = std::function<std::optional<StageTypeView>(const std::string& typeName)>;

// A summary value with its block-averaging error (the summary's <key>_err; NaN when it has none).
struct SummaryValue {
  double value = 0.0;
  double error = 0.0;
};

class UpstreamInstance {
 public:
  // `manifest` is the instance's manifest.json; `stageType` is shown by reports only.
  UpstreamInstance(std::string stage, std::string stageType, std::string key, std::filesystem::path dir,
                   nlohmann::json manifest);

  [[nodiscard]] const std::string& stage() const { return stage_; }
  [[nodiscard]] const std::string& key() const { return key_; }
  // The first 12 characters of the key, as messages name an instance.
  [[nodiscard]] std::string shortKey() const { return key_.substr(0, 12); }
  // Absolute path of the completed instance folder.
  [[nodiscard]] const std::filesystem::path& dir() const { return dir_; }
  // The type's name, for a report's labels. A stage decides what to read by products (its
  // checkAgainstUpstream against PlannedOutput), never by the type's name.
  [[nodiscard]] const std::string& stageTypeLabel() const { return stageType_; }

  // The sweep point it ran at: SI values by swept parameter ({} unless swept), and the same as
  // the config wrote them ("1.92 m/s"; the SI point where none was recorded). A replica (a
  // closure sample) has its instance's sweep point; what tells it apart is in its summary.
  [[nodiscard]] const nlohmann::json& sweepPoint() const { return sweepPoint_; }
  [[nodiscard]] const nlohmann::json& sweepWritten() const { return sweepWritten_; }
  // The sweep point as the plan gives it now, which the executor and the report pass in: a cached
  // instance's manifest may predate the config's wording, or the sweep point's form (before issue
  // 57 a closure sample's carried its sample number, which its summary holds).
  void setSweep(nlohmann::json point, nlohmann::json written);

  // Every summary value (numbers, and a few strings such as a run's closure name).
  [[nodiscard]] const nlohmann::json& summary() const { return summary_; }
  [[nodiscard]] bool hasSummary(const std::string& key) const;
  // A numeric summary value and its error; nullopt when the summary has no number `key`.
  [[nodiscard]] std::optional<SummaryValue> summaryValue(const std::string& key) const;
  // A string summary value, or `fallback`.
  [[nodiscard]] std::string summaryText(const std::string& key, const std::string& fallback = "") const;

  [[nodiscard]] std::vector<ArtifactEntry> artifacts() const;
  // Absolute paths of the artifacts of `kind`, in the order they were registered.
  [[nodiscard]] std::vector<std::filesystem::path> artifactsOfKind(const std::string& kind) const;

  // The columns of its series.csv by name (time first). Throws grainbridge::Error naming the
  // instance when it wrote none, or the file and line of a malformed row.
  [[nodiscard]] std::map<std::string, std::vector<double>> seriesColumns() const;
  // The materials stamped on its field frames (gravity; each solids phase's name, diameter and
  // density as a species), read from the first one; throws naming the instance when it wrote no
  // field frame.
  [[nodiscard]] core::data::Materials fieldMaterials() const;
  // Its solids phases, from fieldMaterials().
  [[nodiscard]] std::vector<core::data::SpeciesMaterial> phases() const { return fieldMaterials().species; }

  // Rows for the closure database it recorded, by table ("closure_points", ...); empty when none.
  [[nodiscard]] std::vector<nlohmann::json> records(const std::string& table) const;
  // What it found (a comparing stage), or nullopt.
  [[nodiscard]] std::optional<contract::Findings> findings() const;

 private:
  std::string stage_, stageType_, key_;
  std::filesystem::path dir_;
  nlohmann::json manifest_;
  nlohmann::json summary_, sweepPoint_, sweepWritten_;
};

}  // namespace grainbridge::workflows::contract
