#include "workflows/driver/CheckpointSlot.hpp"

#include <nlohmann/json.hpp>

#include "core/Error.hpp"
#include "core/Files.hpp"

namespace grainbridge::workflows::driver {

using nlohmann::json;
namespace fs = std::filesystem;

namespace {

constexpr int kRegisterFormat = 1;

std::string numbered(const char* prefix, std::int64_t n, const char* extension) {
  return std::string(prefix) + std::to_string(n) + extension;
}

}  // namespace

CheckpointSlot::CheckpointSlot(fs::path directory, std::string fingerprint)
    : directory_(std::move(directory)), fingerprint_(std::move(fingerprint)) {}

std::optional<CheckpointRecord> CheckpointSlot::last() const {
  if (!fs::exists(registerFile())) return std::nullopt;
  json r;
  try {
    r = json::parse(core::readFile(registerFile()));
    if (r.at("format").get<int>() != kRegisterFormat) {
      throw Error("format " + r.at("format").dump() + ", this build reads format " + std::to_string(kRegisterFormat));
    }
    if (r.at("fingerprint").get<std::string>() != fingerprint_) {
      throw Error("it belongs to another configuration (stage key " + r.at("fingerprint").get<std::string>() + ")");
    }
    CheckpointRecord record;
    record.phase = r.at("phase").get<std::size_t>();
    record.phaseStep = r.at("phase_step").get<std::int64_t>();
    record.state = directory_ / r.at("state").get<std::string>();
    record.series = core::readFile(directory_ / r.at("series").get<std::string>());
    return record;
  } catch (const std::exception& e) {
    throw Error("checkpoint register " + registerFile().string() + ": " + e.what() +
                "; remove the instance's .partial folder to start it afresh");
  }
}

void CheckpointSlot::save(const core::engine::SteppedEngine& engine, std::size_t phase, std::int64_t phaseStep,
                          const std::string& series) {
  fs::create_directories(directory_);
  std::int64_t previous = -1;
  if (fs::exists(registerFile())) previous = json::parse(core::readFile(registerFile())).at("sequence");
  const std::int64_t n = previous + 1;
  const std::string state = numbered("state-", n, ".ckpt");
  const std::string seriesFile = numbered("series-", n, ".csv");
  engine.saveState(directory_ / state, fingerprint_);
  core::writeFileAtomically(directory_ / seriesFile, series);
  const json r = {{"format", kRegisterFormat},
                  {"fingerprint", fingerprint_},
                  {"sequence", n},
                  {"phase", phase},
                  {"phase_step", phaseStep},
                  {"state", state},
                  {"series", seriesFile},
                  {"step", engine.step()},
                  {"time", engine.time()}};
  core::writeFileAtomically(registerFile(), r.dump(2) + "\n");
  if (previous >= 0) {
    fs::remove(directory_ / numbered("state-", previous, ".ckpt"));
    fs::remove(directory_ / numbered("series-", previous, ".csv"));
  }
}

void CheckpointSlot::clear() { fs::remove_all(directory_); }

}  // namespace grainbridge::workflows::driver
