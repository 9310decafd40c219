#pragma once
// The dem stage's engine setup (dem::SimulationSetup) as a LAMMPS input (GRANULAR package,
// LAMMPS 2021-2022 as Debian ships it), and every reason a setup cannot be run there as
// grainbridge runs it. Pure text: built and tested without LAMMPS, so `grainbridge check` refuses
// the same options whether or not the library is installed (docs/dem.md, "engine lammps").
//
// Atom types: species s (0-based) is type s + 1 for its mobile particles and type S + s + 1 for
// its frozen ones, so `fix freeze` and the frozen-frozen neighbour exclusion act on a type group
// and pair gran's m_eff of a frozen partner is the mobile one's mass, as in grainbridge.
#include <cstdint>
#include <string>
#include <vector>

#include "core/engine/SetupProblem.hpp"
#include "engines/dem/SimulationSetup.hpp"

namespace grainbridge::lammps {

// The radius of each species, which the Hertzian conversion needs (LAMMPS scales by
// sqrt(delta R_eff), grainbridge by sqrt(delta / d)).
struct LammpsSpeciesRadii {
  std::vector<double> radius;
};

struct LammpsInput {
  // The simulation box: units, atom style, boundaries, region and create_box. A run restored
  // from a LAMMPS restart file gets these from the file instead.
  std::vector<std::string> system;
  // Pair style, neighbour settings, time step, groups, gravity, integration and the computes the
  // frames read: issued after `system` (or after read_restart).
  std::vector<std::string> interactions;
  // One fix wall/gran per wall, issued after `interactions`. A vibrating wall's fix (wiggle) takes
  // its phase from the step at which it is made, which must be `timeOrigin` (the engine resets
  // LAMMPS's step to it around the fix, fresh or restored).
  struct WallFix {
    std::string command;
    bool vibrating = false;
    std::int64_t timeOrigin = 0;
  };
  std::vector<WallFix> walls;
  int atomTypes = 0;
};

// IDs of what LammpsEngine reads back.
inline constexpr const char* kPairForcesCompute = "gb_pair_forces";
inline constexpr const char* kPairAtomsCompute = "gb_pair_atoms";
inline std::string wallFixId(std::size_t wall) { return "gb_wall" + std::to_string(wall); }

// Every reason `setup` cannot run on LAMMPS with the same forces as on grainbridge, at the JSON
// pointer of the dem stage's key (relative to /params) and saying why. Empty when it can.
std::vector<core::engine::SetupProblem> lammpsProblems(const dem::SimulationSetup& setup,
                                                       const LammpsSpeciesRadii& radii);

// The input for a setup without problems (asserts that). `frozenAtoms`: some particles are frozen
// (their types, fix freeze and the neighbour exclusion are issued only then).
LammpsInput lammpsInput(const dem::SimulationSetup& setup, const LammpsSpeciesRadii& radii, bool frozenAtoms);

// A vibration as LAMMPS's wiggle (A (1 - cos omega (n - n0) dt) from the wall's rest position
// `base`): the step n0 its fix must be made at and the base. at_rest is that with n0 = 0;
// mid_stroke's A sin(omega t) is it three quarters of a period later, with the base one amplitude
// back, so n0 = 3 P / 4 for a period of P steps, which must be whole. False when it is not.
bool wiggleOrigin(const dem::Vibration& vibration, double dt, std::int64_t& timeOrigin);

// The xy tilt the box is created with under Lees-Edwards shear: shear_rate L_y dt, one step
// ahead, since fix deform tilts the box at the end of each step (LammpsInput.cpp).
double leesEdwardsInitialTilt(const dem::SimulationSetup& setup);

// True when this build has LAMMPS (Debian's liblammps-dev, found by CMake); `engine` lammps is
// refused at check otherwise.
bool lammpsAvailable();

// One line for `grainbridge --version` and the check's refusal: "LAMMPS <version>" when the engine
// was built, otherwise why it was left out (the reason CMake gave at configure).
std::string lammpsBuildNote();

// LAMMPS atom type of a particle of `species` (0-based), frozen or not.
inline int lammpsType(int species, bool frozen, int speciesCount) { return species + 1 + (frozen ? speciesCount : 0); }

}  // namespace grainbridge::lammps
