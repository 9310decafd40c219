#pragma once
// The materials contract of particle frames (DESIGN.md, "Materials travel with the data"):
// what a particle engine writes beside every frame so that a reader (extract) never needs the
// params of the stage that wrote it. A frame from dem, from a dem run started from a LAMMPS data
// file, or from the coming tfdem stage gives extract the same state: species (diameter,
// density), contact coefficients per species pair and per wall, gravity. The imposed shear is
// the domain's (Domain::leesEdwardsShearRate), already in every frame.
//
// Stored in a particle frame file as the group /materials (plain numeric datasets, names as
// attributes); a frame without it (an older file, a particle_gas frame) reads as `empty()`.
#include <optional>
#include <string>
#include <vector>

#include "core/Types.hpp"

namespace grainbridge::core::data {

struct SpeciesMaterial {
  std::string name;
  double diameter = 0.0;  // m
  double density = 0.0;   // kg/m3
  bool operator==(const SpeciesMaterial&) const = default;
};

// One species pair (wall < 0) or a species against wall `wall`.
struct ContactMaterial {
  std::int32_t speciesA = 0;
  std::int32_t speciesB = 0;  // == speciesA for a wall contact
  std::int32_t wall = -1;
  double restitution = 1.0;  // normal coefficient of restitution the engine was set to
  double friction = 0.0;     // Coulomb coefficient mu
  double stiffness = 0.0;    // normal spring k_n (N/m, or N/m^1.5 for Hertz)
  double tangentialStiffness = 0.0;
  bool operator==(const ContactMaterial&) const = default;
};

struct Materials {
  std::vector<SpeciesMaterial> species;
  std::vector<ContactMaterial> pairs;  // species pairs, a <= b
  std::vector<ContactMaterial> walls;  // per wall and species
  Vec3 gravity = Vec3::Zero();

  [[nodiscard]] bool empty() const { return species.empty() && pairs.empty() && walls.empty(); }
  // The pair (a, b) in either order, or nullopt.
  [[nodiscard]] std::optional<ContactMaterial> pair(std::int32_t a, std::int32_t b) const;
  // Unit vector against gravity; +z without gravity (heights of the surface analysis).
  [[nodiscard]] Vec3 up() const;
  // Throws grainbridge::Error naming the entry whose species or values are out of range.
  void validate() const;
  bool operator==(const Materials&) const = default;
};

}  // namespace grainbridge::core::data
