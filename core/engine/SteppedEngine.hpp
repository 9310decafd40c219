#pragma once
// What the time-loop driver of the engine stages (workflows/driver/TimeLoopDriver) needs of a
// time-stepping engine, and nothing more: advance one step, say where it is, save its state,
// write its frames. Everything around the loop (the output schedule, checkpoints on wall-clock
// time and SIGTERM, resuming, progress, the throughput log, series columns) is the driver's, so
// a new engine (multi-fluid, TF-DEM) is its physics plus this interface. A virtual call per
// step, never inside an engine's own loops.
//
// Restoring is the other half of saveState(): the stage gives the driver a factory that builds
// the engine from a saved state (engines are constructed whole, not patched), and the driver
// decides whether to call it or the one that builds a fresh engine.
#include <cstdint>
#include <filesystem>
#include <string>

namespace grainbridge::core::engine {

class SteppedEngine {
 public:
  virtual ~SteppedEngine() = default;

  // One time step. `observed`: the state after this step will be written or sampled (a frame or
  // a series row), so an engine that records extra data only on demand (DEM's contact list)
  // records it; observing must not change the trajectory.
  virtual void advance(bool observed) = 0;
  [[nodiscard]] virtual double time() const = 0;
  [[nodiscard]] virtual std::int64_t step() const = 0;

  // Everything needed to continue bit for bit, into `file` (which the engine may overwrite),
  // tagged with `fingerprint` (the stage key) so that a state of another configuration is never
  // restored.
  virtual void saveState(const std::filesystem::path& file, const std::string& fingerprint) const = 0;

  // Writes the current state as this engine's frames (particle frames, field frames or both)
  // into its output folder.
  virtual void writeFrames() = 0;
  // After advance() threw: writes the current state as frames if it is still a usable state
  // (finite), and says whether it did, so the run's last good state is on disk.
  virtual bool writeFramesIfUsable() = 0;

  // The work of one step for the throughput log: "particle" and the particle count give
  // particle-steps/s; a grid engine counts cells.
  [[nodiscard]] virtual std::string workItem() const = 0;
  [[nodiscard]] virtual std::int64_t workItems() const = 0;
  // The throughput's steps: the engine's own time steps taken so far, each over all workItems()
  // (the log counts the difference over a phase). One per advance() by default; an engine whose
  // advance() is several steps counts those: the multi-fluid solver's adaptive steps up to the
  // next output time, TF-DEM's DEM sub-steps of a gas step.
  [[nodiscard]] virtual std::int64_t workSteps() const { return step(); }
  // What one of them is called in the log ("solver step", "DEM step"; "step" by default).
  [[nodiscard]] virtual std::string workStep() const { return "step"; }
  // Appended to the throughput line ("4.07 contacts per particle").
  [[nodiscard]] virtual std::string throughputNote() const { return {}; }
};

}  // namespace grainbridge::core::engine
