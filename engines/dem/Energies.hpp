#pragma once
// The kinetic energies of the mobile particles, as every particle engine reports them.

namespace grainbridge::dem {

struct Energies {
  double translational = 0.0;  // sum 1/2 m v^2 over mobile particles
  double rotational = 0.0;     // sum 1/2 I omega^2
  [[nodiscard]] double kinetic() const { return translational + rotational; }
};

}  // namespace grainbridge::dem
