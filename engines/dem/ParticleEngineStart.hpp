#pragma once
// What a particle engine (grainbridge's own or LAMMPS, engines/particle_engines) is started or
// restored with, whichever it is: the setup, the run's length, the instance's ranks and where its
// frames go.
#include <cstdint>
#include <filesystem>
#include <vector>

#include "core/io/FrameMetadata.hpp"
#include "core/parallel/Communicator.hpp"
#include "engines/dem/SimulationSetup.hpp"

namespace grainbridge::dem {

struct ParticleEngineStart {
  SimulationSetup setup;
  // The radius of each species (LAMMPS's Hertzian law scales by sqrt(delta R_eff), ours by
  // sqrt(delta / d)).
  std::vector<double> speciesRadii;
  // The run's last step (LAMMPS's run start/stop: fix deform interpolates its tilt towards it).
  std::int64_t lastStep = 0;
  // The instance's communicator (MPI_COMM_NULL in a plain serial run).
  MPI_Comm comm = MPI_COMM_NULL;
  std::filesystem::path outputDir;
  core::io::ArtifactStamp stamp;
};

}  // namespace grainbridge::dem
