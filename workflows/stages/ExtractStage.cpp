#include "workflows/stages/ExtractStage.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <sstream>

#include "core/ClosureForms.hpp"
#include "core/Error.hpp"
#include "core/Files.hpp"
#include "core/Log.hpp"
#include "core/grid/CellGrid.hpp"
#include "core/io/FieldFrameReader.hpp"
#include "core/io/FieldFrameWriter.hpp"
#include "core/io/ParticleFrameReader.hpp"
#include "core/text/NumberText.hpp"
#include "core/averaging/BlockAverage.hpp"
#include "extract/coarse/CoarseGrain.hpp"
#include "extract/coarse/DissipationRate.hpp"
#include "extract/coarse/DomainAverages.hpp"
#include "core/averaging/FieldTimeAverage.hpp"
#include "extract/structure/ForceNetworks.hpp"
#include "extract/structure/MstTreeContacts.hpp"
#include "extract/structure/MultiPassMst.hpp"
#include "workflows/stages/ExtractForceStatistics.hpp"
#include "workflows/stages/SurfaceTracker.hpp"

namespace grainbridge::workflows::stages {

using core::units::Dimension;
using nlohmann::json;
using params::ParamSpec;

ExtractStage::ExtractStage() {
  schema_
      .add(ParamSpec::string("family").defaultValue("generic").doc(
          "closure family of the points (simple_shear, fluidized_cell, bnp, ...): what db query filters on"))
      .add(ParamSpec::quantity("start_time", Dimension::timeDim())
               .defaultValue(0.0)
               .min(0.0)
               .doc("frames before this time are discarded (transient)"))
      .add(ParamSpec::quantity("end_time", Dimension::timeDim())
               .min(0.0)
               .doc("frames after this time are not averaged (default: none after the start)"))
      .add(ParamSpec::number("start_strain")
               .defaultValue(0.0)
               .min(0.0)
               .doc("under Lees-Edwards shear: frames before this strain (shear rate x time) are discarded"))
      .add(ParamSpec::integerList("grid_cells", 3)
               .min(1)
               .doc("coarse-grained fields on a grid of nx x ny x nz cells over the domain, one field frame per "
                    "averaged frame (fields.xmf opens in ParaView) and their time average with block-averaging "
                    "errors (mean/fields.xmf, <field>_err); none when absent"))
      .add(ParamSpec::string("kernel")
               .defaultValue("bin")
               .options({"bin", "overlap", "gaussian", "lucy"})
               .doc("coarse-graining kernel: particle-centre cell (Eqs. 7.35-7.36), exact sphere-cell overlap, or "
                    "a Gaussian / Lucy kernel of width kernel_width"))
      .add(ParamSpec::quantity("kernel_width", Dimension::lengthDim())
               .defaultValue(0.0)
               .min(0.0)
               .doc("width w of the gaussian and lucy kernels (their standard deviation per axis)"))
      .add(ParamSpec::boolean("structure")
               .defaultValue(false)
               .doc("force networks and the multi-pass MST of every averaged frame (structure_statistics)"))
      .add(ParamSpec::boolean("force_statistics")
               .defaultValue(false)
               .doc("force PDF with its Eq. 6.11 and 6.13 fits, force (Eq. 6.12) and velocity correlations and "
                    "lengths, velocity kurtosis, pooled over the averaged frames"))
      .add(ParamSpec::number("correlation_range")
               .defaultValue(5.0)
               .positive()
               .doc("largest distance of the correlation functions, in mean diameters (at most half the box)"))
      .add(ParamSpec::integer("mst_passes").defaultValue(5).min(1).max(100).doc("MST passes (Section 6.3.3)"))
      .add(ParamSpec::number("mst_elongation")
               .defaultValue(1.2)
               .min(1.0)
               .doc("elongation factor of previously selected MST edges"))
      .add(ParamSpec::boolean("closure_point")
               .defaultValue(true)
               .doc("record the time-averaged closure point; false for runs that have no steady state to "
                    "average (a vibrated Brazil-nut bed analysed for its surface or structure)"))
      .add(ParamSpec::integerList("surface_particles", 0)
               .defaultValue(json::array())
               .min(0)
               .doc("particle ids whose top is measured against the local free surface of the bed in every "
                    "averaged frame (surface.csv; the Brazil-nut 'at the top' criterion)"))
      .add(ParamSpec::number("surface_tolerance")
               .defaultValue(1.0)
               .positive()
               .doc("a particle is at the top when its top is within this many smallest-grain diameters of "
                    "the local free surface"))
      .add(ParamSpec::number("surface_min_coordination")
               .defaultValue(2.0)
               .min(0.0)
               .doc("frames whose mean coordination number is below this (a vibrated bed in flight) are "
                    "written to surface.csv but not judged"));
}

namespace {

// A grid's cell arrays, per frame: the coarse-grained fields (a few tensors and scalars per
// species), the field frame written from them and the running time average each hold about
// 300-400 bytes a cell; 1 kB a cell is the round estimate the limit below is stated in.
constexpr double kGridBytesPerCell = 1024.0;
// The most memory a grid's per-frame arrays may take: far above any grid a DEM run's particles
// can fill (a cell should hold a few particles), far below a request that cannot be allocated.
constexpr double kGridBytesLimit = 8.0 * 1024.0 * 1024.0 * 1024.0;

// Where the averaging window starts for one upstream run: start_time, or the time its shear
// reaches start_strain, whichever is later.
double windowStart(const json& p, double shearRate) {
  double start = p.at("start_time");
  if (p.at("start_strain").get<double>() > 0.0 && shearRate != 0.0) {
    start = std::max(start, p.at("start_strain").get<double>() / std::abs(shearRate));
  }
  return start;
}

// Six significant digits: enough to recognise a value in a message.
std::string shortNumber(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

std::string seconds(double t) { return shortNumber(t) + " s"; }

}  // namespace

void ExtractStage::checkParams(const json& p, const std::string& ptr, core::json::Diagnostics& d) const {
  const std::string kernel = p.at("kernel");
  if ((kernel == "gaussian" || kernel == "lucy") && !(p.at("kernel_width").get<double>() > 0.0)) {
    d.add(ptr + "/kernel_width", "the " + kernel +
                                     " kernel needs a positive kernel_width (its standard deviation per axis, a "
                                     "length), found " +
                                     shortNumber(p.at("kernel_width").get<double>()));
  }
  if (p.contains("grid_cells")) {
    const json& cells = p["grid_cells"];
    // In doubles: a product of three int64 counts can overflow.
    const double total = cells[0].get<double>() * cells[1].get<double>() * cells[2].get<double>();
    if (total * kGridBytesPerCell > kGridBytesLimit) {
      std::ostringstream msg;
      msg.precision(3);
      msg << "a grid of " << cells[0].get<std::int64_t>() << " x " << cells[1].get<std::int64_t>() << " x "
          << cells[2].get<std::int64_t>() << " = " << total << " cells needs about " << total * kGridBytesPerCell / 1e9
          << " GB of cell arrays per frame (about 1 kB a cell), above the limit of "
          << kGridBytesLimit / (1024.0 * 1024.0 * 1024.0) << " GiB ("
          << static_cast<std::int64_t>(kGridBytesLimit / kGridBytesPerCell) << " cells); use fewer cells";
      d.add(ptr + "/grid_cells", msg.str());
    }
  }
  if (p.contains("end_time") && p.at("end_time").get<double>() < p.at("start_time").get<double>()) {
    d.add(ptr + "/end_time", "the averaging window is empty: end_time " + seconds(p.at("end_time")) +
                                 " is before start_time " + seconds(p.at("start_time")));
  }
}

void ExtractStage::checkAgainstUpstream(const json& p, const std::string& ptr,
                                        const std::vector<UpstreamPlan>& upstream, core::json::Diagnostics& d) const {
  const double startStrain = p.at("start_strain");
  for (const auto& up : upstream) {
    const PlannedOutput& out = up.output;
    if (!out.particleFrames) continue;
    const std::string from = "upstream stage " + up.stage;
    const std::optional<double> rate = out.leesEdwardsShearRate;
    if (startStrain > 0.0 && rate && *rate == 0.0) {
      d.add(ptr + "/start_strain", from + " has no Lees-Edwards shear rate (its strain stays 0), so start_strain " +
                                       shortNumber(startStrain) + " is never reached; use start_time");
    } else {
      // With the shear rate unknown, start_time is a lower bound of the start.
      const double start = windowStart(p, rate.value_or(0.0));
      const bool fromStrain = start > p.at("start_time").get<double>();
      const std::string startText = fromStrain ? "start_strain " + shortNumber(startStrain) + " at the shear rate " +
                                                     shortNumber(std::abs(*rate)) + " 1/s of " + up.stage +
                                                     " is reached at " + seconds(start)
                                               : "start_time is " + seconds(start);
      if (out.lastFrameTime && start > *out.lastFrameTime * (1.0 + 1e-9)) {
        d.add(ptr + (fromStrain ? "/start_strain" : "/start_time"),
              "the averaging window starts after the last frame of " + from + ": " + startText +
                  ", its last frame is at " + seconds(*out.lastFrameTime) + "; no frame to average");
      } else if (fromStrain && p.contains("end_time") && p.at("end_time").get<double>() < start) {
        d.add(ptr + "/end_time", "the averaging window is empty: end_time " + seconds(p.at("end_time")) +
                                     " is before its start (" + startText + ")");
      }
    }
    if (out.particleCount) {
      const std::int64_t n = *out.particleCount;
      for (std::size_t k = 0; k < p.at("surface_particles").size(); ++k) {
        const auto id = p["surface_particles"][k].get<std::int64_t>();
        if (id >= n) {
          d.add(ptr + "/surface_particles/" + std::to_string(k),
                "no particle with id " + std::to_string(id) + " in " + from + " (it inserts " + std::to_string(n) +
                    " particles, ids 0 to " + std::to_string(n - 1) + ")");
        }
      }
    }
  }
}

namespace {

// One time-averaged quantity: mean and block-averaging standard error.
struct Averaged {
  double mean = 0.0;
  double error = 0.0;
};

Averaged averaged(const std::vector<double>& samples) {
  const auto b = core::averaging::blockAverage(samples);
  return {b.mean, b.standardError};
}

// Restitution and friction of the first species pair, from the materials the frames carry
// (core/data/Materials): the state a closure point belongs to. Frames without contact
// materials (a particle gas) have none.
void contactMaterial(const core::data::Materials& materials, json& row) {
  if (materials.pairs.empty()) return;
  row["restitution"] = materials.pairs.front().restitution;
  row["friction"] = materials.pairs.front().friction;
}

std::optional<SurfaceTracker> surfaceTracker(const StageContext& ctx, const core::data::Materials& materials) {
  const json& p = ctx.params();
  if (p.at("surface_particles").empty()) return std::nullopt;
  SurfaceTrackerOptions options;
  // Integers >= 0 by declaration; whether the frames hold them is checked frame by frame.
  for (const auto& id : p["surface_particles"]) options.ids.push_back(id.get<std::int64_t>());
  options.up = materials.up();  // heights are measured against gravity, +z without it
  options.tolerance = p.at("surface_tolerance");
  options.minCoordination = p.at("surface_min_coordination");
  return SurfaceTracker(std::move(options));
}

// The coarse-grained fields of one frame as a field frame: the solids phases (one per species,
// named as the upstream dem stage names them) in the continuum slots, everything else DEM
// adds (stress tensors, pressure, coordination, forces) as named extra fields.
core::data::FieldFrame toFieldFrame(const core::data::ParticleFrame& frame, const extract::coarse::CoarseFields& c,
                                    const std::vector<std::string>& speciesNames) {
  core::data::FieldFrame out;
  out.time = frame.time;
  out.step = frame.step;
  out.units = frame.units;
  out.grid = c.grid.geometry();
  const std::size_t n = c.solidFraction.size();
  out.ep_g.resize(n);
  for (std::size_t k = 0; k < n; ++k) out.ep_g[k] = 1.0 - c.solidFraction[k];
  out.p_g.assign(n, 0.0);  // no gas in a DEM frame
  out.u_g.assign(n, Vec3::Zero());
  for (const auto& sp : c.species) {
    core::data::SolidsPhaseFields phase;
    const auto index = static_cast<std::size_t>(sp.species);
    phase.name = index < speciesNames.size() ? speciesNames[index] : "species" + std::to_string(index);
    phase.ep_s = sp.solidFraction;
    phase.u_s = sp.velocity;
    phase.theta = sp.granularTemperature;
    out.solids.push_back(std::move(phase));
  }
  auto scalar = [&](const char* name, const std::vector<double>& v) { out.extras.push_back({name, 1, v}); };
  auto tensor = [&](const char* name, const std::vector<Mat3>& v) {
    core::data::NamedCellField f{name, 9, {}};
    f.values.reserve(9 * v.size());
    for (const Mat3& m : v) {
      for (int a = 0; a < 3; ++a) {
        for (int b = 0; b < 3; ++b) f.values.push_back(m(a, b));
      }
    }
    out.extras.push_back(std::move(f));
  };
  scalar("solid_fraction", c.solidFraction);
  scalar("granular_temperature", c.granularTemperature);
  scalar("pressure", c.pressure);
  scalar("shear_stress", c.shearStress);
  scalar("deviatoric_stress", c.deviatoricStress);
  tensor("stress", c.stress);
  tensor("kinetic_stress", c.kineticStress);
  tensor("contact_stress", c.contactStress);
  scalar("coordination", c.coordinationNumber);
  scalar("multi_contact_ratio", c.multiContactRatio);
  scalar("contact_force", c.contactForce);
  if (!frame.externalForce.empty()) {
    scalar("drag_force", c.dragForce);
    scalar("contact_to_drag_ratio", c.contactToDragRatio);
  }
  return out;
}

}  // namespace

void ExtractStage::run(StageContext& ctx) const {
  const json& p = ctx.params();
  if (ctx.inputs().size() != 1) {
    throw Error("extract: needs exactly one upstream instance with particle frames, got " +
                std::to_string(ctx.inputs().size()));
  }
  const UpstreamInstance& up = ctx.inputs().front();
  const auto files = core::io::listParticleFrames(up.dir);
  if (files.empty()) {
    throw Error("extract: upstream " + up.stage + " (" + up.dir.string() + ") has no particle frames");
  }

  // Frames after the transient.
  std::vector<std::filesystem::path> selected;
  // Frame times, read once (summaries only: no particle arrays).
  std::vector<double> times;
  for (const auto& f : files) times.push_back(core::io::readParticleFrameSummary(f).time);
  // What the engine wrote beside its frames: the shear it imposed, its materials.
  const auto firstFrame = core::io::readParticleFrame(files.front());
  const double shearRate = firstFrame.domain.leesEdwardsShearRate;
  const core::data::Materials& materials = firstFrame.materials;
  double start = p.at("start_time");
  if (p.at("start_strain").get<double>() > 0.0) {
    if (shearRate == 0.0) {
      throw Error("/stages/" + ctx.stage() + "/params/start_strain: upstream " + up.stage +
                  " has no Lees-Edwards shear rate; use start_time");
    }
    start = std::max(start, p.at("start_strain").get<double>() / std::abs(shearRate));
  }
  const double end = p.contains("end_time") ? p.at("end_time").get<double>() : std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k < files.size(); ++k) {
    if (times[k] >= start * (1.0 - 1e-12) && times[k] <= end * (1.0 + 1e-12)) selected.push_back(files[k]);
  }
  if (selected.empty()) {
    std::ostringstream msg;
    msg << "/stages/" << ctx.stage() << "/params: no frame of " << up.stage << " between " << start << " and " << end
        << " s (its " << files.size() << " frames span " << times.front() << " to " << times.back() << " s)";
    throw Error(msg.str());
  }
  spdlog::info("{}: averaging {} of {} frames of {} (from t = {} s)", ctx.stage(), selected.size(), files.size(),
               up.stage, core::humanNumber(start));

