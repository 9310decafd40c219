#pragma once
// The field frame a continuum engine writes of its flow (mfm, the gas of TF-DEM): the header, the
// gas's cell-centred fields and the solids phases' arrays, cell by cell in the frame's [k][j][i]
// order. Written once so that the engines' frames keep one layout; each engine says only where
// its solids values come from.
#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "core/data/FieldFrame.hpp"
#include "engines/fluid/FlowState.hpp"
#include "engines/fluid/StaggeredGrid.hpp"

namespace grainbridge::fluid {

// Fills solids phases' values of the padded cell `cell` at the frame's index `out`.
using SolidsCellFill =
    std::function<void(std::size_t cell, std::size_t out, std::vector<core::data::SolidsPhaseFields>& solids)>;

// `flow` on `grid`'s interior cells at `step`, in SI: ep_g, p_g and u_g of phase 0 (the gas), and
// one phase per name of `solids` whose ep_s, u_s and theta are sized to the cells (theta zero) and
// filled by `fill`, called once per cell. The materials are left to the caller.
[[nodiscard]] core::data::FieldFrame flowFrame(const StaggeredGrid& grid, const FlowState& flow, std::int64_t step,
                                               const std::vector<std::string>& solids, const SolidsCellFill& fill);

}  // namespace grainbridge::fluid
