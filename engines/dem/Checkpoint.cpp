#include "engines/dem/Checkpoint.hpp"

#include "core/Error.hpp"
#include "core/Files.hpp"
#include "core/io/H5InputFile.hpp"
#include "core/io/H5OutputFile.hpp"

namespace grainbridge::dem {

namespace fs = std::filesystem;

namespace {
void readArray(const core::io::H5InputFile& f, const char* name, std::size_t n, std::vector<std::int64_t>& a) {
  a = f.readInt64s(name, {n});
}
void readArray(const core::io::H5InputFile& f, const char* name, std::size_t n, std::vector<std::int32_t>& a) {
  a = f.readInt32s(name, {n});
}
void readArray(const core::io::H5InputFile& f, const char* name, std::size_t n, std::vector<double>& a) {
  a = f.readDoubles(name, {n});
}
void readArray(const core::io::H5InputFile& f, const char* name, std::size_t n, std::vector<Vec3>& a) {
  a = f.readVec3s(name, {n});
}
}  // namespace

void writeCheckpoint(const fs::path& path, const EngineState& s, const std::string& fingerprint) {
  const fs::path tmp = path.string() + ".tmp";
  {
    core::io::H5OutputFile f(tmp);
    f.writeAttribute("/", "format_version", static_cast<std::int32_t>(kCheckpointFormatVersion));
    f.writeAttribute("/", "fingerprint", fingerprint);
    f.writeAttribute("/", "time", s.time);
    f.writeAttribute("/", "step", static_cast<std::int64_t>(s.step));
    f.writeAttribute("/", "rebuilds_since_sort", static_cast<std::int64_t>(s.rebuildsSinceSort));
    // Every per-particle array by its name (Particles::forEach*Array), exactly as held.
    auto write = [&f](const char* name, const auto& a) { f.writeDataset(name, a); };
    Particles::forEachParticleArray(s.particles, write);
    Particles::forEachOwnedArray(s.particles, write);
    f.writeDataset("build_position", s.buildPositions);
    std::vector<std::int64_t> low;
    std::vector<std::int64_t> high;
    std::vector<Vec3> ut;
    for (const auto& h : s.pairHistory) {
      low.push_back(h.low);
      high.push_back(h.high);
      ut.push_back(h.ut);
    }
    f.writeDataset("pair_low", low);
    f.writeDataset("pair_high", high);
    f.writeDataset("pair_ut", ut);
    f.writeDataset("wall_ut", s.wallHistory);
    f.close();
  }
  fs::rename(tmp, path);
  core::syncDirectory(path.parent_path());
}

EngineState readCheckpoint(const fs::path& path, const std::string& fingerprint) {
  core::io::H5InputFile f(path);
  const auto version = f.readIntAttribute("/", "format_version");
  if (version != kCheckpointFormatVersion) {
    throw Error("checkpoint '" + path.string() + "' has format_version " + std::to_string(version) +
                ", this build reads " + std::to_string(kCheckpointFormatVersion));
  }
  if (f.readStringAttribute("/", "fingerprint") != fingerprint) {
    throw Error("checkpoint '" + path.string() + "' belongs to another configuration");
  }
  EngineState s;
  s.time = f.readDoubleAttribute("/", "time");
  s.step = f.readIntAttribute("/", "step");
  s.rebuildsSinceSort = f.readIntAttribute("/", "rebuilds_since_sort");
  const std::size_t n = f.readInt64s("id", {std::nullopt}).size();
  auto read = [&f, n](const char* name, auto& a) { readArray(f, name, n, a); };
  Particles::forEachParticleArray(s.particles, read);
  Particles::forEachOwnedArray(s.particles, read);
  s.particles.nOwned = n;
  s.buildPositions = f.readVec3s("build_position", {n});
  const auto low = f.readInt64s("pair_low", {std::nullopt});
  const auto high = f.readInt64s("pair_high", {low.size()});
  const auto ut = f.readVec3s("pair_ut", {low.size()});
  for (std::size_t k = 0; k < low.size(); ++k) s.pairHistory.push_back({low[k], high[k], ut[k]});
  s.wallHistory = f.readVec3s("wall_ut", {std::nullopt});
  return s;
}

}  // namespace grainbridge::dem
