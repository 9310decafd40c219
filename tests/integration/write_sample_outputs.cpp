// Writes a small, fully known particle output and field output for
// paraview_check.py, plus expected.json describing what ParaView must see. Usage:
//   write_sample_outputs <output folder>
// Particles: 3 frames of N = 5 particles with 3, 0 and 2 contacts (the middle frame checks
// that a frame without contacts omits the contact grid). One contact crosses the periodic
// x boundary. Fields: 2 frames on a 4 x 3 x 2 grid with two solids phases.
#include <cstdio>
#include <exception>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <vector>

#include "core/Files.hpp"
#include "core/io/FieldFrameWriter.hpp"
#include "core/io/ParticleFrameWriter.hpp"

namespace {
using grainbridge::Vec3;
namespace data = grainbridge::core::data;
namespace io = grainbridge::core::io;

data::ParticleFrame particleFrame(std::int64_t step, double time, int contacts) {
  constexpr int n = 5;
  data::ParticleFrame f;
  f.step = step;
  f.time = time;
  f.domain.lo = Vec3(0.0, 0.0, 0.0);
  f.domain.hi = Vec3(1.0, 1.0, 1.0);
  f.domain.periodic = {true, true, true};
  for (int p = 0; p < n; ++p) {
    f.id.push_back(10 + p);
    f.species.push_back(p % 2);
    f.radius.push_back(0.05 + 0.01 * p);
    f.mass.push_back(1e-3 * (p + 1));
    // Particles drift in y between frames so each frame's positions differ.
    f.position.push_back(Vec3(0.1 + 0.2 * p, 0.5 + 0.01 * static_cast<double>(step), 0.5));
    f.velocity.push_back(Vec3(0.0, 0.01, 0.0));
    f.angularVelocity.push_back(Vec3(0.0, 0.0, 0.1 * p));
  }
  for (int c = 0; c < contacts; ++c) {
    // Contact c joins particle c and c+1; the last one of a 3-contact frame joins 4 and 0
    // across x, with a short minimum-image branch.
    const int a = c == 2 ? 4 : c;
    const int b = c == 2 ? 0 : c + 1;
    f.contacts.i.push_back(f.id[static_cast<std::size_t>(a)]);
    f.contacts.j.push_back(f.id[static_cast<std::size_t>(b)]);
    // r_i - r_j under the minimum image: -0.2 in x for every pair, including 4-0 whose
    // positions are 0.8 apart inside the box.
    const Vec3 branch(-0.2, 0.0, 0.0);
    f.contacts.branch.push_back(branch);
    f.contacts.contactPoint.push_back(f.position[static_cast<std::size_t>(a)] - 0.5 * branch);
    f.contacts.forceNormal.push_back(Vec3(-1.0 - c, 0.0, 0.0));
    f.contacts.forceTangential.push_back(Vec3(0.0, 0.1 * c, 0.0));
    f.contacts.forceNormalElastic.push_back(Vec3(-1.0 - c, 0.0, 0.0));
    f.contacts.forceNormalDissipative.push_back(Vec3::Zero());
    f.contacts.forceTangentialElastic.push_back(Vec3(0.0, 0.1 * c, 0.0));
    f.contacts.forceTangentialDissipative.push_back(Vec3::Zero());
  }
  return f;
}

data::FieldFrame fieldFrame(std::int64_t step, double time) {
  data::FieldFrame f;
  f.step = step;
  f.time = time;
  f.grid.origin = Vec3(0.0, 0.0, 0.0);
  f.grid.spacing = Vec3(0.25, 0.5, 1.0);
  f.grid.cells = {4, 3, 2};
  const std::size_t cells = f.grid.cellCount();
  f.solids = {{"fine", {}, {}, {}}, {"coarse", {}, {}, {}}};
  for (std::size_t c = 0; c < cells; ++c) {
    // ep_g encodes the flat [k][j][i] index so an axis mix-up in the viewer shows.
    f.ep_g.push_back(0.4 + 0.01 * static_cast<double>(c) + 0.001 * static_cast<double>(step));
    f.p_g.push_back(1e5 + static_cast<double>(c));
    f.u_g.push_back(Vec3(1.0, 0.0, 0.0));
    for (auto& s : f.solids) {
      s.ep_s.push_back(0.3);
      s.u_s.push_back(Vec3(0.0, 0.0, -1.0));
      s.theta.push_back(1e-3);
    }
  }
  return f;
}
}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: %s <output folder>\n", argv[0]);
    return 2;
  }
  try {
    const std::filesystem::path out = argv[1];
    std::filesystem::remove_all(out);
    nlohmann::json expected;

    io::ParticleFrameWriter particles(out / "particles", {"paraview-check"});
    const std::vector<std::pair<double, int>> particleFrames{{0.0, 3}, {0.5, 0}, {1.25, 2}};
    for (std::size_t k = 0; k < particleFrames.size(); ++k) {
      const data::ParticleFrame f =
          particleFrame(static_cast<std::int64_t>(100 * k), particleFrames[k].first, particleFrames[k].second);
      particles.write(f);
      expected["particles"]["frames"].push_back(
          {{"time", f.time}, {"points", f.size()}, {"contacts", f.contacts.size()}, {"radius", f.radius}});
    }
    expected["particles"]["xmf"] = particles.xdmfPath().string();

    io::FieldFrameWriter fields(out / "fields", {"paraview-check"});
    for (const auto& [step, time] : std::vector<std::pair<std::int64_t, double>>{{0, 0.0}, {40, 2.0}}) {
      const data::FieldFrame f = fieldFrame(step, time);
      fields.write(f);
      expected["fields"]["frames"].push_back(
          {{"time", f.time},
           {"cells", f.grid.cellCount()},
           {"points", (f.grid.cells[0] + 1) * (f.grid.cells[1] + 1) * (f.grid.cells[2] + 1)},
           {"ep_g", f.ep_g}});
    }
    expected["fields"]["xmf"] = fields.xdmfPath().string();
    expected["fields"]["bounds"] = {0.0, 1.0, 0.0, 1.5, 0.0, 2.0};  // origin + cells * spacing
    expected["fields"]["arrays"] = {"ep_g",       "p_g",         "u_g",        "ep_s_fine",   "u_s_fine",
                                    "theta_fine", "ep_s_coarse", "u_s_coarse", "theta_coarse"};
    grainbridge::core::writeFileAtomically(out / "expected.json", expected.dump(2) + "\n");
  } catch (const std::exception& e) {
    std::fprintf(stderr, "write_sample_outputs: %s\n", e.what());
    return 1;
  }
  return 0;
}
