#include "engines/dem/Checkpoint.hpp"

#include "core/io/CheckpointFile.hpp"
#include "core/io/H5Path.hpp"

namespace grainbridge::dem {

namespace fs = std::filesystem;

namespace {
void readArray(const core::io::H5InputFile& f, const std::string& name, std::size_t n, std::vector<std::int64_t>& a) {
  a = f.readInt64s(name, {n});
}
void readArray(const core::io::H5InputFile& f, const std::string& name, std::size_t n, std::vector<std::int32_t>& a) {
  a = f.readInt32s(name, {n});
}
void readArray(const core::io::H5InputFile& f, const std::string& name, std::size_t n, std::vector<double>& a) {
  a = f.readDoubles(name, {n});
}
void readArray(const core::io::H5InputFile& f, const std::string& name, std::size_t n, std::vector<Vec3>& a) {
  a = f.readVec3s(name, {n});
}
}  // namespace

void writeEngineState(core::io::H5OutputFile& f, const EngineState& s, const std::string& group) {
  if (group != "/") f.createGroup(group);
  auto at = [&group](const char* name) { return core::io::memberPath(group, name); };
  f.writeAttribute(group, "time", s.time);
  f.writeAttribute(group, "step", static_cast<std::int64_t>(s.step));
  f.writeAttribute(group, "rebuilds_since_sort", static_cast<std::int64_t>(s.rebuildsSinceSort));
  f.writeAttribute(group, "build_time", s.buildTime);
  f.writeAttribute(group, "box_high_y", s.boxHighY);
  f.writeAttribute(group, "shear_offset_base", s.shearOffsetBase);
  f.writeAttribute(group, "shear_offset_time", s.shearOffsetTime);
  f.writeAttribute(group, "normal_stress_sum", s.normalStressSum);
  f.writeAttribute(group, "normal_stress_samples", static_cast<std::int64_t>(s.normalStressSamples));
  // Every per-particle array by its name (Particles::forEach*Array), exactly as held.
  auto write = [&](const char* name, const auto& a) { f.writeDataset(at(name), a); };
  Particles::forEachParticleArray(s.particles, write);
  Particles::forEachOwnedArray(s.particles, write);
  f.writeDataset(at("build_position"), s.buildPositions);
  std::vector<std::int64_t> low;
  std::vector<std::int64_t> high;
  std::vector<Vec3> ut;
  for (const auto& h : s.pairHistory) {
    low.push_back(h.low);
    high.push_back(h.high);
    ut.push_back(h.ut);
  }
  f.writeDataset(at("pair_low"), low);
  f.writeDataset(at("pair_high"), high);
  f.writeDataset(at("pair_ut"), ut);
  f.writeDataset(at("wall_ut"), s.wallHistory);
}

EngineState readEngineState(const core::io::H5InputFile& f, const std::string& group) {
  auto at = [&group](const char* name) { return core::io::memberPath(group, name); };
  EngineState s;
  s.time = f.readDoubleAttribute(group, "time");
  s.step = f.readIntAttribute(group, "step");
  s.rebuildsSinceSort = f.readIntAttribute(group, "rebuilds_since_sort");
  s.buildTime = f.readDoubleAttribute(group, "build_time");
  s.boxHighY = f.readDoubleAttribute(group, "box_high_y");
  s.shearOffsetBase = f.readDoubleAttribute(group, "shear_offset_base");
  s.shearOffsetTime = f.readDoubleAttribute(group, "shear_offset_time");
  s.normalStressSum = f.readDoubleAttribute(group, "normal_stress_sum");
  s.normalStressSamples = f.readIntAttribute(group, "normal_stress_samples");
  const std::size_t n = f.readInt64s(at("id"), {std::nullopt}).size();
  auto read = [&](const char* name, auto& a) { readArray(f, at(name), n, a); };
  Particles::forEachParticleArray(s.particles, read);
  Particles::forEachOwnedArray(s.particles, read);
  s.particles.nOwned = n;
  s.buildPositions = f.readVec3s(at("build_position"), {n});
  const auto low = f.readInt64s(at("pair_low"), {std::nullopt});
  const auto high = f.readInt64s(at("pair_high"), {low.size()});
  const auto ut = f.readVec3s(at("pair_ut"), {low.size()});
  for (std::size_t k = 0; k < low.size(); ++k) s.pairHistory.push_back({low[k], high[k], ut[k]});
  s.wallHistory = f.readVec3s(at("wall_ut"), {std::nullopt});
  return s;
}

void writeCheckpoint(const fs::path& path, const EngineState& s, const std::string& fingerprint) {
  core::io::writeCheckpointFile(path, {kCheckpointFormatVersion, fingerprint},
                                [&s](core::io::H5OutputFile& f) { writeEngineState(f, s); });
}

EngineState readCheckpoint(const fs::path& path, const std::string& fingerprint) {
  return readEngineState(core::io::openCheckpointFile(path, {kCheckpointFormatVersion, fingerprint}));
}

}  // namespace grainbridge::dem
