#include "workflows/stages/ParticleGasStage.hpp"

#include <cmath>
#include <random>

#include "core/Error.hpp"
#include "core/FailPoint.hpp"
#include "core/Progress.hpp"
#include "core/data/ParticleFrame.hpp"
#include "core/io/ParticleFrameWriter.hpp"
#include "engines/dem/Insertion.hpp"
#include "engines/dem/MaxwellianVelocities.hpp"

namespace grainbridge::workflows::stages {

using core::units::Dimension;
using params::ParamSpec;

ParticleGasStage::ParticleGasStage() {
  schema_.add(ParamSpec::integer("n_particles").required().min(1).max(5e7).doc("number of spheres"))
      .add(ParamSpec::quantity("diameter", Dimension::lengthDim())
               .defaultValue("1 mm")
               .positive()
               .doc("sphere diameter d"))
      .add(ParamSpec::quantity("density", Dimension::density())
               .defaultValue("2500 kg/m3")
               .positive()
               .doc("material density rho_p"))
      // pi/sqrt(18) is the densest packing of equal spheres; random insertion jams far below it
      // (about 0.38) and then fails with a message saying so.
      .add(ParamSpec::number("solid_fraction")
               .required()
               .min(0.0, false)
               .max(M_PI / std::sqrt(18.0))
               .doc("solid volume fraction of the box"))
      .add(ParamSpec::quantity("granular_temperature", Dimension::granularTemperature())
               .defaultValue("1e-4 m2/s2")
               .min(0.0)
               .doc("granular temperature T = <C^2>/3 (Eq. 3.38)"))
      .add(ParamSpec::integer("seed").defaultValue(1).min(0).doc("random seed (positions and velocities)"))
      .add(ParamSpec::integer("max_attempts")
               .defaultValue(100000)
               .min(1)
               .doc("insertion attempts per particle before giving up"))
      .add(ParamSpec::boolean("progress")
               .defaultValue(true)
               .doesNotAffectResults()
               .doc("report progress while inserting"));
}

void ParticleGasStage::run(StageContext& ctx) const {
  const auto& p = ctx.params();
  const auto n = p.at("n_particles").get<std::int64_t>();
  const double d = p.at("diameter");
  const double rho = p.at("density");
  const double phi = p.at("solid_fraction");
  const double temperature = p.at("granular_temperature");
  const auto maxAttempts = p.at("max_attempts").get<std::int64_t>();
  const double volume = M_PI * d * d * d / 6.0;
  const double box = std::cbrt(static_cast<double>(n) * volume / phi);

  std::mt19937_64 rng(p.at("seed").get<std::uint64_t>());

  core::data::ParticleFrame frame;
  frame.time = 0.0;
  frame.step = 0;
  frame.units = "SI";
  frame.domain.lo = Vec3::Zero();
  frame.domain.hi = Vec3::Constant(box);
  frame.domain.periodic = {true, true, true};

  dem::InsertionRequest request;
  request.lo = frame.domain.lo;
  request.hi = frame.domain.hi;
  request.periodic = {true, true, true};
  request.radii.assign(static_cast<std::size_t>(n), 0.5 * d);
  request.maxAttempts = maxAttempts;
  std::optional<core::Progress> progress;
  if (p.at("progress").get<bool>()) progress.emplace(ctx.stage() + ": inserting", static_cast<double>(n), "particles");
  request.progress = [&](std::size_t placed) {
    if (ctx.stopRequested()) throw StageInterrupted{};
    if (progress) progress->update(static_cast<double>(placed));
  };
  try {
    frame.position = dem::insertRandomly(request, rng);
  } catch (const Error& e) {
    throw Error(std::string("particle_gas: ") + e.what() + " (solid_fraction is " + std::to_string(phi) +
                "; lower it, or raise max_attempts)");
  }
  if (progress) progress->finish();
  core::failPoint("particle_gas.after_insert");

  // Maxwellian velocities with exactly zero momentum and granular temperature T (Eq. 3.38).
  frame.velocity = dem::maxwellianVelocities(static_cast<std::size_t>(n), temperature, rng);

  frame.id.resize(static_cast<std::size_t>(n));
  for (std::int64_t i = 0; i < n; ++i) frame.id[static_cast<std::size_t>(i)] = i;
  frame.species.assign(static_cast<std::size_t>(n), 0);
  frame.radius.assign(static_cast<std::size_t>(n), 0.5 * d);
  frame.mass.assign(static_cast<std::size_t>(n), rho * volume);
  frame.angularVelocity.assign(static_cast<std::size_t>(n), Vec3::Zero());
  frame.materials.species = {{"grain", d, rho}};  // no contacts: no pair coefficients

  core::io::ParticleFrameWriter writer(ctx.outputDir(), core::io::ArtifactStamp{ctx.key()});
  const auto framePath = writer.write(frame);
  ctx.addArtifact(framePath.lexically_relative(ctx.outputDir()).string(), "particle_frame");
  ctx.addArtifact("particles.xmf", "xdmf");

  double measuredT = 0.0;
  for (const auto& v : frame.velocity) measuredT += v.squaredNorm();
  measuredT /= 3.0 * static_cast<double>(n);
  ctx.setSummary({{"n_particles", n},
                  {"box_length", box},
                  {"solid_fraction", static_cast<double>(n) * volume / (box * box * box)},
                  {"granular_temperature", measuredT},
                  {"number_density", static_cast<double>(n) / (box * box * box)}});
}

}  // namespace grainbridge::workflows::stages
