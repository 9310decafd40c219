#pragma once
// The checkpoints of one engine stage instance, in its `checkpoint/` folder (which tells the
// executor to keep the partial instance folder for a resume):
//   driver.json          the register: where the loop was (phase, step in it), which files hold
//                        the engine state and the series written so far, and the stage key;
//   state-<n>.ckpt, series-<n>.csv   the files of checkpoint n.
// A checkpoint's files are written first and the register is renamed over the old one last, so
// a kill at any moment leaves the register naming a complete checkpoint; the files of the
// previous one are removed after that. The register of another configuration (stage key) is
// never resumed.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>

#include "core/engine/SteppedEngine.hpp"

namespace grainbridge::workflows::driver {

struct CheckpointRecord {
  std::size_t phase = 0;        // index of the phase the loop was in
  std::int64_t phaseStep = 0;   // steps of that phase already done
  std::filesystem::path state;  // the engine's saved state
  std::string series;           // series.csv as written so far (header included)
};

class CheckpointSlot {
 public:
  CheckpointSlot(std::filesystem::path directory, std::string fingerprint);

  // The last registered checkpoint, or nothing. Throws grainbridge::Error naming the file if the
  // register is unreadable or belongs to another configuration.
  [[nodiscard]] std::optional<CheckpointRecord> last() const;
  // Registers a new checkpoint: the engine's state and the series so far.
  void save(const core::engine::SteppedEngine& engine, std::size_t phase, std::int64_t phaseStep,
            const std::string& series);
  // The run is complete: its checkpoints have served.
  void clear();

 private:
  [[nodiscard]] std::filesystem::path registerFile() const { return directory_ / "driver.json"; }

  std::filesystem::path directory_;
  std::string fingerprint_;
};

}  // namespace grainbridge::workflows::driver
