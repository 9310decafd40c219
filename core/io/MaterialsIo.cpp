#include "core/io/MaterialsIo.hpp"

#include <array>

#include "core/io/H5InputFile.hpp"
#include "core/io/H5OutputFile.hpp"

namespace grainbridge::core::io {

namespace {

// One contact list (pairs or wall entries) as columns.
struct ContactColumns {
  std::vector<std::int32_t> speciesPair, wall;
  std::vector<double> restitution, friction, stiffness, tangentialStiffness;
};

ContactColumns columnsOf(const std::vector<data::ContactMaterial>& list) {
  ContactColumns c;
  for (const auto& m : list) {
    c.speciesPair.push_back(m.speciesA);
    c.speciesPair.push_back(m.speciesB);
    c.wall.push_back(m.wall);
    c.restitution.push_back(m.restitution);
    c.friction.push_back(m.friction);
    c.stiffness.push_back(m.stiffness);
    c.tangentialStiffness.push_back(m.tangentialStiffness);
  }
  return c;
}

void writeContacts(H5OutputFile& f, const std::string& prefix, const std::vector<data::ContactMaterial>& list) {
  const ContactColumns c = columnsOf(list);
  f.writeDataset("/materials/" + prefix + "_species", std::span<const std::int32_t>(c.speciesPair), {list.size(), 2});
  if (prefix == "wall") f.writeDataset("/materials/wall_index", c.wall);
  f.writeDataset("/materials/" + prefix + "_restitution", c.restitution);
  f.writeDataset("/materials/" + prefix + "_friction", c.friction);
  f.writeDataset("/materials/" + prefix + "_stiffness", c.stiffness);
  f.writeDataset("/materials/" + prefix + "_tangential_stiffness", c.tangentialStiffness);
}

std::vector<data::ContactMaterial> readContacts(const H5InputFile& f, const std::string& prefix) {
  const auto species = f.readInt32s("/materials/" + prefix + "_species", {std::nullopt, 2});
  const hsize_t n = species.size() / 2;
  const auto wall = prefix == "wall" ? f.readInt32s("/materials/wall_index", {n}) : std::vector<std::int32_t>(n, -1);
  const auto restitution = f.readDoubles("/materials/" + prefix + "_restitution", {n});
  const auto friction = f.readDoubles("/materials/" + prefix + "_friction", {n});
  const auto stiffness = f.readDoubles("/materials/" + prefix + "_stiffness", {n});
  const auto tangential = f.readDoubles("/materials/" + prefix + "_tangential_stiffness", {n});
  std::vector<data::ContactMaterial> out(n);
  for (hsize_t k = 0; k < n; ++k) {
    out[k] = {species[2 * k], species[2 * k + 1], wall[k], restitution[k], friction[k], stiffness[k], tangential[k]};
  }
  return out;
}

}  // namespace

void writeMaterials(H5OutputFile& f, const data::Materials& m) {
  if (m.empty()) return;
  f.createGroup("/materials");
  std::vector<double> diameter, density;
  for (std::size_t s = 0; s < m.species.size(); ++s) {
    diameter.push_back(m.species[s].diameter);
    density.push_back(m.species[s].density);
    f.writeAttribute("/materials", "species_name_" + std::to_string(s), m.species[s].name);
  }
  f.writeDataset("/materials/species_diameter", diameter);
  f.writeDataset("/materials/species_density", density);
  writeContacts(f, "pair", m.pairs);
  writeContacts(f, "wall", m.walls);
  f.writeAttribute("/materials", "gravity", std::array<double, 3>{m.gravity.x(), m.gravity.y(), m.gravity.z()});
}

data::Materials readMaterials(const H5InputFile& f) {
  data::Materials m;
  if (!f.exists("/materials")) return m;
  const auto diameter = f.readDoubles("/materials/species_diameter", {std::nullopt});
  const auto density = f.readDoubles("/materials/species_density", {diameter.size()});
  for (std::size_t s = 0; s < diameter.size(); ++s) {
    m.species.push_back(
        {f.readStringAttribute("/materials", "species_name_" + std::to_string(s)), diameter[s], density[s]});
  }
  m.pairs = readContacts(f, "pair");
  m.walls = readContacts(f, "wall");
  const auto g = f.readDouble3Attribute("/materials", "gravity");
  m.gravity = Vec3(g[0], g[1], g[2]);
  return m;
}

}  // namespace grainbridge::core::io
