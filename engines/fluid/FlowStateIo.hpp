#pragma once
// A FlowState in a group of an open HDF5 file, exactly as held: the time as an attribute of the
// group and the padded arrays (ghosts included) as datasets `pressure`, `phase_<m>_fraction`,
// `phase_<m>_granular_temperature` and `phase_<m>_velocity_<axis>`, so a state read back continues
// bit for bit. A checkpoint (core/io/CheckpointFile) chooses the group: the mfm engine keeps it at
// the root beside its own attributes; a coupled engine (TF-DEM) puts it in a group of its own
// beside the particles' state.
#include <string>

#include "core/io/H5InputFile.hpp"
#include "core/io/H5OutputFile.hpp"
#include "engines/fluid/FlowState.hpp"

namespace grainbridge::fluid {

// Creates `group` unless it is the root.
void writeFlowState(core::io::H5OutputFile& file, const std::string& group, const FlowState& state);

// Reads into `state`, whose grid and phase count the stored state must have; throws
// grainbridge::Error naming the file, the group and the array when it does not.
void readFlowState(const core::io::H5InputFile& file, const std::string& group, FlowState& state);

}  // namespace grainbridge::fluid
