#include "core/data/FieldFrame.hpp"

#include <set>
#include <string>

#include "core/Error.hpp"

namespace grainbridge::core::data {

std::size_t GridGeometry::cellCount() const {
  return static_cast<std::size_t>(cells[0]) * static_cast<std::size_t>(cells[1]) * static_cast<std::size_t>(cells[2]);
}

namespace {
template <class T>
void checkLength(const std::vector<T>& v, const std::string& name, std::size_t expected) {
  if (v.size() != expected) {
    throw Error("field array '" + name + "' has " + std::to_string(v.size()) + " entries, expected " +
                std::to_string(expected) + " (nx*ny*nz)");
  }
}

bool isPlainName(const std::string& s) {
  if (s.empty()) return false;
  for (const char c : s) {
    const bool ok = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' || c == '-';
    if (!ok) return false;
  }
  return true;
}
}  // namespace

void FieldFrame::validate() const {
  try {
    for (int d = 0; d < 3; ++d) {
      if (grid.cells[static_cast<std::size_t>(d)] < 1) {
        throw Error("grid has " + std::to_string(grid.cells[static_cast<std::size_t>(d)]) + " cells along axis " +
                    std::to_string(d) + ", expected at least 1");
      }
      if (!(grid.spacing[d] > 0.0)) {
        throw Error("grid spacing along axis " + std::to_string(d) + " is " + std::to_string(grid.spacing[d]) +
                    ", expected > 0");
      }
    }
    const std::size_t n = grid.cellCount();
    checkLength(ep_g, "ep_g", n);
    checkLength(p_g, "p_g", n);
    checkLength(u_g, "u_g", n);
    std::set<std::string> names;
    for (const SolidsPhaseFields& phase : solids) {
      // The name becomes an HDF5 path component and an XDMF attribute name.
      if (!isPlainName(phase.name)) {
        throw Error("solids phase name '" + phase.name +
                    "' must be non-empty and use only letters, digits, '_' or '-'");
      }
      if (!names.insert(phase.name).second) throw Error("solids phase name '" + phase.name + "' is repeated");
      checkLength(phase.ep_s, "solids/" + phase.name + "/ep_s", n);
      checkLength(phase.u_s, "solids/" + phase.name + "/u_s", n);
      checkLength(phase.theta, "solids/" + phase.name + "/theta", n);
    }
    std::set<std::string> extraNames;
    for (const NamedCellField& extra : extras) {
      if (!isPlainName(extra.name)) {
        throw Error("field name '" + extra.name + "' must be non-empty and use only letters, digits, '_' or '-'");
      }
      if (!extraNames.insert(extra.name).second) throw Error("field name '" + extra.name + "' is repeated");
      if (extra.components != 1 && extra.components != 3 && extra.components != 9) {
        throw Error("field '" + extra.name + "' has " + std::to_string(extra.components) +
                    " components per cell; expected 1, 3 or 9");
      }
      checkLength(extra.values, "extra/" + extra.name, n * static_cast<std::size_t>(extra.components));
    }
    if (!materials.empty()) {
      materials.validate();
      if (materials.species.size() != solids.size()) {
        throw Error("materials name " + std::to_string(materials.species.size()) + " species for " +
                    std::to_string(solids.size()) + " solids phases");
      }
      for (std::size_t m = 0; m < solids.size(); ++m) {
        if (materials.species[m].name != solids[m].name) {
          throw Error("materials species " + std::to_string(m) + " is '" + materials.species[m].name +
                      "', the solids phase '" + solids[m].name + "'");
        }
      }
    }
  } catch (const Error& e) {
    throw e.withContext("field frame at step " + std::to_string(step));
  }
}

}  // namespace grainbridge::core::data