  // Per-frame whole-domain values.
  std::vector<double> time, solidFraction, temperature, pressure, shearStress, dissipation, coordination;
  double diameter = 0.0, density = 0.0;
  std::ostringstream perFrame;
  perFrame.precision(std::numeric_limits<double>::max_digits10);  // full precision: a CSV is read back by programs
  perFrame << "time,step,solid_fraction,granular_temperature,pressure,pressure_kinetic,pressure_contact,sigma_xy,"
              "dissipation_rate_dashpots,coordination,multi_contact_ratio\n";
  json structureRows = json::array();
  const bool forceStatistics = p.at("force_statistics");
  std::optional<core::io::FieldFrameWriter> fieldWriter;
  std::vector<std::string> speciesNames;
  if (p.contains("grid_cells")) {
    fieldWriter.emplace(ctx.outputDir(), core::io::ArtifactStamp{ctx.key()});
    for (const auto& sp : materials.species) speciesNames.push_back(sp.name);
  }
  extract::coarse::CoarseGrainer coarseGrainer;  // keeps its cell arrays from frame to frame
  core::averaging::FieldTimeAverage fieldAverage;
  const auto kernel = extract::coarse::CoarseGrainingKernel::fromName(p.at("kernel").get<std::string>(),
                                                                      p.at("kernel_width").get<double>());
  std::vector<core::data::ParticleFrame> kept;  // for the pooled statistics
  // Per kept frame, per MST pass p: the contacts passes 1..p found (Figs. 6.14-6.16).
  std::vector<std::vector<std::vector<std::size_t>>> mstContacts;
  auto surface = surfaceTracker(ctx, materials);
  for (const auto& file : selected) {
    if (ctx.stopRequested()) throw StageInterrupted{};
    auto frame = core::io::readParticleFrame(file);
    const auto a = extract::coarse::averageWholeDomain(frame);
    const double J = extract::coarse::dissipationRate(frame, a.volume);
    time.push_back(frame.time);
    solidFraction.push_back(a.solidFraction);
    temperature.push_back(a.granularTemperature);
    pressure.push_back(a.pressure);
    shearStress.push_back(-a.stress(0, 1));  // positive where the shear does work on the grains
    dissipation.push_back(J);
    coordination.push_back(a.coordinationNumber);
    perFrame << frame.time << ',' << frame.step << ',' << a.solidFraction << ',' << a.granularTemperature << ','
             << a.pressure << ',' << a.kineticStress.trace() / 3.0 << ',' << a.contactStress.trace() / 3.0 << ','
             << a.stress(0, 1) << ',' << J << ',' << a.coordinationNumber << ',' << a.multiContactRatio << '\n';
    if (diameter == 0.0) {
      // Mean diameter and material density of the grains (monodisperse closures; a mixture's
      // points carry the number-mean diameter).
      double sumD = 0.0, sumM = 0.0, sumV = 0.0;
      for (std::size_t i = 0; i < frame.size(); ++i) {
        sumD += 2.0 * frame.radius[i];
        sumM += frame.mass[i];
        sumV += 4.0 / 3.0 * M_PI * std::pow(frame.radius[i], 3);
      }
      diameter = sumD / static_cast<double>(frame.size());
      density = sumM / sumV;
    }
    if (p.at("structure").get<bool>()) {
      const auto networks = extract::structure::analyzeForceNetworks(frame);
      json n = {{"family", p.at("family")},
                {"kind", "force_networks"},
                {"pass", 0},
                {"frame_step", frame.step},
                {"time", frame.time},
                {"networks", networks.networks.size()},
                {"strong_particles", networks.strongParticles}};
      if (!networks.networks.empty()) {
        const auto& largest = networks.networks.front();
        n["largest_particles"] = largest.particleIds.size();
        n["largest_edges"] = largest.contacts;
        n["largest_coordination"] = largest.coordination;
        n["largest_extent"] = largest.extent.largestCentreDistance;
        // The reference gives the extent in d0, the small grains' diameter (52.2 d0, Section
        // 6.3.2): record it in units of the smallest diameter in the frame too.
        double smallest = std::numeric_limits<double>::infinity();
        for (const double r : frame.radius) smallest = std::min(smallest, 2.0 * r);
        n["extra_json"] = {{"smallest_diameter", smallest},
                           {"largest_extent_diameters", largest.extent.largestCentreDistance / smallest}};
      }
      structureRows.push_back(n);
      extract::structure::MultiPassMstOptions options;
      options.passes = static_cast<int>(p.at("mst_passes").get<std::int64_t>());
      options.elongationFactor = p.at("mst_elongation");
      const auto mst = extract::structure::runMultiPassMst(frame, options);
      if (forceStatistics) {
        auto& perPass = mstContacts.emplace_back();
        for (std::size_t pass = 1; pass <= mst.passes.size(); ++pass) {
          perPass.push_back(extract::structure::treeContactsUpToPass(mst, static_cast<int>(pass)));
        }
      }
      for (std::size_t pass = 0; pass < mst.passes.size(); ++pass) {
        const auto& mp = mst.passes[pass];
        structureRows.push_back({{"family", p.at("family")},
                                 {"kind", "mst"},
                                 {"pass", pass + 1},
                                 {"frame_step", frame.step},
                                 {"time", frame.time},
                                 {"largest_particles", mp.largestTree.particles},
                                 {"largest_edges", mp.largestTree.edges},
                                 {"other_trees", mp.otherTrees},
                                 {"other_edges", mp.otherTreeEdges}});
      }
    }
    if (fieldWriter) {
      std::array<int, 3> cells{};
      for (std::size_t axis = 0; axis < 3; ++axis) cells[axis] = static_cast<int>(p["grid_cells"][axis].get<double>());
      const auto grid = core::grid::CellGrid::overDomain(frame.domain, cells);
      const auto fields = toFieldFrame(frame, coarseGrainer(frame, grid, kernel), speciesNames);
      fieldWriter->write(fields);
      fieldAverage.add(fields);
    }
    if (surface) {
      try {
        surface->add(frame, a.coordinationNumber);
      } catch (const Error& e) {
        throw Error("/stages/" + ctx.stage() + "/params/surface_particles: " + e.what() + " (" + file.string() + ")");
      }
    }
    if (forceStatistics) kept.push_back(std::move(frame));
  }
  if (surface) {
    core::writeFileAtomically(ctx.outputDir() / "surface.csv", surface->csv());
    ctx.addArtifact("surface.csv", "csv");
  }
  core::writeFileAtomically(ctx.outputDir() / "frames.csv", perFrame.str());
  ctx.addArtifact("frames.csv", "csv");
  if (fieldWriter) {
    for (const auto& f : core::io::listFieldFrames(ctx.outputDir())) {
      ctx.addArtifact(f.lexically_relative(ctx.outputDir()).string(), "field_frame");
    }
    ctx.addArtifact("fields.xmf", "xdmf");
    // The time-averaged fields with their block-averaging errors, as a one-frame collection.
    core::io::FieldFrameWriter meanWriter(ctx.outputDir() / "mean", core::io::ArtifactStamp{ctx.key()});
    meanWriter.write(fieldAverage.mean());
    for (const auto& f : core::io::listFieldFrames(ctx.outputDir() / "mean")) {
      ctx.addArtifact(f.lexically_relative(ctx.outputDir()).string(), "field_frame");
    }
    ctx.addArtifact("mean/fields.xmf", "xdmf");
  }

