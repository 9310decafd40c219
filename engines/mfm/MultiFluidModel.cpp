#include "engines/mfm/MultiFluidModel.hpp"

#include <algorithm>
#include <cmath>

#include "engines/fluid/StrainRate.hpp"

namespace grainbridge::mfm {

double algebraicGranularTemperature(const closures::SyamlalCoefficients& k, double eps, double traceD,
                                    double doubleDotD) {
  const double a = k.k4 * eps;
  const double b = k.k1 * eps * traceD;
  const double c = -(k.k2 * traceD * traceD + 2.0 * k.k3 * doubleDotD);
  if (!(a > 0.0) || !(c < 0.0)) return 0.0;  // no solids, elastic grains or no shear: no production
  const double root = (-b + std::sqrt(b * b - 4.0 * a * c)) / (2.0 * a);
  return root * root;
}

void MultiFluidModel::evaluate(const fluid::FlowState& state, fluid::FlowProperties& p) const {
  const fluid::StaggeredGrid& grid = state.grid();
  const fluid::PhaseFields& gas = state.phases[0];
  const auto& plastic = params_.plastic.params;
  for (int k = 0; k < grid.cells(2); ++k) {
    for (int j = 0; j < grid.cells(1); ++j) {
      for (int i = 0; i < grid.cells(0); ++i) {
        const std::size_t c = grid.index(i, j, k);
        const double epsG = std::clamp(gas.fraction[c], 1e-12, 1.0);  // as solidsState sees it
        const double rhoG = params_.gas.densityAt(state.pressure[c]);
        p.phases[0].density[c] = rhoG;
        p.phases[0].compressibility[c] = params_.gas.compressibility();
        p.phases[0].shearViscosity[c] = epsG * params_.gas.viscosity;
        p.phases[0].bulkViscosity[c] = -2.0 / 3.0 * epsG * params_.gas.viscosity;
        for (std::size_t m = 1; m < state.phases.size(); ++m) {
          const SolidsPhase& solids = params_.solids[m - 1];
          const fluid::PhaseFields& phase = state.phases[m];
          fluid::PhaseProperties& out = p.phases[m];
          out.density[c] = solids.density;
          const SolidsState now = solidsState(state, m, c);
          const double eps = now.solidFraction, theta = now.theta;
          const closures::SyamlalCoefficients& kc = now.coefficients;
          const closures::PlasticRegime::Result pl = params_.plastic.evaluate(epsG, eps, now.strain.deviatorInvariant());
          out.solidsPressure[c] = kc.k1 * eps * eps * theta + pl.pressure;  // Eqs. 3.21 + 3.26
          out.shearViscosity[c] = kc.k3 * eps * std::sqrt(theta) + pl.viscosity;
          out.bulkViscosity[c] = kc.k2 * eps * std::sqrt(theta);
          double slope = 2.0 * kc.k1 * eps * theta;
          if (pl.plastic) {
            slope += pl.pStar + eps * plastic.exponent * plastic.coefficient *
                                    std::pow(plastic.criticalVoidFraction - epsG, plastic.exponent - 1.0);
          }
          out.solidsPressureSlope[c] = slope;

          // Drag at the cell-centred slip.
          double slip2 = 0.0;
          for (int a = 0; a < grid.dimensions(); ++a) {
            const auto& vg = gas.velocity[static_cast<std::size_t>(a)];
            const auto& vs = phase.velocity[static_cast<std::size_t>(a)];
            const std::size_t low = grid.neighbour(c, a, -1);
            const double s = 0.5 * (vg[c] + vg[low]) - 0.5 * (vs[c] + vs[low]);
            slip2 += s * s;
          }
          const closures::DragState ds{epsG, eps, solids.diameter, rhoG, params_.gas.viscosity, std::sqrt(slip2)};
          p.dragCoefficient[m][c] = params_.drag.evaluate(ds).beta;
        }
      }
    }
  }
}

MultiFluidModel::SolidsState MultiFluidModel::solidsState(const fluid::FlowState& state, std::size_t m,
                                                          std::size_t c) const {
  const SolidsPhase& solids = params_.solids[m - 1];
  // The closures want fractions in range; round-off may leave eps_s a hair below zero, which the
  // state keeps (no clipping) and the closures see as zero.
  const double epsG = std::clamp(state.phases[0].fraction[c], 1e-12, 1.0);
  const double eps = std::clamp(state.phases[m].fraction[c], 0.0, 1.0 - epsG);
  const closures::KineticState ks{eps, 0.0, solids.diameter, solids.density, solids.restitution, 0.0};
  const closures::SyamlalCoefficients kc = params_.kinetic.coefficients(ks);
  const fluid::StrainRate D = fluid::strainRate(state.phases[m], c);
  return {epsG, eps, kc, D, algebraicGranularTemperature(kc, eps, D.trace(), D.doubleDot())};
}

double MultiFluidModel::granularTemperature(const fluid::FlowState& state, std::size_t m, std::size_t c) const {
  return solidsState(state, m, c).theta;
}

}  // namespace grainbridge::mfm
