#pragma once
// One saved DEM / TF-DEM frame: particle state as per-property arrays plus the contact lists.
// This is the contract between the engines (writers) and extract (reader); extract never
// sees engine internals.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "core/Types.hpp"
#include "core/data/ContactList.hpp"
#include "core/data/Domain.hpp"
#include "core/data/Materials.hpp"
#include "core/data/WallContactList.hpp"

namespace grainbridge::core::data {

struct ParticleFrame {
  double time = 0.0;
  std::int64_t step = 0;
  std::string units = "SI";
  Domain domain;

  std::vector<std::int64_t> id;  // global ids, stable over the run
  std::vector<std::int32_t> species;
  std::vector<double> radius, mass;
  std::vector<Vec3> position, velocity, angularVelocity;
  // Drag from the gas in TF-DEM; empty when the engine has no external force.
  std::vector<Vec3> externalForce;

  ContactList contacts;
  WallContactList wallContacts;
  // Species, contact coefficients and gravity of the engine that wrote the frame (empty for
  // an engine without contacts, or a file written before the contract).
  Materials materials;

  [[nodiscard]] std::size_t size() const { return id.size(); }
  // Throws grainbridge::Error naming the first array whose length is inconsistent, an
  // unknown wall kind, or a wall contact pointing at a wall that does not exist.
  void validate() const;

  bool operator==(const ParticleFrame&) const = default;
};

}  // namespace grainbridge::core::data
