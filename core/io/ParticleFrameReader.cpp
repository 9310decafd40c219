#include "core/io/ParticleFrameReader.hpp"

#include <string>

#include "core/Error.hpp"
#include "core/io/FrameFileReading.hpp"
#include "core/io/FrameFiles.hpp"
#include "core/io/H5InputFile.hpp"

namespace grainbridge::core::io {

namespace {
using Shape = H5InputFile::Shape;

data::Domain readDomain(const H5InputFile& f) {
  data::Domain d;
  const auto lo = f.readDouble3Attribute("/domain", "lo");
  const auto hi = f.readDouble3Attribute("/domain", "hi");
  const auto periodic = f.readInt3Attribute("/domain", "periodic");
  for (int a = 0; a < 3; ++a) {
    const auto k = static_cast<std::size_t>(a);
    d.lo[a] = lo[k];
    d.hi[a] = hi[k];
    d.periodic[k] = periodic[k] != 0;
  }
  d.leesEdwardsOffset = f.readDoubleAttribute("/domain", "lees_edwards_offset");
  d.leesEdwardsShearRate = f.readDoubleAttribute("/domain", "lees_edwards_shear_rate");

  const std::vector<std::int32_t> kind = f.readInt32s("/domain/wall_kind", {std::nullopt});
  const hsize_t w = kind.size();
  const std::vector<Vec3> origin = f.readVec3s("/domain/wall_origin", {w});
  const std::vector<Vec3> direction = f.readVec3s("/domain/wall_direction", {w});
  const std::vector<double> radius = f.readDoubles("/domain/wall_radius", {w});
  const std::vector<Vec3> velocity = f.readVec3s("/domain/wall_velocity", {w});
  d.walls.resize(kind.size());
  for (std::size_t k = 0; k < kind.size(); ++k) {
    if (kind[k] != 0 && kind[k] != 1) {
      throw f.error("dataset", "/domain/wall_kind",
                    "wall " + std::to_string(k) + " has kind code " + std::to_string(kind[k]) +
                        ", expected 0 (plane) or 1 (cylinder)");
    }
    d.walls[k] = {kind[k] == 0 ? "plane" : "cylinder", origin[k], direction[k], radius[k], velocity[k]};
  }
  return d;
}

std::size_t length(const H5InputFile& f, const std::string& dataset) {
  const std::vector<hsize_t> dims = f.shape(dataset);
  if (dims.size() != 1)
    throw f.error("dataset", dataset, "expected a 1-D array, found rank " + std::to_string(dims.size()));
  return static_cast<std::size_t>(dims[0]);
}

// A particle frame's own datasets: the domain, the particles, their contacts and wall contacts.
// The frame's validation after them catches wall indices out of range (the shapes are consistent
// by then).
void readParticleDatasets(const H5InputFile& f, data::ParticleFrame& frame) {
  frame.domain = readDomain(f);

  // N comes from `id`; every other per-particle array must match it.
  frame.id = f.readInt64s("/id", {std::nullopt});
  const hsize_t n = frame.id.size();
  frame.species = f.readInt32s("/species", {n});
  frame.radius = f.readDoubles("/radius", {n});
  frame.mass = f.readDoubles("/mass", {n});
  frame.position = f.readVec3s("/position", {n});
  frame.velocity = f.readVec3s("/velocity", {n});
  frame.angularVelocity = f.readVec3s("/angular_velocity", {n});
  if (f.exists("/external_force")) frame.externalForce = f.readVec3s("/external_force", {n});

  data::ContactList& c = frame.contacts;
  c.i = f.readInt64s("/contacts/i", {std::nullopt});
  const hsize_t m = c.i.size();
  c.j = f.readInt64s("/contacts/j", {m});
  c.branch = f.readVec3s("/contacts/branch", {m});
  c.contactPoint = f.readVec3s("/contacts/contact_point", {m});
  c.forceNormal = f.readVec3s("/contacts/force_normal", {m});
  c.forceTangential = f.readVec3s("/contacts/force_tangential", {m});
  c.forceNormalElastic = f.readVec3s("/contacts/force_normal_elastic", {m});
  c.forceNormalDissipative = f.readVec3s("/contacts/force_normal_dissipative", {m});
  c.forceTangentialElastic = f.readVec3s("/contacts/force_tangential_elastic", {m});
  c.forceTangentialDissipative = f.readVec3s("/contacts/force_tangential_dissipative", {m});

  data::WallContactList& wc = frame.wallContacts;
  wc.particle = f.readInt64s("/wall_contacts/particle", {std::nullopt});
  const hsize_t mw = wc.particle.size();
  wc.wall = f.readInt32s("/wall_contacts/wall", {mw});
  wc.point = f.readVec3s("/wall_contacts/point", {mw});
  wc.forceNormal = f.readVec3s("/wall_contacts/force_normal", {mw});
  wc.forceTangential = f.readVec3s("/wall_contacts/force_tangential", {mw});
}

void readParticleSummaryRest(const H5InputFile& f, ParticleFrameSummary& s) {
  s.particles = length(f, "/id");
  s.contacts = length(f, "/contacts/i");
  s.hasExternalForce = f.exists("/external_force");
}
}  // namespace

data::ParticleFrame readParticleFrame(const std::filesystem::path& path) {
  return readFrameFile<data::ParticleFrame>(path, kParticleFormatVersion, readParticleDatasets);
}

ParticleFrameSummary readParticleFrameSummary(const std::filesystem::path& path) {
  return readFrameFileSummary<ParticleFrameSummary>(path, kParticleFormatVersion, readParticleSummaryRest);
}

std::vector<std::filesystem::path> listParticleFrames(const std::filesystem::path& directory) {
  return listFrameFiles(directory, "particles");
}

}  // namespace grainbridge::core::io
