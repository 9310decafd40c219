#include "engines/lammps/LammpsInput.hpp"

#include <array>
#include <charconv>
#include <cmath>
#include <cstdio>

#include "core/Error.hpp"
#include "engines/dem/contact/DampingModels.hpp"
#include "engines/dem/contact/NormalModels.hpp"
#include "engines/dem/contact/TangentialModels.hpp"

namespace grainbridge::lammps {

namespace {

constexpr std::array<const char*, 3> kAxis{"x", "y", "z"};

// The shortest text that reads back as the same double, so LAMMPS gets our coefficients to the
// bit.
std::string exact(double v) {
  std::array<char, 32> buf{};
  const auto [end, ec] = std::to_chars(buf.data(), buf.data() + buf.size(), v);
  GB_ASSERT(ec == std::errc(), "to_chars of a double fits 32 characters");
  return {buf.data(), end};
}

template <class... T>
std::string text(const T&... parts) {
  std::string out;
  auto append = [&out](const auto& p) {
    if constexpr (std::is_arithmetic_v<std::decay_t<decltype(p)>>) {
      out += exact(static_cast<double>(p));
    } else {
      out += p;
    }
  };
  (append(parts), ...);
  return out;
}

// The axis a unit direction lies along (+1 or -1 in `sign`), or -1 when it is oblique.
int axisOf(const Vec3& direction, int& sign) {
  const Vec3 n = direction.normalized();
  for (int a = 0; a < 3; ++a) {
    if (std::abs(n[a]) == 1.0) {
      sign = n[a] > 0.0 ? 1 : -1;
      return a;
    }
  }
  return -1;
}

bool sameMaterial(const dem::PairMaterial& a, const dem::PairMaterial& b) {
  return a.kn == b.kn && a.kt == b.kt && a.gammaN == b.gammaN && a.gammaT == b.gammaT && a.mu == b.mu &&
         a.etaN == b.etaN && a.etaT == b.etaT;
}

std::string describe(const dem::PairMaterial& m) {
  std::array<char, 160> buf{};
  std::snprintf(buf.data(), buf.size(), "k_n %.6g, k_t %.6g, gamma_n %.6g, gamma_t %.6g, mu %.6g", m.kn, m.kt, m.gammaN,
                m.gammaT, m.mu);
  return buf.data();
}

bool hertz(const dem::SimulationSetup& s) { return s.contact.normal == dem::contact::HertzSpring::name; }

// gran/hooke/history and gran/hertz/history: k_n k_t gamma_n gamma_t mu dampflag. LAMMPS's
// Hertzian factor is sqrt(delta R_eff), grainbridge's sqrt(delta / d) (Eq. 6.5, d = a_i + a_j,
// or 2 a_i against a wall): for one radius a both are one factor apart, a between grains and
// a sqrt(2) against a wall, which the coefficients absorb.
std::string granularArgs(const dem::SimulationSetup& s, const dem::PairMaterial& m, double hertzFactor) {
  const double scale = hertz(s) ? hertzFactor : 1.0;
  return text(hertz(s) ? "hertz/history " : "hooke/history ", m.kn / scale, " ", m.kt / scale, " ", m.gammaN / scale,
              " ", m.gammaT / scale, " ", m.mu, " ", m.gammaT > 0.0 ? "1" : "0");
}

}  // namespace

bool wiggleOrigin(const dem::Vibration& v, double dt, std::int64_t& timeOrigin) {
  if (v.start == dem::Vibration::Start::AtRest) {
    timeOrigin = 0;
    return true;
  }
  const double steps = 0.75 / (v.frequency * dt);
  const double whole = std::round(steps);
  if (whole < 1.0 || std::abs(steps - whole) > 1e-12 * steps) return false;
  timeOrigin = static_cast<std::int64_t>(whole);
  return true;
}

double leesEdwardsInitialTilt(const dem::SimulationSetup& s) { return s.shearRate * (s.hi[1] - s.lo[1]) * s.dt; }

bool lammpsAvailable() {
#ifdef GRAINBRIDGE_HAVE_LAMMPS
  return true;
#else
  return false;
#endif
}

std::string lammpsBuildNote() {
#if defined(GRAINBRIDGE_HAVE_LAMMPS) && defined(GRAINBRIDGE_LAMMPS_VERSION)
  return std::string("LAMMPS ") + GRAINBRIDGE_LAMMPS_VERSION;
#elif defined(GRAINBRIDGE_HAVE_LAMMPS)
  return "LAMMPS";
#elif defined(GRAINBRIDGE_LAMMPS_OFF_REASON)
  return std::string("off: ") + GRAINBRIDGE_LAMMPS_OFF_REASON;
#else
  return "off";
#endif
}

std::vector<core::engine::SetupProblem> lammpsProblems(const dem::SimulationSetup& s, const LammpsSpeciesRadii& radii) {
  std::vector<core::engine::SetupProblem> out;
  auto add = [&out](std::string pointer, std::string message) {
    out.push_back({std::move(pointer), std::move(message)});
  };
  if (s.contact.damping != dem::contact::MassScaledDamping::name) {
    add("/damping_model",
        "engine lammps: LAMMPS's gran pair styles damp as -m_eff gamma v only (damping_model "
        "\"mass_scaled\"); \"" +
            s.contact.damping + "\" has no counterpart there");
  }
  // Without friction anywhere there is no tangential force, whichever law keeps the history.
  bool friction = false;
  for (const auto& m : s.pairMaterial) friction = friction || m.mu > 0.0;
  for (const auto& w : s.walls) {
    for (const auto& m : w.material) friction = friction || m.mu > 0.0;
  }
  if (friction && s.contact.tangential != dem::contact::LammpsHistory::name) {
    add("/tangential_model",
        "engine lammps: LAMMPS keeps its own tangential history; set tangential_model "
        "\"lammps_history\", the grainbridge law that equals it (found \"" +
            s.contact.tangential + "\")");
  }
  if (hertz(s)) {
    for (double r : radii.radius) {
      if (r != radii.radius.front()) {
        add("/normal_model",
            "engine lammps: LAMMPS's Hertzian factor sqrt(delta R_eff) equals grainbridge's "
            "sqrt(delta / d) up to one constant only when every species has one diameter");
        break;
      }
    }
  }
  for (int a = 0; a < s.species; ++a) {
    for (int b = 0; b < s.species; ++b) {
      if (!sameMaterial(s.material(a, b), s.material(0, 0))) {
        add("/pair_contacts",
            text("engine lammps: LAMMPS's gran pair styles take one set of coefficients for every "
                 "pair, but species ",
                 a, " with species ", b, " has ", describe(s.material(a, b)), " against ", describe(s.material(0, 0)),
                 " (a restitution gives each pair of masses its own gamma_n: give gamma_n instead)"));
        a = s.species;
        break;
      }
    }
  }
  if (s.planarAxis >= 0) add("/planar", "engine lammps: planar beds have no counterpart in LAMMPS's fix nve/sphere");
  if (s.pressureControl.active())
    add("/pressure_control",
        "engine lammps: the pressure-controlled box is grainbridge's own (issue 30); not offered "
        "on LAMMPS");
  if (s.compression.active())
    add("/compression", "engine lammps: the compressed box is grainbridge's own (issue 60); not offered on LAMMPS");
  if (s.fluidCoupled) add("", "engine lammps: a fluid-coupled (TF-DEM) run needs grainbridge's engine");
  for (std::size_t w = 0; w < s.walls.size(); ++w) {
    const auto& wall = s.walls[w];
    const std::string where = "/walls/" + std::to_string(w);
    int sign = 0;
    const int axis = axisOf(wall.direction, sign);
    if (wall.kind == dem::Wall::Kind::Plane && axis < 0) {
      add(where + "/direction", "engine lammps: fix wall/gran takes planes normal to x, y or z only");
    }
    if (wall.kind == dem::Wall::Kind::Cylinder && (axis != 2 || wall.origin[0] != 0.0 || wall.origin[1] != 0.0)) {
      add(where,
          "engine lammps: fix wall/gran's zcylinder has its axis along z through x = y = 0; give the "
          "cylinder that axis (shift the box)");
    }
    if (wall.vibration.active()) {
      int vibrationSign = 0;
      const int vibrationAxis = axisOf(wall.vibration.direction, vibrationSign);
      std::int64_t origin = 0;
      if (vibrationAxis < 0) {
        add(where + "/vibration_direction", "engine lammps: fix wall/gran wiggles along x, y or z only");
      } else if (wall.kind == dem::Wall::Kind::Cylinder && vibrationAxis != 2) {
        add(where + "/vibration_direction", "engine lammps: fix wall/gran's zcylinder wiggles along its axis z only");
      } else if (!wiggleOrigin(wall.vibration, s.dt, origin)) {
        add(where + "/vibration_start",
            text("engine lammps: fix wall/gran's wiggle moves as A (1 - cos 2 pi f t) from the step its fix is "
                 "made; mid_stroke's A sin(2 pi f t) is that three quarters of a period on, which must be a "
                 "whole number of steps and is ",
                 0.75 / (wall.vibration.frequency * s.dt),
                 " here: set vibration_start \"at_rest\", or a frequency and dt with 3 / (4 f dt) whole"));
      }
    }
    for (std::size_t k = 1; k < wall.material.size(); ++k) {
      if (!sameMaterial(wall.material[k], wall.material[0])) {
        add(where, text("engine lammps: fix wall/gran takes one set of coefficients per wall, but species ", k, " has ",
                        describe(wall.material[k]), " against ", describe(wall.material[0]),
                        " (give gamma_n instead of restitution)"));
        break;
      }
    }
  }
  return out;
}

LammpsInput lammpsInput(const dem::SimulationSetup& s, const LammpsSpeciesRadii& radii, bool frozenAtoms) {
  GB_ASSERT(lammpsProblems(s, radii).empty(), "lammpsInput() of a setup LAMMPS cannot run as grainbridge does");
  LammpsInput in;
  in.atomTypes = 2 * s.species;
  std::string boundary = "boundary";
  for (int a = 0; a < 3; ++a) boundary += s.periodic[static_cast<std::size_t>(a)] ? " p" : " f";
  in.system = {
      "units si",
      "atom_style sphere",
      "atom_modify map array",
      boundary,
      "newton off",
      "comm_modify vel yes",
      s.shearRate != 0.0 ? text("region gb_box prism ", s.lo[0], " ", s.hi[0], " ", s.lo[1], " ", s.hi[1], " ", s.lo[2],
                                " ", s.hi[2], " ", leesEdwardsInitialTilt(s), " 0 0 units box")
                         : text("region gb_box block ", s.lo[0], " ", s.hi[0], " ", s.lo[1], " ", s.hi[1], " ", s.lo[2],
                                " ", s.hi[2], " units box"),
      text("create_box ", in.atomTypes, " gb_box"),
  };

  const double a = radii.radius.empty() ? 1.0 : radii.radius.front();
  auto& cmd = in.interactions;
  cmd.push_back("pair_style gran/" + granularArgs(s, s.material(0, 0), a));
  cmd.push_back("pair_coeff * *");
  cmd.push_back(text("neighbor ", s.skin, " bin"));
  cmd.push_back("neigh_modify delay 0 every 1 check yes");
  cmd.push_back(text("timestep ", s.dt));
  // Frozen types only where there are frozen atoms: an exclusion in the neighbour build costs
  // every pair a test (9 % of the 80k dense bed's rate here, bench/dem-lammps-scaling.sh).
  const std::string mobile = frozenAtoms ? "gb_mobile" : "all";
  if (frozenAtoms) {
    cmd.push_back(text("group gb_frozen type ", s.species + 1, ":", 2 * s.species));
    cmd.push_back("group gb_mobile subtract all gb_frozen");
    cmd.push_back("neigh_modify exclude group gb_frozen gb_frozen");
  }
  // A particle that leaves a fixed boundary is dropped, and LammpsEngine stops the run naming the
  // step; without it LAMMPS would end the whole process (this build has no C++ exceptions).
  cmd.push_back("thermo_modify lost ignore");
  const double g = s.gravity.norm();
  if (g > 0.0) {
    cmd.push_back(
        text("fix gb_gravity all gravity ", g, " vector ", s.gravity[0], " ", s.gravity[1], " ", s.gravity[2]));
  }
  if (frozenAtoms) cmd.push_back("fix gb_freeze gb_frozen freeze");
  cmd.push_back("fix gb_integrate " + mobile + " nve/sphere");
  // Lees-Edwards shear: the image above (y + L_y) moves with +shear_rate L_y, and a particle that
  // crosses the y boundary takes that velocity jump (remap v). fix deform sets the tilt at the
  // end of a step, so the forces of step n + 1 see the tilt of step n: the box starts one step
  // ahead (leesEdwardsInitialTilt) to give them grainbridge's offset at t_(n+1).
  if (s.shearRate != 0.0) cmd.push_back(text("fix gb_shear all deform 1 xy erate ", s.shearRate, " remap v"));
  // Eq. 6.7's -b v.
  if (s.backgroundDamping > 0.0) cmd.push_back(text("fix gb_damping ", mobile, " viscous ", s.backgroundDamping));
  for (std::size_t w = 0; w < s.walls.size(); ++w) {
    const auto& wall = s.walls[w];
    int sign = 0;
    const int axis = axisOf(wall.direction, sign);
    LammpsInput::WallFix fix;
    // A wiggle moves the wall as a (1 - cos omega (n - n0) dt) from its base, a signed along the
    // axis; mid_stroke's base is one amplitude back from the rest position (wiggleOrigin).
    std::string wiggle;
    double base = wall.kind == dem::Wall::Kind::Plane ? wall.origin[axis] : 0.0;
    if (wall.vibration.active()) {
      int vibrationSign = 0;
      const int vibrationAxis = axisOf(wall.vibration.direction, vibrationSign);
      const double amplitude = vibrationSign * wall.vibration.amplitude;
      fix.vibrating = true;
      const bool wiggles = wiggleOrigin(wall.vibration, s.dt, fix.timeOrigin);
      GB_ASSERT(wiggles, "a refused vibration reached lammpsInput()");
      if (vibrationAxis == axis && wall.vibration.start == dem::Vibration::Start::MidStroke) base -= amplitude;
      wiggle = text(" wiggle ", kAxis[static_cast<std::size_t>(vibrationAxis)], " ", amplitude, " ",
                    1.0 / wall.vibration.frequency);
    }
    std::string geometry;
    if (wall.kind == dem::Wall::Kind::Plane) {
      // The normal points into the domain: a +z normal is a floor (lo), a -z one a lid (hi).
      const std::string at = exact(base);
      geometry =
          std::string(kAxis[static_cast<std::size_t>(axis)]) + "plane " + (sign > 0 ? at + " NULL" : "NULL " + at);
    } else {
      geometry = "zcylinder " + exact(wall.radius);
    }
    fix.command = "fix " + wallFixId(w) + " all wall/gran " + granularArgs(s, wall.material.front(), a * std::sqrt(2.0)) +
                  " " + geometry + wiggle + " contacts";
    in.walls.push_back(std::move(fix));
  }
  cmd.push_back(std::string("compute ") + kPairAtomsCompute + " all property/local patom1 patom2 cutoff radius");
  cmd.push_back(std::string("compute ") + kPairForcesCompute +
                " all pair/local dist fx fy fz p1 p2 p3 p5 p6 p7 cutoff radius");
  return in;
}

}  // namespace grainbridge::lammps
