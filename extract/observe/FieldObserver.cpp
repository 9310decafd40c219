#include "extract/observe/FieldObserver.hpp"

#include "core/grid/CellGrid.hpp"
#include "core/io/FieldFrameReader.hpp"
#include "extract/observe/MeanForceRatio.hpp"

namespace grainbridge::extract::observe {

FieldObserver::FieldObserver(FieldOptions options)
    : options_(std::move(options)), writer_(options_.outputDir, options_.stamp) {}

void FieldObserver::observe(ObservedFrame& observed) {
  const auto& frame = observed.frame;
  const auto grid = core::grid::CellGrid::overDomain(frame.domain, options_.cells);
  const auto fields = toFieldFrame(frame, coarseGrainer_(frame, grid, options_.kernel), options_.speciesNames);
  writer_.write(fields);
  average_.add(fields);
}

void FieldObserver::finish(OutputSink& out, ExtractResult& /*result*/) {
  const auto& dir = options_.outputDir;
  for (const auto& f : core::io::listFieldFrames(dir))
    out.addArtifact(f.lexically_relative(dir).string(), "field_frame");
  out.addArtifact("fields.xmf", "xdmf");
  // The time-averaged fields with their block-averaging errors, as a one-frame collection.
  core::io::FieldFrameWriter meanWriter(dir / "mean", options_.stamp);
  core::data::FieldFrame mean = average_.mean();
  useRatioOfMeans(mean);  // Figs. 7.7b and 7.12b: the ratio of the mean forces, not the mean ratio
  meanWriter.write(mean);
  for (const auto& f : core::io::listFieldFrames(dir / "mean")) {
    out.addArtifact(f.lexically_relative(dir).string(), "mean_field_frame");
  }
  out.addArtifact("mean/fields.xmf", "xdmf");
}

core::data::FieldFrame toFieldFrame(const core::data::ParticleFrame& frame, const coarse::CoarseFields& c,
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

}  // namespace grainbridge::extract::observe
