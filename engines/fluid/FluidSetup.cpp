#include "engines/fluid/FluidSetup.hpp"

#include <cmath>
#include <exception>
#include <utility>

#include "core/json/Vec3Json.hpp"
#include "core/text/NumberText.hpp"
#include "engines/fluid/PetscKsp.hpp"
#include "engines/fluid/StaggeredGrid.hpp"

namespace grainbridge::fluid {

using nlohmann::json;

namespace {

constexpr std::array<const char*, 6> kSideNames = {"x_low", "x_high", "y_low", "y_high", "z_low", "z_high"};
constexpr std::array<std::pair<const char*, BoundaryKind>, 4> kKinds = {
    {{"no_slip_wall", BoundaryKind::NoSlipWall},
     {"free_slip_wall", BoundaryKind::FreeSlipWall},
     {"velocity_inlet", BoundaryKind::VelocityInlet},
     {"pressure_outlet", BoundaryKind::PressureOutlet}}};

// The Side of a side's name (index = Side), -1 for none.
int sideOf(const std::string& name) {
  for (std::size_t s = 0; s < kSideNames.size(); ++s) {
    if (name == kSideNames[s]) return static_cast<int>(s);
  }
  return -1;
}

std::optional<BoundaryKind> kindOf(const std::string& name) {
  for (const auto& [n, kind] : kKinds) {
    if (name == n) return kind;
  }
  return std::nullopt;
}

// Whether x is a whole number of h (to round-off).
bool onFaces(double x, double h) { return std::abs(x / h - std::round(x / h)) < 1e-6; }

// Each phase's inflow state of a patch on a side normal to `axis`, the gas first: the solids
// fractions given (0 beyond the list), the gas the rest; normal speeds into the domain.
std::vector<PhaseInflow> inflow(const PatchSetup& b, int side, std::size_t solidsPhases) {
  const int axis = side / 2;
  const double inward = side % 2 == 0 ? 1.0 : -1.0;
  std::vector<PhaseInflow> phases(1 + solidsPhases);
  double solids = 0.0;
  for (std::size_t m = 0; m < solidsPhases; ++m) {
    phases[m + 1].fraction = m < b.solidsFractions.size() ? b.solidsFractions[m] : 0.0;
    phases[m + 1].velocity[axis] = inward * (m < b.solidsInflow.size() ? b.solidsInflow[m] : 0.0);
    if (m < b.solidsTemperature.size()) phases[m + 1].granularTemperature = b.solidsTemperature[m];
    solids += phases[m + 1].fraction;
  }
  phases[0].fraction = 1.0 - solids;
  phases[0].velocity[axis] = inward * b.gasInflow;
  return phases;
}

std::string countProblem(std::size_t given, const char* what, std::size_t solidsPhases) {
  return "gives " + std::to_string(given) + " " + what + " for " + std::to_string(solidsPhases) + " solids phases";
}

}  // namespace

const char* sideKey(int side) { return kSideNames.at(static_cast<std::size_t>(side)); }

core::data::GridGeometry FluidSetup::geometry() const {
  core::data::GridGeometry g;
  g.cells = cells;
  for (int a = 0; a < 3; ++a) g.spacing[a] = lengths[a] / cells[static_cast<std::size_t>(a)];
  g.origin = Vec3::Zero();
  return g;
}

std::vector<SetupProblem> FluidSetup::problems(std::size_t solidsPhases, const PackedFraction& packedFraction) const {
  std::vector<SetupProblem> out;
  auto add = [&out](std::string pointer, std::string message) {
    out.push_back({std::move(pointer), std::move(message)});
  };
  bool gridUsable = true;
  for (std::size_t a = 0; a < 3; ++a) {
    if (cells[a] < 1) add("/cells/" + std::to_string(a), "needs at least one cell along every axis");
    if (!(lengths[static_cast<int>(a)] > 0.0)) add("/lengths/" + std::to_string(a), "must be positive");
    gridUsable = gridUsable && cells[a] >= 1 && lengths[static_cast<int>(a)] > 0.0;
  }
  for (auto& problem : timeStep.problems()) {
    if (!fixedStepKey.empty()) problem.pointer = "/" + fixedStepKey;  // dt, dt_min and dt_max are one key
    out.push_back(std::move(problem));
  }
  if (!gridUsable) return out;

  // Patches: sides, jets on cell faces, inflow states, a fixed step's CFL limit.
  const core::data::GridGeometry g = geometry();
  const bool fixedStep = timeStep.minimum == timeStep.maximum;
  const std::size_t before = out.size();
  for (std::size_t k = 0; k < boundaries.size(); ++k) {
    const PatchSetup& b = boundaries[k];
    const std::string at = "/boundaries/" + std::to_string(k);
    const int side = sideOf(b.side);
    const auto kind = kindOf(b.kind);
    if (side < 0) add(at + "/side", "no side named \"" + b.side + "\" (x_low, x_high, y_low, y_high, z_low, z_high)");
    if (!kind) {
      add(at + "/kind",
          "no boundary kind named \"" + b.kind + "\" (no_slip_wall, free_slip_wall, velocity_inlet, pressure_outlet)");
    }
    if (side < 0 || !kind) continue;
    const int axis = side / 2;
    if (twoD() && axis == 2) {
      add(at + "/side", "the grid is 2D (cells along z is 1): it has no z sides");
      continue;
    }
    const std::array<int, 2> tangential = tangentialAxes(axis);
    if (b.from.has_value() != b.to.has_value()) add(at, "give both from and to, or neither (the whole side)");
    if (b.from && b.to) {
      for (std::size_t q = 0; q < 2; ++q) {
        const int t = tangential[q];
        if (twoD() && t == 2) continue;
        const double from = (*b.from)[q], to = (*b.to)[q];
        const double h = g.spacing[t];
        const std::string axisName(1, "xyz"[t]);
        if (from < 0.0 || to > lengths[t] * (1.0 + 1e-9) || from >= to) {
          add(at + "/to", "the patch [" + core::humanNumber(from) + ", " + core::humanNumber(to) + "] m along " +
                              axisName + " is not inside the side (0 to " + core::humanNumber(lengths[t]) + " m)");
        } else if (!onFaces(from, h) || !onFaces(to, h)) {
          add(at + "/from", "the patch's ends along " + axisName + " (" + core::humanNumber(from) + ", " +
                                core::humanNumber(to) + " m) must lie on cell faces, multiples of " +
                                core::humanNumber(h) + " m");
        }
      }
    }
    if (!b.solidsFractions.empty() && b.solidsFractions.size() != solidsPhases)
      add(at + "/solids_fractions", countProblem(b.solidsFractions.size(), "fractions", solidsPhases));
    if (!b.solidsInflow.empty() && b.solidsInflow.size() != solidsPhases)
      add(at + "/solids_inflow", countProblem(b.solidsInflow.size(), "speeds", solidsPhases));
    for (std::size_t m = 0; m < b.solidsInflow.size(); ++m) {
      if (b.solidsInflow[m] < 0.0) {
        add(at + "/solids_inflow/" + std::to_string(m),
            "is " + core::humanNumber(b.solidsInflow[m]) +
                " m/s: a speed into the domain, not negative (solids leave through a pressure_outlet)");
      }
    }
    if (!b.solidsTemperature.empty() && b.solidsTemperature.size() != solidsPhases)
      add(at + "/solids_temperature", countProblem(b.solidsTemperature.size(), "temperatures", solidsPhases));
    if (!b.solidsTemperature.empty() && *kind != BoundaryKind::VelocityInlet)
      add(at + "/solids_temperature", "only a velocity_inlet's inflow carries a stated granular temperature");
    for (std::size_t m = 0; m < b.solidsTemperature.size(); ++m) {
      if (b.solidsTemperature[m] < 0.0)
        add(at + "/solids_temperature/" + std::to_string(m), "is negative: a granular temperature is >= 0");
    }
    // An inlet's gas speed is into the domain (inflow() turns it inward): a negative one would
    // pull gas out at a fixed speed whatever the pressure, with the inflow's fractions; gas
    // leaves through an outlet, which holds the pressure beyond it.
    if (*kind == BoundaryKind::VelocityInlet && b.gasInflow < 0.0) {
      add(at + "/gas_inflow", "is " + core::humanNumber(b.gasInflow) +
                                  " m/s: a velocity_inlet's gas speed is into the domain, not negative (gas leaves "
                                  "through a pressure_outlet)");
    }
    // A wall lets nothing through: its phases would be dropped without a word.
    const bool wall = *kind == BoundaryKind::NoSlipWall || *kind == BoundaryKind::FreeSlipWall;
    if (wall && b.gasInflow != 0.0) {
      add(at + "/gas_inflow", "is " + core::humanNumber(b.gasInflow) + " m/s, but a " + b.kind +
                                  " lets no gas through: blow it in through a velocity_inlet");
    }
    if (wall && !b.solidsFractions.empty())
      add(at + "/solids_fractions", "a " + b.kind + " lets no solids in: feed them through a velocity_inlet");
    if (wall && !b.solidsInflow.empty())
      add(at + "/solids_inflow", "a " + b.kind + " lets no solids in: feed them through a velocity_inlet");
    const std::vector<PhaseInflow> phases = inflow(b, side, solidsPhases);
    double solids = 0.0;
    std::vector<double> fractions;
    for (std::size_t m = 1; m < phases.size(); ++m) {
      solids += phases[m].fraction;
      fractions.push_back(phases[m].fraction);
    }
    if (const double packed = packedFraction(fractions); solids > packed) {
      add(at + "/solids_fractions",
          "the solids fractions add up to " + core::humanNumber(solids) + ", above the packed solids fraction " +
              core::humanNumber(packed) +
              " (eps_s,max of this feed's composition: packed_solids_fraction, by default 1 - "
              "critical_void_fraction, or under a packing_limit by composition from the "
              "phases' max_packing; feed less)");
    }
    if (*kind == BoundaryKind::VelocityInlet && fixedStep) {
      for (std::size_t m = 0; m < phases.size(); ++m) {
        const double cfl = std::abs(phases[m].velocity[axis]) * timeStep.maximum / g.spacing[axis];
        if (cfl > timeStep.courant) {
          add(at + (m == 0 ? "/gas_inflow" : "/solids_inflow"),
              "with the fixed time step " + core::humanNumber(timeStep.maximum) + " s the inflow crosses " +
                  core::humanNumber(cfl) + " cells per step, above the Courant limit " +
                  core::humanNumber(timeStep.courant) + ": " +
                  (fixedStepKey.empty() ? std::string("lower dt or let it adapt (dt_min < dt_max)")
                                        : "lower " + fixedStepKey));
        }
      }
    }
  }
  // Overlapping patches: the grid's own check, named at the boundaries.
  if (out.size() == before) {
    try {
      const StaggeredGrid grid(g);
      const Boundaries check(grid, patches(solidsPhases), 1 + solidsPhases);
    } catch (const std::exception& e) {
      add("/boundaries", e.what());
    }
  }
  return out;
}

std::vector<BoundaryPatch> FluidSetup::patches(std::size_t solidsPhases) const {
  const core::data::GridGeometry g = geometry();
  std::vector<BoundaryPatch> out;
  for (const PatchSetup& b : boundaries) {
    BoundaryPatch patch;
    patch.side = sideOf(b.side);
    patch.kind = kindOf(b.kind).value_or(BoundaryKind::NoSlipWall);
    if (b.from && b.to) {
      const std::array<int, 2> tangential = tangentialAxes(patch.side / 2);
      for (std::size_t q = 0; q < 2; ++q) {
        const int t = tangential[q];
        if (twoD() && t == 2) continue;
        patch.from[q] = static_cast<int>(std::lround((*b.from)[q] / g.spacing[t]));
        patch.to[q] = static_cast<int>(std::lround((*b.to)[q] / g.spacing[t]));
      }
      if (twoD()) {
        patch.from[1] = 0;
        patch.to[1] = 1;
      }
    }
    patch.pressure = b.pressure;
    // Inflow (inlet) or backflow (outlet) state; walls carry none.
    if (patch.kind == BoundaryKind::VelocityInlet || patch.kind == BoundaryKind::PressureOutlet)
      patch.phases = inflow(b, patch.side, solidsPhases);
    out.push_back(std::move(patch));
  }
  return out;
}

void to_json(json& j, const PatchSetup& p) {
  j = {{"side", p.side},
       {"kind", p.kind},
       {"gas_inflow", p.gasInflow},
       {"solids_fractions", p.solidsFractions},
       {"solids_inflow", p.solidsInflow},
       {"solids_temperature", p.solidsTemperature},
       {"pressure", p.pressure}};
  if (p.from) j["from"] = *p.from;
  if (p.to) j["to"] = *p.to;
}

void from_json(const json& j, PatchSetup& p) {
  p.side = j.at("side").get<std::string>();
  p.kind = j.at("kind").get<std::string>();
  p.from = j.contains("from") ? std::optional(j.at("from").get<std::array<double, 2>>()) : std::nullopt;
  p.to = j.contains("to") ? std::optional(j.at("to").get<std::array<double, 2>>()) : std::nullopt;
  p.gasInflow = j.at("gas_inflow");
  p.solidsFractions = j.at("solids_fractions").get<std::vector<double>>();
  p.solidsInflow = j.at("solids_inflow").get<std::vector<double>>();
  p.solidsTemperature = j.value("solids_temperature", std::vector<double>{});
  p.pressure = j.at("pressure");
}

void to_json(json& j, const FluidSetup& s) {
  j = {{"cells", s.cells},
       {"lengths", core::json::vec3Json(s.lengths)},
       {"boundaries", s.boundaries},
       {"dt", s.timeStep.initial},
       {"dt_min", s.timeStep.minimum},
       {"dt_max", s.timeStep.maximum},
       {"courant", s.timeStep.courant}};
}

void from_json(const json& j, FluidSetup& s) {
  s.cells = j.at("cells").get<std::array<int, 3>>();
  s.lengths = core::json::vec3FromJson(j.at("lengths"));
  s.boundaries = j.at("boundaries").get<std::vector<PatchSetup>>();
  s.timeStep.initial = j.at("dt");
  s.timeStep.minimum = j.at("dt_min");
  s.timeStep.maximum = j.at("dt_max");
  s.timeStep.courant = j.at("courant");
}

LinearSolve linearSolveFromJson(const nlohmann::json& p, const std::string& family) {
  LinearSolve how;
  const std::string name = p.at(family + "_solver").get<std::string>();
  if (name == "bicgstab") how.method = LinearSolve::Method::Iterative;
  if (name == "gauss_seidel") how.method = LinearSolve::Method::GaussSeidel;
  if (name == "petsc") how.method = LinearSolve::Method::Petsc;
  how.tolerance = p.at(family + "_solver_tolerance");
  // Optional in the object (a set-up written before issue 58 has none); the schema fills it in.
  if (const auto options = p.find(family + "_petsc_options"); options != p.end())
    how.petscOptions = options->get<std::string>();
  return how;
}

std::vector<SetupProblem> linearSolveProblems(const LinearSolve& how, const std::string& family) {
  if (how.method != LinearSolve::Method::Petsc) return {};
  if (!petscAvailable())
    return {{"/" + family + "_solver",
             "petsc: this build has no PETSc (" + petscBuildNote() + "); install libpetsc-real-dev and rebuild"}};
  if (auto why = petscOptionsProblem(how.petscOptions)) return {{"/" + family + "_petsc_options", *why}};
  return {};
}

}  // namespace grainbridge::fluid
