#pragma once
// Checkpoint files of the DEM engine: an EngineState held exactly (doubles stored as doubles) in a
// core/io checkpoint file (format version and fingerprint on "/", written beside its destination
// and renamed into place, so a kill during the write leaves the previous checkpoint intact). A run
// resumed from it continues bit for bit. The state goes into a group of the open file, the root
// for the dem engine, so a coupled engine (TF-DEM) can keep it in its own group beside the fluid's.
#include <filesystem>
#include <string>

#include "core/io/H5InputFile.hpp"
#include "core/io/H5OutputFile.hpp"
#include "engines/dem/Simulation.hpp"

namespace grainbridge::dem {

// 2: every per-particle array by name (inverse mass and inertia instead of a frozen flag)
// 3: TF-DEM's pressure-gradient force apart from its drag (coupling_pressure)
// 4: the time of the last list build: a sheared run's ghosts were built with the Lees-Edwards
//    offset of that time, and without it a resumed sheared run left its bits at the first step;
//    and pressure control's box, offset base and running p_yy sum
inline constexpr int kCheckpointFormatVersion = 4;

// `state` into `group` of an open file, created unless it is the root.
void writeEngineState(core::io::H5OutputFile& file, const EngineState& state, const std::string& group = "/");
// Throws grainbridge::Error naming the file and the array if one is missing or of another shape.
[[nodiscard]] EngineState readEngineState(const core::io::H5InputFile& file, const std::string& group = "/");

// `fingerprint` identifies the run configuration (the stage key): a checkpoint of another
// configuration is never resumed. The state is at the root.
void writeCheckpoint(const std::filesystem::path& path, const EngineState& state, const std::string& fingerprint);
// Throws grainbridge::Error naming the file if it is unreadable, of another format version, or
// of another configuration.
EngineState readCheckpoint(const std::filesystem::path& path, const std::string& fingerprint);

}  // namespace grainbridge::dem
