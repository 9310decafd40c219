#include "workflows/stages/ExtractStage.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <sstream>

#include "core/Error.hpp"
#include "core/Files.hpp"
#include "core/Log.hpp"
#include "core/io/ParticleFrameReader.hpp"
#include "core/text/NumberText.hpp"
#include "extract/coarse/CoarseGrainingKernel.hpp"
#include "extract/coarse/DomainAverages.hpp"
#include "extract/observe/ClosurePointObserver.hpp"
#include "extract/observe/FieldObserver.hpp"
#include "extract/observe/ForceStatisticsObserver.hpp"
#include "extract/observe/OutputSink.hpp"
#include "extract/observe/SpeciesClosurePoints.hpp"
#include "extract/observe/StructureObserver.hpp"
#include "extract/observe/SurfaceObserver.hpp"

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
               .doc("record the time-averaged closure point (and, for a mixture in a box periodic along every "
                    "axis, one per species and species pair); false for runs that have no steady state to "
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

// The extract stage's outputs go through its context: extract/observe never sees workflows/.
class StageSink final : public extract::observe::OutputSink {
 public:
  explicit StageSink(StageContext& ctx) : ctx_(ctx) {}
  [[nodiscard]] const std::filesystem::path& outputDir() const override { return ctx_.outputDir(); }
  [[nodiscard]] const std::string& label() const override { return ctx_.stage(); }
  void writeFile(const std::string& relativePath, const std::string& content, const std::string& kind) override {
    core::writeFileAtomically(ctx_.outputDir() / relativePath, content);
    ctx_.addArtifact(relativePath, kind);
  }
  void addArtifact(const std::string& relativePath, const std::string& kind) override {
    ctx_.addArtifact(relativePath, kind);
  }
  void addRecord(const std::string& table, json row) override { ctx_.addRecord(table, std::move(row)); }

 private:
  StageContext& ctx_;
};

}  // namespace

