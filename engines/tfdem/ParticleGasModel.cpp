#include "engines/tfdem/ParticleGasModel.hpp"

#include "core/Error.hpp"
#include "engines/fluid/FieldSampling.hpp"

namespace grainbridge::tfdem {

ParticleGasModel::ParticleGasModel(Gas gas, closures::GasSolidsDrag law, GasReaction reaction,
                                   const ParticleDeposit& deposit, const std::vector<Vec3>* summedDrag)
    : gas_(gas), law_(std::move(law)), reaction_(reaction), deposit_(&deposit), summedDrag_(summedDrag) {
  if (reaction_ == GasReaction::Summed && summedDrag_ == nullptr)
    throw Error("tfdem: the summed gas reaction needs the particles' drag per cell");
}

namespace {

// Eq. 7.34's beta in cell c for the law chosen by the caller (once per sweep in evaluate()).
template <class Law>
double cellBetaWith(const Law& law, const Gas& gas, const ParticleDeposit& deposit, const fluid::FlowState& state,
                    std::size_t c) {
  const double epsS = deposit.fraction[c];
  if (!(epsS > 0.0)) return 0.0;
  closures::DragState s;
  s.voidFraction = state.phases[0].fraction[c];
  s.solidFraction = epsS;
  s.diameter = deposit.diameter[c];
  s.gasDensity = gas.density;
  s.gasViscosity = gas.viscosity;
  s.slip = (fluid::cellVelocity(state.phases[0], c) - deposit.velocity[c]).norm();
  return law.evaluate(s).beta;  // Eq. 7.34
}

}  // namespace

double ParticleGasModel::cellBeta(const fluid::FlowState& state, std::size_t c) const {
  return law_.visit([&](const auto& law) { return cellBetaWith(law, gas_, *deposit_, state, c); });
}

std::vector<double> ParticleGasModel::cellBetas(const fluid::FlowState& state) const {
  const fluid::StaggeredGrid& grid = state.grid();
  std::vector<double> beta(grid.paddedCount(), 0.0);
  law_.visit([&](const auto& law) {
    for (std::size_t c = 0; c < grid.paddedCount(); ++c) {
      if (grid.interior(c)) beta[c] = cellBetaWith(law, gas_, *deposit_, state, c);
    }
  });
  return beta;
}

void ParticleGasModel::evaluate(const fluid::FlowState& state, fluid::FlowProperties& p) const {
  law_.visit([&](const auto& law) { evaluateWith(law, state, p); });
}

template <class Law>
void ParticleGasModel::evaluateWith(const Law& law, const fluid::FlowState& state, fluid::FlowProperties& p) const {
  const fluid::StaggeredGrid& grid = state.grid();
  fluid::PhaseProperties& g = p.phases[0];
  const bool summed = reaction_ == GasReaction::Summed;
  if (summed) g.momentumSource.assign(3, fluid::CellField(grid, 0.0));
  for (std::size_t c = 0; c < grid.paddedCount(); ++c) {
    const double epsG = state.phases[0].fraction[c];
    g.density[c] = gas_.density;
    g.shearViscosity[c] = epsG * gas_.viscosity;  // Eq. 3.20
    g.bulkViscosity[c] = -2.0 / 3.0 * epsG * gas_.viscosity;
    p.phases[1].density[c] = 0.0;  // unused: the particles' momentum is the DEM's
    if (!grid.interior(c)) continue;
    if (summed) {
      for (int a = 0; a < 3; ++a) g.momentumSource[static_cast<std::size_t>(a)][c] = -(*summedDrag_)[c][a];
    } else {
      p.dragCoefficient[1][c] = cellBetaWith(law, gas_, *deposit_, state, c);
    }
  }
}

}  // namespace grainbridge::tfdem