  // The closure point: time averages with their block-averaging errors.
  const Averaged eps = averaged(solidFraction), T = averaged(temperature), P = averaged(pressure),
                 tau = averaged(shearStress), Z = averaged(coordination), dashpots = averaged(dissipation);
  // The dissipation rate J. The frames' dashpot forces give the power the contacts' dashpots
  // take out of the relative motion (DissipationRate.hpp). With friction that misses the Coulomb
  // sliding loss (the tangential spring cut back to the cap) and the tangential spring energy a
  // contact carries off when it opens: at friction 0.5 in the shear sweep the dashpots took only
  // 9-56 % of the shear work. In steady Lees-Edwards shear the work done by the shear,
  // -sigma_xy gammadot, is the whole dissipation (energy balance, VALIDATION.md), with a smaller
  // error too, so it is J there; the dashpot figure stays in extra_json, and for frictionless
  // grains their ratio is the check that the averaged window is a steady state. Without shear
  // the dashpots are all there is: exact for frictionless grains, a lower bound with friction.
  const bool fromShearWork = shearRate != 0.0;
  const Averaged J =
      fromShearWork ? Averaged{tau.mean * std::abs(shearRate), tau.error * std::abs(shearRate)} : dashpots;
  json row = {{"family", p.at("family")},
              {"solid_fraction", eps.mean},
              {"diameter", diameter},
              {"density", density},
              {"frames", selected.size()},
              {"granular_temperature", T.mean},
              {"granular_temperature_err", T.error},
              {"pressure", P.mean},
              {"pressure_err", P.error},
              {"dissipation_rate", J.mean},
              {"dissipation_rate_err", J.error},
              {"coordination", Z.mean},
              {"coordination_err", Z.error},
              {"extra_json",
               {{"solid_fraction_err", eps.error},
                {"start_time", start},
                {"upstream_stage", up.stage},
                {"dissipation_rate_source", fromShearWork ? "shear_work" : "contact_dashpots"},
                {"dissipation_rate_dashpots", dashpots.mean},
                {"dissipation_rate_dashpots_err", dashpots.error}}}};
  contactMaterial(materials, row);
  if (fromShearWork && row.contains("friction") && row["friction"].get<double>() == 0.0 && J.mean > 0.0) {
    // Frictionless grains lose energy in the dashpots only: shear work above them is heating.
    const double gap = std::abs(dashpots.mean - J.mean);
    if (gap > 3.0 * std::hypot(dashpots.error, J.error) + 0.05 * J.mean) {
      spdlog::warn(
          "{}: the shear work ({} W/m3) and the dashpot dissipation ({} W/m3) of these frictionless grains "
          "differ by {:.0f} %: the averaged frames are not a steady state (raise start_strain or run longer)",
          ctx.stage(), core::humanNumber(J.mean, 4), core::humanNumber(dashpots.mean, 4), 100.0 * gap / J.mean);
    }
  }
  // The closure forms (core/ClosureForms), each with its block-averaging error.
  const core::ClosureFormState state{density, diameter, T.mean, std::abs(shearRate)};
  auto addForm = [&](core::ClosureForm form, const Averaged& value) {
    const std::string name(core::closureFormInfo(form).name);
    row[name] = core::toClosureForm(form, value.mean, state);
    row[name + "_err"] = core::closureFormError(form, {value.mean, value.error}, {T.mean, T.error}, state);
  };
  if (T.mean > 0.0) {
    // The theta-scaled forms a continuum engine uses with its own temperature (DESIGN.md).
    addForm(core::ClosureForm::PTheta, P);
    addForm(core::ClosureForm::JTheta, J);
  }
  if (shearRate != 0.0) {
    const double g = std::abs(shearRate);
    row["shear_rate"] = g;
    row["shear_stress"] = tau.mean;
    row["shear_stress_err"] = tau.error;
    const Averaged mu{tau.mean / g, tau.error / g};
    row["viscosity"] = mu.mean;
    row["viscosity_err"] = mu.error;
    addForm(core::ClosureForm::PShear, P);
    addForm(core::ClosureForm::TauShear, tau);
    addForm(core::ClosureForm::TShear, T);
    if (T.mean > 0.0) addForm(core::ClosureForm::EtaTheta, mu);
  }
  if (forceStatistics) {
    addForceStatistics(ctx, kept, diameter, row);
    if (!mstContacts.empty()) addMstForceStatistics(ctx, kept, mstContacts, diameter);
  }
  for (auto& s : structureRows) ctx.addRecord("structure_statistics", std::move(s));
  json summary = json::object();
  if (p.at("closure_point").get<bool>()) {
    ctx.addRecord("closure_points", row);
    std::ostringstream point;
    point.precision(std::numeric_limits<double>::max_digits10);
    point << "quantity,value\n";
    for (const auto& [k, v] : row.items()) {
      if (v.is_number()) point << k << ',' << v.get<double>() << '\n';
    }
    core::writeFileAtomically(ctx.outputDir() / "closure_point.csv", point.str());
    ctx.addArtifact("closure_point.csv", "csv");
    summary = row;
    summary.erase("extra_json");
  }
  if (surface) summary.update(surface->summary());
  ctx.setSummary(summary);
}

}  // namespace grainbridge::workflows::stages
