#include "engines/dem/Checkpoint.hpp"

#include "core/Error.hpp"
#include "core/Files.hpp"
#include "core/io/H5InputFile.hpp"
#include "core/io/H5OutputFile.hpp"

namespace grainbridge::dem {

namespace fs = std::filesystem;

void writeCheckpoint(const fs::path& path, const EngineState& s, const std::string& fingerprint) {
  const fs::path tmp = path.string() + ".tmp";
  {
    core::io::H5OutputFile f(tmp);
    f.writeAttribute("/", "format_version", static_cast<std::int32_t>(kCheckpointFormatVersion));
    f.writeAttribute("/", "fingerprint", fingerprint);
    f.writeAttribute("/", "time", s.time);
    f.writeAttribute("/", "step", static_cast<std::int64_t>(s.step));
    f.writeAttribute("/", "rebuilds_since_sort", static_cast<std::int64_t>(s.rebuildsSinceSort));
    const auto& p = s.particles;
    f.writeDataset("id", p.id);
    f.writeDataset("species", p.species);
    f.writeDataset("radius", p.radius);
    f.writeDataset("mass", p.mass);
    std::vector<std::int32_t> frozen(p.nOwned);
    for (std::size_t i = 0; i < p.nOwned; ++i) frozen[i] = p.isFrozen(i) ? 1 : 0;
    f.writeDataset("frozen", frozen);
    f.writeDataset("position", p.x);
    f.writeDataset("velocity", p.v);
    f.writeDataset("angular_velocity", p.omega);
    f.writeDataset("force", p.force);
    f.writeDataset("torque", p.torque);
    f.writeDataset("coupling_a", p.couplingA);
    f.writeDataset("coupling_b", p.couplingB);
    f.writeDataset("coupling_u", p.couplingU);
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
  const auto id = f.readInt64s("id", {std::nullopt});
  const std::size_t n = id.size();
  const auto species = f.readInt32s("species", {n});
  const auto radius = f.readDoubles("radius", {n});
  const auto mass = f.readDoubles("mass", {n});
  const auto frozen = f.readInt32s("frozen", {n});
  const auto x = f.readVec3s("position", {n});
  const auto v = f.readVec3s("velocity", {n});
  const auto w = f.readVec3s("angular_velocity", {n});
  for (std::size_t i = 0; i < n; ++i)
    s.particles.addOwned(id[i], species[i], radius[i], mass[i], x[i], v[i], w[i], frozen[i] != 0);
  s.particles.force = f.readVec3s("force", {n});
  s.particles.torque = f.readVec3s("torque", {n});
  s.particles.couplingA = f.readVec3s("coupling_a", {n});
  s.particles.couplingB = f.readDoubles("coupling_b", {n});
  s.particles.couplingU = f.readVec3s("coupling_u", {n});
  s.buildPositions = f.readVec3s("build_position", {n});
  const auto low = f.readInt64s("pair_low", {std::nullopt});
  const auto high = f.readInt64s("pair_high", {low.size()});
  const auto ut = f.readVec3s("pair_ut", {low.size()});
  for (std::size_t k = 0; k < low.size(); ++k) s.pairHistory.push_back({low[k], high[k], ut[k]});
  s.wallHistory = f.readVec3s("wall_ut", {std::nullopt});
  return s;
}

}  // namespace grainbridge::dem
