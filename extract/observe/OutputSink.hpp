#pragma once
// Where an extraction puts what it found: files in the instance folder (each an artifact),
// rows for the closure database, and a name for its log lines. The extract stage implements
// it over its StageContext, so the analyses in extract/ never see the workflow layer.
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

namespace grainbridge::extract::observe {

class OutputSink {
 public:
  virtual ~OutputSink() = default;
  [[nodiscard]] virtual const std::filesystem::path& outputDir() const = 0;
  // Who is speaking in log lines (the stage's name).
  [[nodiscard]] virtual const std::string& label() const = 0;
  // Writes `content` to outputDir()/relativePath atomically and registers it as an artifact.
  virtual void writeFile(const std::string& relativePath, const std::string& content, const std::string& kind) = 0;
  // Registers a file already written under outputDir() (field frames).
  virtual void addArtifact(const std::string& relativePath, const std::string& kind) = 0;
  // A row for a closure-database table (closure_points, force_statistics, structure_statistics).
  virtual void addRecord(const std::string& table, nlohmann::json row) = 0;
};

}  // namespace grainbridge::extract::observe
