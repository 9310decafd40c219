#pragma once
// The materials contract (core/data/Materials) in a particle or field frame file: group /materials with
//   species_diameter, species_density           [n_species]   and attributes species_name_<s>
//   pair_species [n_pairs x 2] (int32), pair_restitution, pair_friction, pair_stiffness,
//   pair_tangential_stiffness                    [n_pairs]
//   wall_index, wall_species (int32), wall_restitution, ... [n_wall_entries]
//   attribute gravity (3 doubles)
// Plain numeric datasets, so equal materials give equal bytes.
#include "core/data/Materials.hpp"

namespace grainbridge::core::io {

class H5OutputFile;
class H5InputFile;

// Writes nothing for empty materials.
void writeMaterials(H5OutputFile& file, const data::Materials& materials);
// Empty materials when the file has no /materials group; throws (naming file and dataset)
// when it has a malformed one.
data::Materials readMaterials(const H5InputFile& file);

}  // namespace grainbridge::core::io
