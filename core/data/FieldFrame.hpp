#pragma once
// One saved continuum frame (MFM or the gas side of TF-DEM, or coarse-grained DEM): cell-
// centred fields on a uniform grid. Cell arrays are C order [k][j][i] (i fastest), the
// order HDF5 and XDMF's 3DCoRectMesh expect, so they are written without reordering.
#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "core/Types.hpp"
#include "core/data/Materials.hpp"

namespace grainbridge::core::data {

struct GridGeometry {
  Vec3 origin = Vec3::Zero();         // lower corner of cell (0,0,0)
  Vec3 spacing = Vec3::Ones();        // cell size dx, dy, dz
  std::array<int, 3> cells{0, 0, 0};  // nx, ny, nz

  [[nodiscard]] std::size_t cellCount() const;
  // Flat index of cell (i, j, k) in [k][j][i] order.
  [[nodiscard]] std::size_t index(int i, int j, int k) const {
    return (static_cast<std::size_t>(k) * static_cast<std::size_t>(cells[1]) + static_cast<std::size_t>(j)) *
               static_cast<std::size_t>(cells[0]) +
           static_cast<std::size_t>(i);
  }

  bool operator==(const GridGeometry&) const = default;
};

struct SolidsPhaseFields {
  // Used as an HDF5 group and XDMF attribute name: letters, digits, '_' and '-' only.
  std::string name;
  std::vector<double> ep_s;   // solids volume fraction
  std::vector<Vec3> u_s;      // solids velocity
  std::vector<double> theta;  // granular temperature

  bool operator==(const SolidsPhaseFields&) const = default;
};

// Any further cell field (coarse-grained DEM: stress tensor, pressure, coordination, ...):
// `components` values per cell, 1 (scalar), 3 (vector) or 9 (tensor, row-major), cell-major.
struct NamedCellField {
  std::string name;  // a plain identifier, as phase names
  int components = 1;
  std::vector<double> values;
  bool operator==(const NamedCellField&) const = default;
};

struct FieldFrame {
  double time = 0.0;
  std::int64_t step = 0;
  std::string units = "SI";
  GridGeometry grid;
  std::vector<double> ep_g, p_g;  // gas volume fraction, gas pressure
  std::vector<Vec3> u_g;          // gas velocity
  std::vector<SolidsPhaseFields> solids;
  std::vector<NamedCellField> extras;  // written under /extra only when present
  // What the fields are of (DESIGN.md, "Field frames carry their materials too"): gravity, and
  // each solids phase as a species (name, diameter, density) in the order of `solids`, so a
  // reader never needs the params of the stage that wrote the frame. Empty in a frame that does
  // not know them (coarse-grained DEM fields, older files).
  Materials materials;

  // Throws grainbridge::Error naming the array whose length is not the cell count, a bad
  // grid, a phase name that is empty, repeated or not a plain identifier, or materials whose
  // species are not the solids phases.
  void validate() const;

  bool operator==(const FieldFrame&) const = default;
};

}  // namespace grainbridge::core::data
