#pragma once
// Which kernel spreads particles and contacts over the cells of a coarse-graining grid
// (MercuryDPM's split: resolved directions x kernel x fields; this is the kernel):
//  - bin: each particle wholly in the cell holding its centre (Eqs. 7.35-7.36); contacts by
//    the exact length of the contact line in each cell.
//  - overlap: each particle by its exact overlap volume with each cell; contacts as for bin.
//  - gaussian(w), lucy(w): smooth kernels of width w (core/grid/SmoothingKernel.hpp: w is a
//    per-axis standard deviation; Gaussian cut at 3w, Lucy cutoff 2 sqrt(3) w), point values at
//    cell centres for particles, exact line integrals for contacts, normalised over the cell
//    lattice so every particle and contact deposits exactly once.
#include <optional>
#include <string>
#include <string_view>

#include "core/grid/SmoothingKernel.hpp"

namespace grainbridge::extract::coarse {

enum class KernelKind { Bin, Overlap, Gaussian, Lucy };

struct CoarseGrainingKernel {
  KernelKind kind = KernelKind::Bin;
  double width = 0.0;  // [m]; gaussian and lucy only

  static CoarseGrainingKernel bin() { return {KernelKind::Bin, 0.0}; }
  static CoarseGrainingKernel overlap() { return {KernelKind::Overlap, 0.0}; }
  static CoarseGrainingKernel gaussian(double w) { return {KernelKind::Gaussian, w}; }
  static CoarseGrainingKernel lucy(double w) { return {KernelKind::Lucy, w}; }
  // "bin", "overlap", "gaussian" or "lucy"; throws grainbridge::Error listing the choices.
  static CoarseGrainingKernel fromName(std::string_view name, double width = 0.0);

  [[nodiscard]] std::string name() const;
  [[nodiscard]] bool smooth() const { return kind == KernelKind::Gaussian || kind == KernelKind::Lucy; }
  // The smooth kernel (throws grainbridge::Error for a width that is not positive), or nothing
  // for bin and overlap.
  [[nodiscard]] std::optional<core::grid::SmoothingKernel> smoothingKernel() const;

  bool operator==(const CoarseGrainingKernel&) const = default;
};

}  // namespace grainbridge::extract::coarse
