#include "core/io/ParticleFrameWriter.hpp"

#include <sstream>
#include <string>
#include <unordered_map>

#include "core/Error.hpp"
#include "core/Files.hpp"
#include "core/io/FrameFiles.hpp"
#include "core/io/H5OutputFile.hpp"
#include "core/io/MaterialsIo.hpp"
#include "core/io/XdmfText.hpp"

namespace grainbridge::core::io {

namespace {

std::string particleStepGrid(std::int64_t step, const ParticleFrameSummary& s) {
  // One spatial collection per step inside the temporal collection: the particles as a
  // Polyvertex grid (one vertex cell each) and, when there are contacts, the contacts as a Polyline grid of segments
  // (r_i, r_i - branch), so a contact across a periodic boundary is drawn short instead of across the box. ParaView
  // shows this as a multiblock per time step.
  std::ostringstream x;
  // Relative to the .xmf, so a moved results folder still opens.
  const std::string file = "frames/" + s.file.filename().string() + ":";
  const std::string n = std::to_string(s.particles);
  const std::string m = std::to_string(s.contacts);
  x << "   <Grid Name=\"step_" << step << "\" GridType=\"Collection\" CollectionType=\"Spatial\">\n"
    << "    <Time Value=\"" << formatReal(s.time) << "\"/>\n";
  // An empty frame keeps its time step but has no grids: ParaView's XDMF reader reports
  // an error on a zero-length geometry.
  if (s.particles > 0) {
    x << "    <Grid Name=\"particles\" GridType=\"Uniform\">\n"
      << "     <Topology TopologyType=\"Polyvertex\" NumberOfElements=\"" << n << "\" NodesPerElement=\"1\"/>\n"
      << "     <Geometry GeometryType=\"XYZ\">" << xdmfHdfItem(n + " 3", "Float", 8, file + "/position")
      << "</Geometry>\n"
      << "     " << xdmfAttribute("id", "Scalar", "Node", xdmfHdfItem(n, "Int", 8, file + "/id")) << "\n"
      << "     " << xdmfAttribute("species", "Scalar", "Node", xdmfHdfItem(n, "Int", 4, file + "/species")) << "\n"
      << "     " << xdmfAttribute("radius", "Scalar", "Node", xdmfHdfItem(n, "Float", 8, file + "/radius")) << "\n"
      << "     " << xdmfAttribute("mass", "Scalar", "Node", xdmfHdfItem(n, "Float", 8, file + "/mass")) << "\n"
      << "     " << xdmfAttribute("velocity", "Vector", "Node", xdmfHdfItem(n + " 3", "Float", 8, file + "/velocity"))
      << "\n"
      << "     "
      << xdmfAttribute("angular_velocity", "Vector", "Node",
                       xdmfHdfItem(n + " 3", "Float", 8, file + "/angular_velocity"))
      << "\n";
    if (s.hasExternalForce) {
      x << "     "
        << xdmfAttribute("external_force", "Vector", "Node",
                         xdmfHdfItem(n + " 3", "Float", 8, file + "/external_force"))
        << "\n";
    }
    x << "    </Grid>\n";
  }
  if (s.contacts > 0) {
    const std::string twoM = std::to_string(2 * s.contacts);
    x << "    <Grid Name=\"contacts\" GridType=\"Uniform\">\n"
      << "     <Topology TopologyType=\"Polyline\" NumberOfElements=\"" << m << "\" NodesPerElement=\"2\">"
      << xdmfHdfItem(m + " 2", "Int", 8, file + "/contacts/segment_connectivity") << "</Topology>\n"
      << "     <Geometry GeometryType=\"XYZ\">" << xdmfHdfItem(twoM + " 3", "Float", 8, file + "/contacts/segments")
      << "</Geometry>\n"
      << "     "
      << xdmfAttribute("force_normal", "Vector", "Cell",
                       xdmfHdfItem(m + " 3", "Float", 8, file + "/contacts/force_normal"))
      << "\n"
      << "     "
      << xdmfAttribute("force_tangential", "Vector", "Cell",
                       xdmfHdfItem(m + " 3", "Float", 8, file + "/contacts/force_tangential"))
      << "\n"
      << "     " << xdmfAttribute("i", "Scalar", "Cell", xdmfHdfItem(m, "Int", 8, file + "/contacts/i")) << "\n"
      << "     " << xdmfAttribute("j", "Scalar", "Cell", xdmfHdfItem(m, "Int", 8, file + "/contacts/j")) << "\n"
      << "    </Grid>\n";
  }
  x << "   </Grid>\n";
  return x.str();
}

}  // namespace

ParticleFrameWriter::ParticleFrameWriter(std::filesystem::path directory, ArtifactStamp stamp, int deflateLevel)
    : stamp_(std::move(stamp)),
      deflateLevel_(deflateLevel),
      series_(std::move(directory), "particles", readParticleFrameSummary, particleStepGrid) {}

std::filesystem::path ParticleFrameWriter::write(const data::ParticleFrame& frame) {
  frame.validate();
  return series_.write(
      frame.step, [&](const std::filesystem::path& temporary) { writeFile(temporary, frame); },
      ParticleFrameSummary{
          {}, frame.step, frame.time, frame.size(), frame.contacts.size(), !frame.externalForce.empty()});
}

void ParticleFrameWriter::writeFile(const std::filesystem::path& path, const data::ParticleFrame& frame) const {
  // Segments (r_i, r_i - branch) need r_i by global id; a contact whose i is not in the
  // frame is an engine bug that would otherwise produce a silently wrong picture.
  const data::ContactList& c = frame.contacts;
  std::vector<Vec3> segments(2 * c.size());
  std::vector<std::int64_t> connectivity(2 * c.size());
  if (c.size() > 0) {
    std::unordered_map<std::int64_t, std::size_t> indexOf;
    indexOf.reserve(frame.size());
    for (std::size_t p = 0; p < frame.size(); ++p) indexOf.emplace(frame.id[p], p);
    for (std::size_t k = 0; k < c.size(); ++k) {
      const auto it = indexOf.find(c.i[k]);
      if (it == indexOf.end()) {
        throw Error("particle frame at step " + std::to_string(frame.step) + ": contact " + std::to_string(k) +
                    " has i = " + std::to_string(c.i[k]) + ", which is not a particle id of the frame");
      }
      const Vec3& ri = frame.position[it->second];
      segments[2 * k] = ri;
      segments[2 * k + 1] = ri - c.branch[k];
      connectivity[2 * k] = static_cast<std::int64_t>(2 * k);
      connectivity[2 * k + 1] = static_cast<std::int64_t>(2 * k + 1);
    }
  }

  H5OutputFile f(path, deflateLevel_);
  writeFrameAttributes(f, stamp_, kParticleFormatVersion, frame.time, frame.step, frame.units);

  const data::Domain& d = frame.domain;
  f.createGroup("/domain");
  f.writeAttribute("/domain", "lo", std::array<double, 3>{d.lo.x(), d.lo.y(), d.lo.z()});
  f.writeAttribute("/domain", "hi", std::array<double, 3>{d.hi.x(), d.hi.y(), d.hi.z()});
  f.writeAttribute("/domain", "periodic",
                   std::array<std::int32_t, 3>{d.periodic[0] ? 1 : 0, d.periodic[1] ? 1 : 0, d.periodic[2] ? 1 : 0});
  f.writeAttribute("/domain", "lees_edwards_offset", d.leesEdwardsOffset);
  f.writeAttribute("/domain", "lees_edwards_shear_rate", d.leesEdwardsShearRate);
  std::vector<std::int32_t> wallKind;
  std::vector<Vec3> wallOrigin, wallDirection, wallVelocity;
  std::vector<double> wallRadius;
  for (const data::Wall& w : d.walls) {
    wallKind.push_back(w.kind == "plane" ? 0 : 1);
    wallOrigin.push_back(w.origin);
    wallDirection.push_back(w.direction);
    wallRadius.push_back(w.radius);
    wallVelocity.push_back(w.velocity);
  }
  f.writeDataset("/domain/wall_kind", wallKind);
  f.writeAttribute("/domain/wall_kind", "codes", std::string("0 = plane, 1 = cylinder"));
  f.writeDataset("/domain/wall_origin", wallOrigin);
  f.writeDataset("/domain/wall_direction", wallDirection);
  f.writeDataset("/domain/wall_radius", wallRadius);
  f.writeDataset("/domain/wall_velocity", wallVelocity);

  f.writeDataset("/id", frame.id);
  f.writeDataset("/species", frame.species);
  f.writeDataset("/radius", frame.radius);
  f.writeDataset("/mass", frame.mass);
  f.writeDataset("/position", frame.position);
  f.writeDataset("/velocity", frame.velocity);
  f.writeDataset("/angular_velocity", frame.angularVelocity);
  if (!frame.externalForce.empty()) f.writeDataset("/external_force", frame.externalForce);

  f.createGroup("/contacts");
  f.writeDataset("/contacts/i", c.i);
  f.writeDataset("/contacts/j", c.j);
  f.writeDataset("/contacts/branch", c.branch);
  f.writeDataset("/contacts/contact_point", c.contactPoint);
  f.writeDataset("/contacts/force_normal", c.forceNormal);
  f.writeDataset("/contacts/force_tangential", c.forceTangential);
  f.writeDataset("/contacts/force_normal_elastic", c.forceNormalElastic);
  f.writeDataset("/contacts/force_normal_dissipative", c.forceNormalDissipative);
  f.writeDataset("/contacts/force_tangential_elastic", c.forceTangentialElastic);
  f.writeDataset("/contacts/force_tangential_dissipative", c.forceTangentialDissipative);
  f.writeDataset("/contacts/segments", segments);
  f.writeDataset("/contacts/segment_connectivity", std::span<const std::int64_t>(connectivity), {c.size(), 2});

  const data::WallContactList& wc = frame.wallContacts;
  f.createGroup("/wall_contacts");
  f.writeDataset("/wall_contacts/particle", wc.particle);
  f.writeDataset("/wall_contacts/wall", wc.wall);
  f.writeDataset("/wall_contacts/point", wc.point);
  f.writeDataset("/wall_contacts/force_normal", wc.forceNormal);
  f.writeDataset("/wall_contacts/force_tangential", wc.forceTangential);
  writeMaterials(f, frame.materials);
  f.close();
}

}  // namespace grainbridge::core::io
