#include "engines/tfdem/ParticleForces.hpp"

#include "engines/fluid/FieldSampling.hpp"

namespace grainbridge::tfdem {

std::vector<Vec3> cellDragPerSolidsVolume(const fluid::FlowState& state, const ParticleDeposit& deposit,
                                          const std::vector<double>& cellBeta) {
  const fluid::StaggeredGrid& grid = state.grid();
  std::vector<Vec3> drag(grid.paddedCount(), Vec3::Zero());
  for (std::size_t c = 0; c < grid.paddedCount(); ++c) {
    if (!grid.interior(c) || !(deposit.fraction[c] > 0.0)) continue;
    drag[c] = cellBeta[c] * (fluid::cellVelocity(state.phases[0], c) - deposit.velocity[c]) / deposit.fraction[c];
  }
  return drag;
}

namespace {

// setParticleForces for the law chosen once per call: Eq. 7.29 is evaluated per particle.
template <class Law>
void setParticleForcesWith(const Law& law, dem::Particles& p, const fluid::FlowState& state,
                           const ParticleDeposit& deposit, const std::vector<Vec3>& cellDrag,
                           const ParticleForceSettings& settings) {
  const fluid::StaggeredGrid& grid = state.grid();
  const fluid::PhaseFields& gas = state.phases[0];
  // Per cell with particles, once: the pressure gradient and the gas velocity at the centre.
  std::vector<Vec3> gradient(grid.paddedCount(), Vec3::Zero()), gasVelocity(grid.paddedCount(), Vec3::Zero());
  for (std::size_t c = 0; c < grid.paddedCount(); ++c) {
    if (!grid.interior(c) || !(deposit.fraction[c] > 0.0)) continue;
    gradient[c] = fluid::pressureGradient(state.pressure, c);
    gasVelocity[c] = fluid::cellVelocity(gas, c);
  }
  for (std::size_t i = 0; i < p.nOwned; ++i) {
    const double vp = particleVolume(p.radius[i]);
    Vec3 grad = Vec3::Zero(), drag = Vec3::Zero(), u = Vec3::Zero();
    double epsG = 0.0, epsS = 0.0, share = 0.0;
    for (std::size_t k = deposit.offset[i]; k < deposit.offset[i + 1]; ++k) {
      const auto& [c, w] = deposit.shares[k];
      grad += w * gradient[c];
      if (settings.transfer == DragTransfer::CellAverage) drag += w * cellDrag[c];
      u += w * gasVelocity[c];
      epsG += w * gas.fraction[c];
      epsS += w * deposit.fraction[c];
      share += w;
    }
    p.couplingPressure[i] = -vp * grad;
    p.couplingA[i] = Vec3::Zero();
    p.couplingB[i] = 0.0;
    p.couplingU[i] = Vec3::Zero();
    if (!(share > 0.0)) continue;  // outside the grid: no gas
    if (settings.transfer == DragTransfer::CellAverage) {
      p.couplingA[i] = vp * drag;  // Eq. 7.33 shared by volume
      continue;
    }
    // Eq. 7.29: the particle's own slip, its cells' fractions (normalised over the part inside).
    epsG /= share;
    epsS /= share;
    if (settings.gasVelocity == GasVelocity::Interpolated) {
      u = fluid::velocityAt(gas, p.x[i]);
    } else {
      u /= share;
    }
    closures::DragState s;
    s.voidFraction = epsG;
    s.solidFraction = epsS;
    s.diameter = 2.0 * p.radius[i];
    s.gasDensity = settings.gas.density;
    s.gasViscosity = settings.gas.viscosity;
    s.slip = (u - p.v[i]).norm();
    p.couplingB[i] = epsG * law.evaluate(s).particle;  // eps_g f_d of Eq. 7.28
    p.couplingU[i] = u;
  }
}

}  // namespace

void setParticleForces(dem::Particles& p, const fluid::FlowState& state, const ParticleDeposit& deposit,
                       const std::vector<Vec3>& cellDrag, const closures::GasSolidsDrag& law,
                       const ParticleForceSettings& settings) {
  law.visit([&](const auto& l) { setParticleForcesWith(l, p, state, deposit, cellDrag, settings); });
}

}  // namespace grainbridge::tfdem
