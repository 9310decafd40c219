#include "core/io/FieldFrameReader.hpp"

#include <algorithm>
#include <limits>
#include <utility>

#include "core/Error.hpp"
#include "core/io/FrameFileReading.hpp"
#include "core/io/FrameFiles.hpp"
#include "core/io/H5InputFile.hpp"

namespace grainbridge::core::io {

namespace {
data::GridGeometry readGrid(const H5InputFile& f) {
  data::GridGeometry g;
  const auto origin = f.readDouble3Attribute("/grid", "origin");
  const auto spacing = f.readDouble3Attribute("/grid", "spacing");
  const auto cells = f.readInt3Attribute("/grid", "cells");
  for (std::size_t a = 0; a < 3; ++a) {
    if (cells[a] < 1 || cells[a] > std::numeric_limits<int>::max()) {
      throw f.error("attribute", "/grid/@cells",
                    "axis " + std::to_string(a) + " has " + std::to_string(cells[a]) + " cells, expected at least 1");
    }
    g.origin[static_cast<int>(a)] = origin[a];
    g.spacing[static_cast<int>(a)] = spacing[a];
    g.cells[a] = static_cast<int>(cells[a]);
  }
  return g;
}

// Phase groups in the order the writer stored them (their `index` attribute); HDF5 itself
// lists group members by name.
std::vector<std::string> readPhaseNames(const H5InputFile& f) {
  if (!f.exists("/solids")) throw f.error("group", "/solids", "is missing");
  std::vector<std::pair<std::int64_t, std::string>> phases;
  for (std::string& name : f.children("/solids")) {
    const std::int64_t index = f.readIntAttribute("/solids/" + name, "index");
    phases.emplace_back(index, std::move(name));
  }
  std::sort(phases.begin(), phases.end());
  std::vector<std::string> names;
  for (auto& p : phases) names.push_back(std::move(p.second));
  return names;
}

// Extra cell fields (optional group /extra), in the writer's order, with their component
// counts (the dataset's trailing dimension, 1 when it has none).
std::vector<std::pair<std::string, int>> readExtraNames(const H5InputFile& f) {
  std::vector<std::pair<std::string, int>> out;
  if (!f.exists("/extra")) return out;
  std::vector<std::pair<std::int64_t, std::string>> ordered;
  for (std::string& name : f.children("/extra")) {
    ordered.emplace_back(f.readIntAttribute("/extra/" + name, "index"), std::move(name));
  }
  std::sort(ordered.begin(), ordered.end());
  for (auto& [index, name] : ordered) {
    const auto shape = f.shape("/extra/" + name);
    out.emplace_back(name, shape.size() == 4 ? static_cast<int>(shape[3]) : 1);
  }
  return out;
}

// A field frame's own datasets: the grid, the gas, the solids phases and the extra fields.
void readFieldDatasets(const H5InputFile& f, data::FieldFrame& frame) {
  frame.grid = readGrid(f);
  // Stored [nz][ny][nx] (C order, i fastest) as XDMF's 3DCoRectMesh expects.
  const H5InputFile::Shape cells{static_cast<hsize_t>(frame.grid.cells[2]), static_cast<hsize_t>(frame.grid.cells[1]),
                                 static_cast<hsize_t>(frame.grid.cells[0])};
  frame.ep_g = f.readDoubles("/ep_g", cells);
  frame.p_g = f.readDoubles("/p_g", cells);
  frame.u_g = f.readVec3s("/u_g", cells);
  for (const std::string& name : readPhaseNames(f)) {
    const std::string group = "/solids/" + name;
    data::SolidsPhaseFields phase;
    phase.name = name;
    phase.ep_s = f.readDoubles(group + "/ep_s", cells);
    phase.u_s = f.readVec3s(group + "/u_s", cells);
    phase.theta = f.readDoubles(group + "/theta", cells);
    frame.solids.push_back(std::move(phase));
  }
  for (const auto& [name, components] : readExtraNames(f)) {
    data::NamedCellField extra;
    extra.name = name;
    extra.components = components;
    H5InputFile::Shape shape = cells;
    if (components > 1) shape.push_back(static_cast<hsize_t>(components));
    extra.values = f.readDoubles("/extra/" + name, shape);
    frame.extras.push_back(std::move(extra));
  }
}

void readFieldSummaryRest(const H5InputFile& f, FieldFrameSummary& s) {
  s.grid = readGrid(f);
  s.solidsPhases = readPhaseNames(f);
  s.extras = readExtraNames(f);
}
}  // namespace

data::FieldFrame readFieldFrame(const std::filesystem::path& path) {
  return readFrameFile<data::FieldFrame>(path, kFieldFormatVersion, readFieldDatasets);
}

FieldFrameSummary readFieldFrameSummary(const std::filesystem::path& path) {
  return readFrameFileSummary<FieldFrameSummary>(path, kFieldFormatVersion, readFieldSummaryRest);
}

std::vector<std::filesystem::path> listFieldFrames(const std::filesystem::path& directory) {
  return listFrameFiles(directory, "fields");
}

}  // namespace grainbridge::core::io
