#pragma once
// A LAMMPS data file (atom_style sphere) of one grain of diameter 1 and density 6/pi (mass 1) in
// the box [0, 8]^3, for tests that follow a single grain read through lammps_data.
#include <string>

namespace grainbridge::testing {

// `position`: "x y z"; `velocity`: "vx vy vz wx wy wz" (velocity, then angular velocity).
inline std::string oneGrainLammpsData(const std::string& position, const std::string& velocity) {
  return "LAMMPS data file: one grain\n\n1 atoms\n1 atom types\n\n0 8 xlo xhi\n0 8 ylo yhi\n0 8 zlo zhi\n\nAtoms\n\n"
         "1 1 1 1.909859317102744 " +
         position + "\n\nVelocities\n\n1 " + velocity + "\n";
}

}  // namespace grainbridge::testing
