#include "core/io/FieldFrameWriter.hpp"

#include <sstream>
#include <string>

#include "core/Error.hpp"
#include "core/Files.hpp"
#include "core/io/FrameFiles.hpp"
#include "core/io/H5OutputFile.hpp"
#include "core/io/MaterialsIo.hpp"
#include "core/io/XdmfText.hpp"

namespace grainbridge::core::io {

namespace {

std::string fieldStepGrid(std::int64_t step, const FieldFrameSummary& s) {
  // 3DCoRectMesh takes NODE counts and origin / spacing all ordered z y x; the cell arrays
  // are [nz][ny][nx], so Center="Cell" attributes map onto the mesh without reordering.
  std::ostringstream x;
  const data::GridGeometry& g = s.grid;
  const std::string file = "frames/" + s.file.filename().string() + ":";
  const std::string cells =
      std::to_string(g.cells[2]) + " " + std::to_string(g.cells[1]) + " " + std::to_string(g.cells[0]);
  const std::string nodes =
      std::to_string(g.cells[2] + 1) + " " + std::to_string(g.cells[1] + 1) + " " + std::to_string(g.cells[0] + 1);
  const auto zyx = [](const Vec3& v) { return formatReal(v.z()) + " " + formatReal(v.y()) + " " + formatReal(v.x()); };
  const auto scalar = [&](const std::string& name, const std::string& dataset) {
    return xdmfAttribute(name, "Scalar", "Cell", xdmfHdfItem(cells, "Float", 8, file + dataset));
  };
  const auto vector = [&](const std::string& name, const std::string& dataset) {
    return xdmfAttribute(name, "Vector", "Cell", xdmfHdfItem(cells + " 3", "Float", 8, file + dataset));
  };
  x << "   <Grid Name=\"step_" << step << "\" GridType=\"Uniform\">\n"
    << "    <Time Value=\"" << formatReal(s.time) << "\"/>\n"
    << "    <Topology TopologyType=\"3DCoRectMesh\" Dimensions=\"" << nodes << "\"/>\n"
    << "    <Geometry GeometryType=\"ORIGIN_DXDYDZ\">\n"
    << "     <DataItem Dimensions=\"3\" NumberType=\"Float\" Precision=\"8\" Format=\"XML\">" << zyx(g.origin)
    << "</DataItem>\n"
    << "     <DataItem Dimensions=\"3\" NumberType=\"Float\" Precision=\"8\" Format=\"XML\">" << zyx(g.spacing)
    << "</DataItem>\n"
    << "    </Geometry>\n"
    << "    " << scalar("ep_g", "/ep_g") << "\n"
    << "    " << scalar("p_g", "/p_g") << "\n"
    << "    " << vector("u_g", "/u_g") << "\n";
  for (const std::string& phase : s.solidsPhases) {
    // Phase names are plain identifiers (FieldFrame::validate), safe in XML and HDF5.
    x << "    " << scalar("ep_s_" + phase, "/solids/" + phase + "/ep_s") << "\n"
      << "    " << vector("u_s_" + phase, "/solids/" + phase + "/u_s") << "\n"
      << "    " << scalar("theta_" + phase, "/solids/" + phase + "/theta") << "\n";
  }
  for (const auto& [name, components] : s.extras) {
    const std::string dims = components == 1 ? cells : cells + " " + std::to_string(components);
    const char* type = components == 1 ? "Scalar" : components == 3 ? "Vector" : "Tensor";
    x << "    " << xdmfAttribute(name, type, "Cell", xdmfHdfItem(dims, "Float", 8, file + "/extra/" + name)) << "\n";
  }
  x << "   </Grid>\n";
  return x.str();
}

}  // namespace

FieldFrameWriter::FieldFrameWriter(std::filesystem::path directory, ArtifactStamp stamp, int deflateLevel)
    : stamp_(std::move(stamp)),
      deflateLevel_(deflateLevel),
      series_(std::move(directory), "fields", readFieldFrameSummary, fieldStepGrid) {}

std::filesystem::path FieldFrameWriter::write(const data::FieldFrame& frame) {
  frame.validate();
  FieldFrameSummary s{{}, frame.step, frame.time, frame.grid, {}, {}};
  for (const auto& phase : frame.solids) s.solidsPhases.push_back(phase.name);
  for (const auto& extra : frame.extras) s.extras.emplace_back(extra.name, extra.components);
  return series_.write(
      frame.step, [&](const std::filesystem::path& temporary) { writeFile(temporary, frame); }, std::move(s));
}

void FieldFrameWriter::writeFile(const std::filesystem::path& path, const data::FieldFrame& frame) const {
  const data::GridGeometry& g = frame.grid;
  const std::vector<hsize_t> scalar{static_cast<hsize_t>(g.cells[2]), static_cast<hsize_t>(g.cells[1]),
                                    static_cast<hsize_t>(g.cells[0])};
  const std::vector<hsize_t> vector{scalar[0], scalar[1], scalar[2], 3};

  H5OutputFile f(path, deflateLevel_);
  writeFrameAttributes(f, stamp_, kFieldFormatVersion, frame.time, frame.step, frame.units);
  f.createGroup("/grid");
  f.writeAttribute("/grid", "origin", std::array<double, 3>{g.origin.x(), g.origin.y(), g.origin.z()});
  f.writeAttribute("/grid", "spacing", std::array<double, 3>{g.spacing.x(), g.spacing.y(), g.spacing.z()});
  f.writeAttribute("/grid", "cells", std::array<std::int32_t, 3>{g.cells[0], g.cells[1], g.cells[2]});
  f.writeDataset("/ep_g", std::span<const double>(frame.ep_g), scalar);
  f.writeDataset("/p_g", std::span<const double>(frame.p_g), scalar);
  f.writeDataset("/u_g", flatView(frame.u_g), vector);
  f.createGroup("/solids");
  for (std::size_t k = 0; k < frame.solids.size(); ++k) {
    const data::SolidsPhaseFields& phase = frame.solids[k];
    const std::string group = "/solids/" + phase.name;
    f.createGroup(group);
    // HDF5 lists members by name; the index keeps the engine's phase order.
    f.writeAttribute(group, "index", static_cast<std::int32_t>(k));
    f.writeDataset(group + "/ep_s", std::span<const double>(phase.ep_s), scalar);
    f.writeDataset(group + "/u_s", flatView(phase.u_s), vector);
    f.writeDataset(group + "/theta", std::span<const double>(phase.theta), scalar);
  }
  if (!frame.extras.empty()) {
    f.createGroup("/extra");
    for (std::size_t k = 0; k < frame.extras.size(); ++k) {
      const data::NamedCellField& extra = frame.extras[k];
      std::vector<hsize_t> shape = scalar;
      if (extra.components > 1) shape.push_back(static_cast<hsize_t>(extra.components));
      f.writeDataset("/extra/" + extra.name, std::span<const double>(extra.values), shape);
      f.writeAttribute("/extra/" + extra.name, "index", static_cast<std::int32_t>(k));
    }
  }
  writeMaterials(f, frame.materials);
  f.close();
}

}  // namespace grainbridge::core::io
