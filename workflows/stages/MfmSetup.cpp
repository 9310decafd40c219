#include "workflows/stages/MfmSetup.hpp"

#include <cmath>
#include <map>
#include <optional>

#include "core/text/NumberText.hpp"
#include "engines/closures/SyamlalOBrien.hpp"
#include "engines/closures/TabulatedClosure.hpp"
#include "engines/fluid/BedMeasures.hpp"

namespace grainbridge::workflows::stages {

using nlohmann::json;

namespace {

const std::map<std::string, int> kSides = {{"x_low", fluid::XLow}, {"x_high", fluid::XHigh},
                                           {"y_low", fluid::YLow}, {"y_high", fluid::YHigh},
                                           {"z_low", fluid::ZLow}, {"z_high", fluid::ZHigh}};
const std::map<std::string, fluid::BoundaryKind> kKinds = {{"no_slip_wall", fluid::BoundaryKind::NoSlipWall},
                                                           {"free_slip_wall", fluid::BoundaryKind::FreeSlipWall},
                                                           {"velocity_inlet", fluid::BoundaryKind::VelocityInlet},
                                                           {"pressure_outlet", fluid::BoundaryKind::PressureOutlet}};

Vec3 vec3(const json& j) { return Vec3(j.at(0).get<double>(), j.at(1).get<double>(), j.at(2).get<double>()); }

// Whether x is a whole number of h (to round-off).
bool onFaces(double x, double h) { return std::abs(x / h - std::round(x / h)) < 1e-6; }

}  // namespace

std::int64_t mfmSteps(const json& p) {
  return std::max<std::int64_t>(1,
                                std::llround(p.at("duration").get<double>() / p.at("output_interval").get<double>()));
}

std::string tableQuantity(const std::string& q) {
  return q == "pressure" ? "p_theta" : q == "shear_viscosity" ? "eta_theta" : "j_theta";
}

MfmSetup makeMfmSetup(const json& p, const json* closureTables) {
  MfmSetup s;
  auto problem = [&s](std::string where, std::string what) {
    s.problems.emplace_back(std::move(where), std::move(what));
  };

  // The grid.
  const json& cells = p.at("cells");
  const Vec3 lengths = vec3(p.at("lengths"));
  auto& geometry = s.engine.geometry;
  for (int a = 0; a < 3; ++a) {
    geometry.cells[static_cast<std::size_t>(a)] = cells.at(static_cast<std::size_t>(a)).get<int>();
    geometry.spacing[a] = lengths[a] / geometry.cells[static_cast<std::size_t>(a)];
  }
  geometry.origin = Vec3::Zero();
  const bool twoD = geometry.cells[2] == 1;

  // The phases and their closures.
  auto& model = s.engine.model;
  model.gas.density = p.at("gas_density");
  model.gas.viscosity = p.at("gas_viscosity");
  model.gas.ideal = p.at("gas_model").get<std::string>() == "ideal";
  model.gas.molarMass = p.at("gas_molar_mass");
  model.gas.temperature = p.at("gas_temperature");
  for (const auto& sp : p.at("solids")) {
    mfm::SolidsPhase phase;
    phase.name = sp.at("name").get<std::string>();
    phase.diameter = sp.at("diameter");
    phase.density = sp.at("density");
    phase.restitution = sp.at("restitution");
    phase.wallRestitution = sp.contains("wall_restitution") ? sp.at("wall_restitution").get<double>() : phase.restitution;
    phase.friction = sp.at("friction");
    phase.wallFriction = sp.at("wall_friction");
    phase.tangentialRestitution = sp.at("tangential_restitution");
    model.solids.push_back(std::move(phase));
  }
  const std::size_t M = model.solids.size();
  model.drag = closures::GasSolidsDrag::byName(p.at("drag").get<std::string>());
  if (auto* so = std::get_if<closures::SyamlalOBrien>(&model.drag.law)) {
    so->params = {p.at("drag_c").get<double>(), p.at("drag_d").get<double>()};
    if (const auto why = so->params.continuityProblem(); !why.empty()) problem("/drag_d", why);
  }
  const std::string kineticModel = p.at("kinetic_model");
  model.kinetic.params.viscosityForm = kineticModel == "syamlal_algebraic_mfix" ? closures::SyamlalViscosityForm::Mfix
                                                                               : closures::SyamlalViscosityForm::Printed;
  model.closure = closures::ClosureModel::kineticTheory(closures::kineticModelFromString(kineticModel));
  model.granularEnergy =
      p.at("granular_energy").get<std::string>() == "pde" ? mfm::GranularEnergyForm::Pde : mfm::GranularEnergyForm::Algebraic;
  model.rotation = p.at("rotation_model");
  const bool johnsonJackson = p.at("solids_walls").get<std::string>() == "johnson_jackson";
  if (p.at("closure").get<std::string>() == "table") {
    if (!p.contains("closure_table")) problem("/closure_table", "closure \"table\" needs the name of the tables");
    if (!p.contains("out_of_range")) {
      problem("/out_of_range",
              "closure \"table\" needs an explicit out-of-range policy: error, clamp or kinetic_theory");
    }
    if (p.at("table_quantities").empty()) problem("/table_quantities", "name at least one quantity the table supplies");
    if (model.granularEnergy != mfm::GranularEnergyForm::Pde)
      problem("/granular_energy", "a closure table is read at the granular-energy equation's theta: needs pde");
    if (closureTables != nullptr && s.problems.empty()) {
      const auto policy = closures::outOfRangePolicyFromString(p.value("out_of_range", "error"));
      const auto fallback = closures::kineticModelFromString(kineticModel);
      std::optional<closures::TabulatedClosure> pressure, viscosity, dissipation;
      for (const auto& record : *closureTables) {
        const core::ClosureTable table(record.at("quantity").get<std::string>(),
                                       record.at("solid_fractions").get<std::vector<double>>(),
                                       record.at("second_variable").get<std::string>(),
                                       record.at("seconds").get<std::vector<double>>(),
                                       record.at("values").get<std::vector<double>>());
        const double friction = record.at("filters").value("friction", 0.0);
        if (model.rotation && friction > 0.0) {
          problem("/rotation_model", "closure table \"" + record.at("name").get<std::string>() + "\" (" +
                                         table.quantity() + ") was made from grains with friction " +
                                         core::humanNumber(friction) +
                                         ": the rotation model would count their friction a second time");
        }
        closures::TabulatedClosure closure(table, policy, fallback);
        if (table.quantity() == "p_theta") pressure.emplace(closure);
        if (table.quantity() == "eta_theta") viscosity.emplace(closure);
        if (table.quantity() == "j_theta") dissipation.emplace(closure);
      }
      model.closure = closures::ClosureModel::tabulated(fallback, pressure, viscosity, dissipation);
    }
  }
  if (model.granularEnergy == mfm::GranularEnergyForm::Algebraic) {
    if (kineticModel == "lun1984")
      problem("/granular_energy", "the algebraic balance is written for the syamlal kinetic models; lun1984 needs pde");
    if (model.rotation) problem("/rotation_model", "the rotation model needs granular_energy pde");
    if (johnsonJackson) problem("/solids_walls", "Johnson-Jackson walls need granular_energy pde");
  }
  model.plastic.params.criticalVoidFraction = p.at("critical_void_fraction").get<double>();
  model.plastic.params.internalFrictionAngle = p.at("friction_angle").get<double>();
  if (const auto why = model.plastic.params.problem(); !why.empty()) problem("/friction_angle", why);
  const double packed = p.contains("packed_solids_fraction") ? p.at("packed_solids_fraction").get<double>()
                                                             : 1.0 - model.plastic.params.criticalVoidFraction;
  if (johnsonJackson) model.wall = closures::JohnsonJackson::Params{p.at("specularity").get<double>(), packed, 1.0, {}};

  // The solver.
  auto& settings = s.engine.settings;
  settings.gravity = vec3(p.at("gravity"));
  settings.packedFraction = packed;
  settings.tolerance = p.at("tolerance");
  settings.maxIterations = p.at("max_iterations");
  settings.momentumRelaxation = p.at("momentum_relaxation");
  settings.pressureRelaxation = p.at("pressure_relaxation");
  settings.fractionRelaxation = p.at("fraction_relaxation");
  settings.diluteFraction = p.at("dilute_fraction");
  auto& limits = s.engine.limits;
  limits.initial = p.at("dt");
  limits.minimum = p.at("dt_min");
  limits.maximum = p.at("dt_max");
  limits.courant = p.at("courant");
  if (const auto why = limits.problem(); !why.empty()) problem("/dt", why);
  s.engine.interval = p.at("output_interval");
  s.duration = p.at("duration");
  s.averageFrom = p.at("average_from");
  if (s.averageFrom >= s.duration) problem("/average_from", "must be before the end of the run (duration)");
  if (s.engine.interval > s.duration) problem("/output_interval", "is longer than the run (duration)");
  const bool fixedStep = limits.minimum == limits.maximum;

  // Boundaries: sides, jets on cell faces, inflow states, a fixed step's CFL limit.
  for (std::size_t k = 0; k < p.at("boundaries").size(); ++k) {
    const json& b = p["boundaries"][k];
    const std::string at = "/boundaries/" + std::to_string(k);
    fluid::BoundaryPatch patch;
    patch.side = kSides.at(b.at("side").get<std::string>());
    patch.kind = kKinds.at(b.at("kind").get<std::string>());
    const int axis = patch.side / 2;
    if (twoD && axis == 2) {
      problem(at + "/side", "the grid is 2D (cells along z is 1): it has no z sides");
      continue;
    }
    const std::array<int, 2> tangential = fluid::tangentialAxes(axis);
    if (b.contains("from") != b.contains("to")) problem(at, "give both from and to, or neither (the whole side)");
    if (b.contains("from") && b.contains("to")) {
      for (int q = 0; q < 2; ++q) {
        const int t = tangential[static_cast<std::size_t>(q)];
        if (twoD && t == 2) continue;
        const double from = b["from"].at(static_cast<std::size_t>(q)), to = b["to"].at(static_cast<std::size_t>(q));
        const double h = geometry.spacing[t];
        const std::string axisName(1, "xyz"[t]);
        if (from < 0.0 || to > lengths[t] * (1.0 + 1e-9) || from >= to) {
          problem(at + "/to", "the patch [" + core::humanNumber(from) + ", " + core::humanNumber(to) + "] m along " +
                                  axisName + " is not inside the side (0 to " + core::humanNumber(lengths[t]) + " m)");
        } else if (!onFaces(from, h) || !onFaces(to, h)) {
          problem(at + "/from", "the patch's ends along " + axisName + " (" + core::humanNumber(from) + ", " +
                                    core::humanNumber(to) + " m) must lie on cell faces, multiples of " +
                                    core::humanNumber(h) + " m");
        }
        patch.from[static_cast<std::size_t>(q)] = static_cast<int>(std::lround(from / h));
        patch.to[static_cast<std::size_t>(q)] = static_cast<int>(std::lround(to / h));
      }
      if (twoD) {
        patch.from[1] = 0;
        patch.to[1] = 1;
      }
    }
    patch.pressure = b.at("pressure");
    // Inflow (inlet) or backflow (outlet) state: normal speeds into the domain.
    const double inward = patch.side % 2 == 0 ? 1.0 : -1.0;
    const json& fractions = b.at("solids_fractions");
    const json& speeds = b.at("solids_inflow");
    if (!fractions.empty() && fractions.size() != M)
      problem(at + "/solids_fractions",
              "gives " + std::to_string(fractions.size()) + " fractions for " + std::to_string(M) + " solids phases");
    if (!speeds.empty() && speeds.size() != M)
      problem(at + "/solids_inflow",
              "gives " + std::to_string(speeds.size()) + " speeds for " + std::to_string(M) + " solids phases");
    double solids = 0.0;
    patch.phases.assign(1 + M, fluid::PhaseInflow{});
    for (std::size_t m = 0; m < M; ++m) {
      patch.phases[m + 1].fraction = m < fractions.size() ? fractions[m].get<double>() : 0.0;
      patch.phases[m + 1].velocity[axis] = inward * (m < speeds.size() ? speeds[m].get<double>() : 0.0);
      solids += patch.phases[m + 1].fraction;
    }
    if (solids > packed) {
      problem(at + "/solids_fractions", "the solids fractions add up to " + core::humanNumber(solids) +
                                            ", above the packed solids fraction " + core::humanNumber(packed));
    }
    patch.phases[0].fraction = 1.0 - solids;
    patch.phases[0].velocity[axis] = inward * b.at("gas_inflow").get<double>();
    if (patch.kind == fluid::BoundaryKind::VelocityInlet && fixedStep) {
      for (std::size_t m = 0; m <= M; ++m) {
        const double cfl = std::abs(patch.phases[m].velocity[axis]) * limits.maximum / geometry.spacing[axis];
        if (cfl > limits.courant) {
          problem(at + (m == 0 ? "/gas_inflow" : "/solids_inflow"),
                  "with the fixed time step " + core::humanNumber(limits.maximum) + " s the inflow crosses " +
                      core::humanNumber(cfl) + " cells per step, above the Courant limit " +
                      core::humanNumber(limits.courant) + ": lower dt or let it adapt (dt_min < dt_max)");
        }
      }
    }
    if (patch.kind != fluid::BoundaryKind::VelocityInlet && patch.kind != fluid::BoundaryKind::PressureOutlet)
      patch.phases.clear();
    s.engine.patches.push_back(std::move(patch));
  }
  // Overlapping patches: the grid's own check, named at the boundaries.
  if (s.problems.empty()) {
    try {
      const fluid::StaggeredGrid grid(geometry);
      const fluid::Boundaries check(grid, s.engine.patches, 1 + M);
    } catch (const std::exception& e) {
      problem("/boundaries", e.what());
    }
  }

  // Initial regions.
  const json regions = p.value("regions", json::array());
  for (std::size_t k = 0; k < regions.size(); ++k) {
    const json& r = regions[k];
    const std::string at = "/regions/" + std::to_string(k);
    mfm::InitialRegion region;
    region.lo = vec3(r.at("lo"));
    region.hi = vec3(r.at("hi"));
    const json& fractions = r.at("solids_fractions");
    if (fractions.size() != M) {
      problem(at + "/solids_fractions",
              "gives " + std::to_string(fractions.size()) + " fractions for " + std::to_string(M) + " solids phases");
      continue;
    }
    double solids = 0.0;
    for (const auto& f : fractions) {
      region.solidsFractions.push_back(f.get<double>());
      solids += f.get<double>();
    }
    if (solids > packed + 1e-12) {
      problem(at + "/solids_fractions",
              "the solids fractions add up to " + core::humanNumber(solids) +
                  ", above the packed solids fraction eps_s,max = " + core::humanNumber(packed));
    }
    region.granularTemperature = r.at("granular_temperature");
    region.velocities.push_back(vec3(r.at("gas_velocity")));
    for (std::size_t m = 0; m < M; ++m) region.velocities.push_back(vec3(r.at("solids_velocity")));
    s.initial.regions.push_back(std::move(region));
  }
  s.initial.referencePressure = p.at("reference_pressure");
  s.initial.perturbation = p.at("perturbation");
  s.initial.seed = p.at("seed").get<std::uint64_t>();

  // Pressure taps, heights along gravity.
  const fluid::VerticalAxis vertical = fluid::verticalAxis(settings.gravity);
  const double height = lengths[vertical.axis];
  const json taps = p.value("pressure_taps", json::array());  // optional lists: absent when not given
  for (std::size_t k = 0; k < taps.size(); ++k) {
    const json& t = taps[k];
    PressureTap tap{t.at("name").get<std::string>(), t.at("low").get<double>(), t.at("high").get<double>()};
    if (!(tap.low < tap.high) || tap.low < 0.0 || tap.high > height * (1.0 + 1e-9)) {
      problem("/pressure_taps/" + std::to_string(k) + "/high",
              "the taps must satisfy 0 <= low < high <= " + core::humanNumber(height) + " m (the domain's height)");
    }
    s.taps.push_back(std::move(tap));
  }
  return s;
}

}  // namespace grainbridge::workflows::stages
