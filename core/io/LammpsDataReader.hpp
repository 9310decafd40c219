#pragma once
// Reads a LAMMPS data file written by `write_data` for `atom_style sphere`, so that a user can
// bring a bed settled in LAMMPS (and so that the DEM benchmark starts from the same state as
// LAMMPS's reference run, bench/lammps/).
//
// What is read (LAMMPS read_data format; the first line is a title, `#` starts a comment):
//   header    "N atoms", "N atom types", "xlo xhi", "ylo yhi", "zlo zhi". A "xy xz yz" line
//             (triclinic box) is rejected. Other header lines (bonds, ellipsoids, ...) are ignored.
//   Atoms     "Atoms" or "Atoms # sphere": atom-ID atom-type diameter density x y z, optionally
//             followed by the image flags ix iy iz.
//   Velocities  atom-ID vx vy vz wx wy wz (w: angular velocity), matched to atoms by id.
// Every other section (Masses, Pair Coeffs, Bonds, fix sections, ...) is skipped: a section runs
// until the next line that starts with a letter.
//
// Every failure is a grainbridge::Error naming the file and, where there is one, the line: a
// missing or unreadable file, a missing header line, a triclinic box, an Atoms section whose
// line count differs from the header's, a non-numeric or non-finite field, a wrong column
// count, a type outside 1..atom types, a negative diameter or non-positive density, an atom id
// given twice, a Velocities line for an id that is not an atom, and an atom outside the box by
// more than the tolerance.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <numbers>
#include <string>
#include <vector>

#include "core/Types.hpp"

namespace grainbridge::core::io {

// Default tolerance for atoms outside the box, as a fraction of the box length on that axis.
// write_data wraps periodic coordinates into [lo, hi), but older versions printed only six
// significant digits (data.chute: "0 37.2886 zlo zhi"), so an atom rounded up can sit a few
// 1e-6 of the box length past a bound that was rounded down.
inline constexpr double kLammpsBoxTolerance = 1e-4;

struct LammpsData {
  std::string title;  // the file's first line
  Vec3 lo = Vec3::Zero(), hi = Vec3::Zero();
  std::int64_t atomTypes = 0;
  bool hasVelocities = false;  // the file had a Velocities section

  // Per atom, in file order of the Atoms section.
  std::vector<std::int64_t> id;
  std::vector<int> type;  // 1..atomTypes, as in LAMMPS
  // LAMMPS sphere units: diameter in length, density in mass/length^3 (see mass()).
  std::vector<double> diameter, density;
  // As written, i.e. wrapped into the box for periodic axes; see unwrappedPosition().
  std::vector<Vec3> position;
  // Zero for an atom the Velocities section does not list (or when there is none).
  std::vector<Vec3> velocity, angularVelocity;
  std::vector<Vec3i> image;  // periodic image flags ix iy iz (Eigen::Vector3i); zero if absent

  [[nodiscard]] std::size_t size() const { return id.size(); }

  // LAMMPS atom_style sphere stores density, not mass: for a 3d sphere
  //   mass = density * pi/6 * diameter^3   (= density * 4/3 pi r^3),
  // and a point particle (diameter 0) carries its mass in the density column. (A 2d LAMMPS run
  // uses an areal density instead; grainbridge beds are 3d.)
  [[nodiscard]] double mass(std::size_t i) const {
    const double d = diameter[i];
    return d > 0.0 ? density[i] * std::numbers::pi / 6.0 * d * d * d : density[i];
  }

  // x + (ix, iy, iz) * box length: the position before LAMMPS wrapped it into the box.
  [[nodiscard]] Vec3 unwrappedPosition(std::size_t i) const {
    return position[i] + image[i].cast<double>().cwiseProduct(hi - lo);
  }
};

// `boxTolerance`: how far (as a fraction of the box length on that axis) an atom may lie
// outside [lo, hi] before it is an error.
LammpsData readLammpsData(const std::filesystem::path& path, double boxTolerance = kLammpsBoxTolerance);

}  // namespace grainbridge::core::io