void ExtractStage::run(StageContext& ctx) const {
  const json& p = ctx.params();
  if (ctx.inputs().size() != 1) {
    throw Error("extract: needs exactly one upstream instance with particle frames, got " +
                std::to_string(ctx.inputs().size()));
  }
  const UpstreamInstance& up = ctx.inputs().front();
  const auto files = core::io::listParticleFrames(up.dir());
  if (files.empty()) {
    throw Error("extract: upstream " + up.stage() + " (" + up.dir().string() + ") has no particle frames");
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
      throw Error("/stages/" + ctx.stage() + "/params/start_strain: upstream " + up.stage() +
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
    msg << "/stages/" << ctx.stage() << "/params: no frame of " << up.stage() << " between " << start << " and " << end
        << " s (its " << files.size() << " frames span " << times.front() << " to " << times.back() << " s)";
    throw Error(msg.str());
  }
  spdlog::info("{}: averaging {} of {} frames of {} (from t = {} s)", ctx.stage(), selected.size(), files.size(),
               up.stage(), core::humanNumber(start));

  // The analyses this stage's parameters ask for, each an observer in extract/observe, fed every
  // averaged frame with its whole-domain averages (computed once here). Finished in this order:
  // the closure point first (force statistics add to it), then what adds records and files.
  namespace ob = extract::observe;
  ob::ClosurePointObserver closurePoint({p.at("family"), shearRate, materials, start, up.stage()});
  std::vector<ob::FrameObserver*> observers{&closurePoint};
  // A homogeneous mixture's frames (a box periodic along every axis, without walls: the closure
  // boxes): its species' and species pairs' points beside the mixture's (issue 60). A bed under
  // gravity (the Brazil-nut pack) has no homogeneous state for them to describe.
  std::optional<ob::SpeciesClosurePoints> speciesPoints;
  const bool mixture = std::any_of(firstFrame.species.begin(), firstFrame.species.end(),
                                   [&](std::int32_t s) { return s != firstFrame.species.front(); });
  const auto& box = firstFrame.domain;
  const bool homogeneous = box.periodic[0] && box.periodic[1] && box.periodic[2] && box.walls.empty();
  if (p.at("closure_point").get<bool>() && mixture && homogeneous) {
    speciesPoints.emplace(ob::ClosurePointOptions{p.at("family"), shearRate, materials, start, up.stage()});
    observers.push_back(&*speciesPoints);
  }
  std::optional<ob::FieldObserver> fields;
  if (p.contains("grid_cells")) {
    std::array<int, 3> cells{};
    for (std::size_t axis = 0; axis < 3; ++axis) cells[axis] = static_cast<int>(p["grid_cells"][axis].get<double>());
    std::vector<std::string> speciesNames;
    for (const auto& sp : materials.species) speciesNames.push_back(sp.name);
    fields.emplace(ob::FieldOptions{cells,
                                    extract::coarse::CoarseGrainingKernel::fromName(p.at("kernel").get<std::string>(),
                                                                                    p.at("kernel_width").get<double>()),
                                    speciesNames, ctx.outputDir(), core::io::ArtifactStamp{ctx.key()}});
    observers.push_back(&*fields);
  }
  const bool forceStatistics = p.at("force_statistics");
  std::optional<ob::StructureObserver> structure;
  if (p.at("structure").get<bool>()) {
    structure.emplace(ob::StructureOptions{p.at("family"), static_cast<int>(p.at("mst_passes").get<std::int64_t>()),
                                           p.at("mst_elongation").get<double>(), forceStatistics});
    observers.push_back(&*structure);
  }
  std::optional<ob::SurfaceObserver> surface;
  if (!p.at("surface_particles").empty()) {
    ob::SurfaceOptions options;
    // Integers >= 0 by declaration; whether the frames hold them is checked frame by frame.
    for (const auto& id : p["surface_particles"]) options.ids.push_back(id.get<std::int64_t>());
    options.up = materials.up();  // heights are measured against gravity, +z without it
    options.tolerance = p.at("surface_tolerance");
    options.minCoordination = p.at("surface_min_coordination");
    surface.emplace(std::move(options));
    observers.push_back(&*surface);
  }
  std::optional<ob::ForceStatisticsObserver> forces;
  if (forceStatistics) {
    forces.emplace(ob::ForceStatisticsOptions{p.at("family"), p.at("correlation_range").get<double>()}, closurePoint,
                   structure ? &*structure : nullptr);
    observers.push_back(&*forces);  // last: it keeps (moves) the frames
  }

  for (const auto& file : selected) {
    if (ctx.stopRequested()) throw StageInterrupted{};
    auto frame = core::io::readParticleFrame(file);
    const auto domain = extract::coarse::averageWholeDomain(frame);
    ob::ObservedFrame observed{frame, domain};
    for (auto* observer : observers) {
      try {
        observer->observe(observed);
      } catch (const Error& e) {
        if (observer->parameter().empty()) throw;
        throw Error("/stages/" + ctx.stage() + "/params/" + observer->parameter() + ": " + e.what() + " (" +
                    file.string() + ")");
      }
    }
  }

  StageSink sink(ctx);
  ob::ExtractResult result;
  closurePoint.finish(sink, result);
  if (fields) fields->finish(sink, result);
  if (forces) forces->finish(sink, result);
  if (structure) structure->finish(sink, result);
  if (surface) surface->finish(sink, result);
  json summary = json::object();
  if (p.at("closure_point").get<bool>()) {
    ctx.addRecord("closure_points", result.point);
    sink.writeFile("closure_point.csv", ob::closurePointCsv(result.point), "csv");
    summary = result.point;
    // The solid fraction's error stays a summary value: a pressure-controlled box's fraction is
    // measured (tabulate's phi(I) fit weighs it), a constant-volume box's is exact (0).
    if (result.point.contains("extra_json") && result.point["extra_json"].contains("solid_fraction_err")) {
      summary["solid_fraction_err"] = result.point["extra_json"]["solid_fraction_err"];
    }
    summary.erase("extra_json");
  }
  if (speciesPoints) speciesPoints->finish(sink, result);  // after the mixture's row: the database lists it first
  summary.update(result.summary);
  ctx.setSummary(summary);
}

}  // namespace grainbridge::workflows::stages
