#pragma once
// Checkpoint files of the DEM engine: one HDF5 file holding an EngineState exactly (doubles
// stored as doubles), written beside its destination and renamed into place, so a kill during
// the write leaves the previous checkpoint intact. A run resumed from it continues bit for bit.
#include <filesystem>
#include <string>

#include "engines/dem/Simulation.hpp"

namespace grainbridge::dem {

// 2: every per-particle array by name (inverse mass and inertia instead of a frozen flag)
inline constexpr int kCheckpointFormatVersion = 2;

// `fingerprint` identifies the run configuration (the stage key): a checkpoint of another
// configuration is never resumed.
void writeCheckpoint(const std::filesystem::path& path, const EngineState& state, const std::string& fingerprint);
// Throws grainbridge::Error naming the file if it is unreadable, of another format version, or
// of another configuration.
EngineState readCheckpoint(const std::filesystem::path& path, const std::string& fingerprint);

}  // namespace grainbridge::dem
