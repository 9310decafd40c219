#pragma once
// The columns of a `dem` stage's series.csv, as observers of the DEM engine (one per group of
// columns, in the order the stage adds them): kinetic energies, contacts and coordination, the
// whole-domain stress of Eq. 2.3, the force on each wall, the species' centres of mass and free
// surfaces, and the heights of tracked particles.
#include <memory>
#include <vector>

#include "engines/dem/DemEngine.hpp"
#include "workflows/driver/SeriesColumns.hpp"
#include "workflows/stages/DemSetup.hpp"

namespace grainbridge::workflows::stages {

// Every column group of the dem series, in series.csv's order, of either engine (grainbridge's
// or LAMMPS).
std::vector<std::unique_ptr<driver::SeriesColumns>> demSeriesColumns(dem::ParticleEngine& engine,
                                                                     const DemSetup& setup);

}  // namespace grainbridge::workflows::stages
