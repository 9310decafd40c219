#include "engines/mfm/MultiFluidModel.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <span>
#include <vector>

#include "core/Error.hpp"
#include "engines/closures/EffectiveRestitution.hpp"
#include "engines/closures/GranularEnergyGasTerms.hpp"
#include "engines/closures/RadialDistribution.hpp"
#include "engines/fluid/FieldSampling.hpp"
#include "engines/fluid/MassFlux.hpp"
#include "engines/fluid/StrainRate.hpp"
#include "engines/mfm/GranularEnergy.hpp"

namespace grainbridge::mfm {

double algebraicGranularTemperature(const closures::SyamlalCoefficients& k, double eps, double traceD,
                                    double doubleDotD) {
  constexpr double kNoSolids = 1e-15;  // MFiX's SMALL_NUMBER: theta_m = 0 at or below it
  if (!(eps > kNoSolids)) return 0.0;
  const double a = k.k4 * eps;
  const double b = k.k1 * eps * traceD;
  const double c = -(k.k2 * traceD * traceD + 2.0 * k.k3 * doubleDotD);
  if (!(a > 0.0) || !(c < 0.0)) return 0.0;  // no solids, elastic grains or no shear: no production
  const double root = (-b + std::sqrt(b * b - 4.0 * a * c)) / (2.0 * a);
  return root * root;
}

namespace {

// The fractions the closures see: round-off may leave eps_s a hair below zero, which the state
// keeps (no clipping) and the closures see as zero.
double closureVoidFraction(const fluid::FlowState& state, std::size_t c) {
  return std::clamp(state.phases[0].fraction[c], 1e-12, 1.0);
}
// An iterate of a mixture may overfill a cell (the step is then retried); its phases are scaled
// to the room the clamped void fraction leaves, so that the closures (Lebowitz's g0 needs
// sum eps < 1) see the cell as packed, as the one phase's clamp does.
double closureSolidFraction(const fluid::FlowState& state, std::size_t m, std::size_t c) {
  const double room = 1.0 - closureVoidFraction(state, c);
  if (state.phases.size() == 2) return std::clamp(state.phases[m].fraction[c], 0.0, room);
  double total = 0.0;
  for (std::size_t l = 1; l < state.phases.size(); ++l) total += std::clamp(state.phases[l].fraction[c], 0.0, 1.0);
  const double eps = std::clamp(state.phases[m].fraction[c], 0.0, 1.0);
  return total > room ? eps * (room / total) : eps;
}

// Every solids phase's closure fraction in cell c, [l - 1] for phase l. The kinetic theory asks
// for them several times per cell and iteration: up to kInline phases they live on the stack (a
// vector per call cost 5 % of the binary bed's run, bench/README.md).
class CellSolidFractions {
 public:
  CellSolidFractions(const fluid::FlowState& state, std::size_t c) : CellSolidFractions(state.phases.size() - 1) {
    for (std::size_t l = 1; l <= values_.size(); ++l) values_[l - 1] = closureSolidFraction(state, l, c);
  }
  // `from` with eps of [own] raised by `shift` (the pressure slope's neighbouring state).
  CellSolidFractions(const CellSolidFractions& from, std::size_t own, double shift) : CellSolidFractions(from.size()) {
    std::copy(from.values_.begin(), from.values_.end(), values_.begin());
    values_[own] += shift;
  }
  CellSolidFractions(const CellSolidFractions&) = delete;  // values_ points into this object
  CellSolidFractions& operator=(const CellSolidFractions&) = delete;
  [[nodiscard]] std::size_t size() const { return values_.size(); }
  double& operator[](std::size_t k) { return values_[k]; }
  double operator[](std::size_t k) const { return values_[k]; }
  [[nodiscard]] std::span<const double> values() const { return values_; }

 private:
  static constexpr std::size_t kInline = 8;
  explicit CellSolidFractions(std::size_t phases)
      : heap_(phases > kInline ? phases : 0), values_(heap_.empty() ? inline_.data() : heap_.data(), phases) {}
  std::array<double, kInline> inline_{};
  std::vector<double> heap_;
  std::span<double> values_;
};

// Phase m's share of the plastic viscosity (Eq. 3.27). Schaeffer's mu^p is written with P*, not
// eps_sm P* (PlasticRegime.hpp), so each phase of a mixture takes eps_sm / eps_s of it, as MFIX
// does (calc_mu_s.f: EP_s(M)/SUM_EPS_CP), and identical phases add up to one; one phase takes it all,
// and so does each phase when the plastic pressure is per phase (its own P*).
double plasticViscosityShare(const CellSolidFractions& fractions, std::size_t m, PlasticPressure form) {
  if (fractions.size() == 1 || form == PlasticPressure::PerPhase) return 1.0;
  double total = 0.0;
  for (double eps : fractions.values()) total += eps;
  return total > 0.0 ? fractions[m - 1] / total : 0.0;
}

// d(eps P*)/d eps of Eq. 3.26 at void fraction voidFraction, P* = A (eps_g* - eps_g)^n: the
// fraction correction's plastic slope, zero outside the plastic regime.
double plasticPressureSlope(const closures::PlasticRegime::Params& plastic, const closures::PlasticRegime::Result& pl,
                            double eps, double voidFraction, double epsGStar) {
  if (!pl.plastic) return 0.0;
  return pl.pStar + eps * plastic.exponent * plastic.coefficient * std::pow(epsGStar - voidFraction, plastic.exponent - 1.0);
}

// |v_g - v_s| at the cell centre, component by component as the drag has always read it.
double slipSpeed(const fluid::PhaseFields& gas, const fluid::PhaseFields& solids, std::size_t c) {
  const fluid::StaggeredGrid& grid = gas.fraction.grid();
  double slip2 = 0.0;
  for (int a = 0; a < grid.dimensions(); ++a) {
    const auto& vg = gas.velocity[static_cast<std::size_t>(a)];
    const auto& vs = solids.velocity[static_cast<std::size_t>(a)];
    const std::size_t low = grid.neighbour(c, a, -1);
    const double s = 0.5 * (vg[c] + vg[low]) - 0.5 * (vs[c] + vs[low]);
    slip2 += s * s;
  }
  return std::sqrt(slip2);
}

}  // namespace

class MultiFluidModel::CellMixture {
 public:
  CellMixture(const fluid::FlowState& state, std::size_t c, const std::vector<double>& diameters, bool lebowitz)
      : fractions(state, c) {
    if (lebowitz) mixture.emplace(fractions.values(), diameters);
  }
  const CellSolidFractions fractions;
  std::optional<closures::LebowitzMixture> mixture;  // under Lebowitz's g0
};

namespace {

std::vector<double> maxPackingsOf(const std::vector<SolidsPhase>& solids) {
  std::vector<double> packings;
  for (const SolidsPhase& s : solids) packings.push_back(s.maxPacking);
  return packings;
}

std::vector<double> diametersOf(const std::vector<SolidsPhase>& solids) {
  std::vector<double> diameters;
  for (const SolidsPhase& s : solids) diameters.push_back(s.diameter);
  return diameters;
}

}  // namespace

closures::MixturePacking mixturePackingOf(const MultiFluidParams& params) {
  return {params.packingLimit, params.plastic.params.criticalVoidFraction, diametersOf(params.solids),
          maxPackingsOf(params.solids)};
}

MultiFluidModel::MultiFluidModel(MultiFluidParams params)
    : params_(std::move(params)),
      dissipationScale_(params_.solids.size() + 1, 1.0),
      diameters_(diametersOf(params_.solids)),
      wallEffective_(params_.solids.size() + 1),
      packing_(mixturePackingOf(params_)) {
  if (params_.granularEnergy == GranularEnergyForm::Algebraic && (params_.rotation || params_.wall)) {
    throw Error(
        "multi-fluid model: the rotation model and Johnson-Jackson walls need the granular-energy equation "
        "(granular_energy pde)");
  }
  for (std::size_t k = 0; k < params_.solidsPairs.size(); ++k) {
    const SolidsPair& pair = params_.solidsPairs[k];
    if (!(pair.l >= 1 && pair.l < pair.m && pair.m <= params_.solids.size()))
      throw Error("multi-fluid model: solids pair " + std::to_string(k) + " (" + std::to_string(pair.l) + ", " +
                  std::to_string(pair.m) + ") is not two solids phases l < m of " +
                  std::to_string(params_.solids.size()));
    for (std::size_t j = 0; j < k; ++j) {
      if (params_.solidsPairs[j].l == pair.l && params_.solidsPairs[j].m == pair.m)
        throw Error("multi-fluid model: solids pair " + std::to_string(k) + " repeats pair " + std::to_string(j));
    }
  }
  if (params_.radialDistribution == RadialDistributionModel::CarnahanStarling && params_.solids.size() > 1)
    throw Error("multi-fluid model: Carnahan-Starling's g0 is of one solids phase; a mixture needs lebowitz");
  if (!params_.rotation) return;
  for (std::size_t m = 1; m <= params_.solids.size(); ++m) {
    const SolidsPhase& s = params_.solids[m - 1];
    const auto particle = closures::EffectiveRestitution{{s.friction, s.tangentialRestitution}}.evaluate(s.restitution);
    const double elastic = 1.0 - s.restitution * s.restitution;
    // Eq. 5.20 over Eq. 5.7. Elastic grains (e = 1) have no (1 - e^2) to scale: the closures'
    // dissipation is zero there and stays zero, the reference's model being about e < 1.
    dissipationScale_[m] = elastic > 0.0 ? particle.dissipationFactor / elastic : 1.0;
    wallEffective_[m] = closures::EffectiveRestitution{{s.wallFriction, s.tangentialRestitution}}
                            .evaluate(s.wallRestitution)
                            .effectiveRestitution;
  }
}

closures::JohnsonJackson MultiFluidModel::wallFor(std::size_t m) const {
  closures::JohnsonJackson jj{*params_.wall};
  jj.params.wallRestitution = params_.solids[m - 1].wallRestitution;
  jj.params.wallEffectiveRestitution = wallEffective_[m];
  return jj;
}

double MultiFluidModel::criticalVoidFraction(const fluid::FlowState& state, std::size_t c) const {
  if (!packing_.byComposition()) return params_.plastic.params.criticalVoidFraction;
  const CellSolidFractions fractions(state, c);
  return packing_.criticalVoidFraction(fractions.values());
}

double MultiFluidModel::plasticSolidsShare(const fluid::FlowState& state) const {
  const fluid::StaggeredGrid& grid = state.grid();
  double plastic = 0.0, total = 0.0;
  for (int k = 0; k < grid.cells(2); ++k) {
    for (int j = 0; j < grid.cells(1); ++j) {
      for (int i = 0; i < grid.cells(0); ++i) {
        const std::size_t c = grid.index(i, j, k);
        const double solids = 1.0 - closureVoidFraction(state, c);
        total += solids;
        if (closureVoidFraction(state, c) < criticalVoidFraction(state, c)) plastic += solids;
      }
    }
  }
  return total > 0.0 ? plastic / total : 0.0;
}

std::vector<std::array<std::size_t, 2>> MultiFluidModel::solidsPairs() const {
  std::vector<std::array<std::size_t, 2>> pairs;
  for (const SolidsPair& pair : params_.solidsPairs) pairs.push_back({pair.l, pair.m});
  return pairs;
}

void MultiFluidModel::evaluateSolidsDrag(const fluid::FlowState& state, fluid::FlowProperties& p, std::size_t c,
                                         const CellMixture& cell) const {
  const CellSolidFractions& fractions = cell.fractions;
  // Solids pairs make a mixture, and a mixture runs on Lebowitz's g0 (the constructor refuses
  // Carnahan-Starling's with several phases): the cell's mixture is there.
  const closures::LebowitzMixture& mixture = cell.mixture.value();
  for (std::size_t k = 0; k < params_.solidsPairs.size(); ++k) {
    const SolidsPair& pair = params_.solidsPairs[k];
    const SolidsPhase& l = params_.solids[pair.l - 1];
    const SolidsPhase& m = params_.solids[pair.m - 1];
    const double g0 = mixture.g0(pair.l - 1, pair.m - 1);
    const double relative =
        (fluid::cellVelocity(state.phases[pair.l], c) - fluid::cellVelocity(state.phases[pair.m], c)).norm();
    p.solidsDrag[k].coefficient[c] = closures::SolidsSolidsDrag{pair.drag}.evaluate(
        {fractions[pair.l - 1], l.density, l.diameter}, {fractions[pair.m - 1], m.density, m.diameter}, g0, relative);
  }
}

void MultiFluidModel::evaluate(const fluid::FlowState& state, fluid::FlowProperties& p) const {
  params_.drag.visit([&](const auto& drag) { evaluateCells(drag, state, p); });
}

template <class Drag>
void MultiFluidModel::evaluateCells(const Drag& drag, const fluid::FlowState& state, fluid::FlowProperties& p) const {
  const fluid::StaggeredGrid& grid = state.grid();
  const fluid::PhaseFields& gas = state.phases[0];
  for (std::size_t m = 1; m < state.phases.size(); ++m) p.phases[m].partialSlipWalls = params_.wall.has_value();
  for (int k = 0; k < grid.cells(2); ++k) {
    for (int j = 0; j < grid.cells(1); ++j) {
      for (int i = 0; i < grid.cells(0); ++i) {
        const std::size_t c = grid.index(i, j, k);
        const double epsG = closureVoidFraction(state, c);
        const double rhoG = params_.gas.densityAt(state.pressure[c]);
        p.phases[0].density[c] = rhoG;
        p.phases[0].compressibility[c] = params_.gas.compressibility();
        p.phases[0].shearViscosity[c] = epsG * params_.gas.viscosity;
        p.phases[0].bulkViscosity[c] = -2.0 / 3.0 * epsG * params_.gas.viscosity;
        const CellMixture cell(state, c, diameters_, params_.radialDistribution == RadialDistributionModel::Lebowitz);
        const double epsGStar = packing_.byComposition() ? packing_.criticalVoidFraction(cell.fractions.values())
                                                         : params_.plastic.params.criticalVoidFraction;
        if (p.packedFraction) (*p.packedFraction)[c] = 1.0 - epsGStar;  // Eq. 3.68's eps_p
        for (std::size_t m = 1; m < state.phases.size(); ++m) {
          const SolidsPhase& solids = params_.solids[m - 1];
          p.phases[m].density[c] = solids.density;
          // Drag first: Lun et al.'s viscosity and conductivity read it (Ma-Ahmadi).
          const double slip = slipSpeed(gas, state.phases[m], c);
          const closures::DragState ds{epsG, cell.fractions[m - 1], solids.diameter, rhoG, params_.gas.viscosity, slip};
          p.dragCoefficient[m][c] = drag.evaluate(ds).beta;
          if (params_.granularEnergy == GranularEnergyForm::Algebraic) {
            evaluateAlgebraic(state, p, m, c, epsG, epsGStar, cell);
          } else {
            evaluatePde(state, p, m, c, epsG, epsGStar, cell);
          }
        }
        if (!p.solidsDrag.empty()) evaluateSolidsDrag(state, p, c, cell);
      }
    }
  }
}

void MultiFluidModel::evaluateAlgebraic(const fluid::FlowState& state, fluid::FlowProperties& p, std::size_t m,
                                        std::size_t c, double epsG, double epsGStar, const CellMixture& cell) const {
  const auto& plastic = params_.plastic.params;
  fluid::PhaseProperties& out = p.phases[m];
  const SolidsState now = solidsState(state, m, c);
  const double eps = now.solidFraction, theta = now.theta;
  const closures::SyamlalCoefficients& kc = now.coefficients;
  const double plasticVoid = plasticVoidFraction(epsG, eps);
  const closures::PlasticRegime::Result pl =
      params_.plastic.evaluate(plasticVoid, eps, now.strain.deviatorInvariant(), epsGStar);
  out.solidsPressure[c] = kc.k1 * eps * eps * theta + pl.pressure;  // Eqs. 3.21 + 3.26
  out.plasticPressure[c] = pl.pressure;
  out.shearViscosity[c] = kc.k3 * eps * std::sqrt(theta) + plasticViscosityShare(cell.fractions, m, params_.plasticPressure) * pl.viscosity;
  out.bulkViscosity[c] = kc.k2 * eps * std::sqrt(theta);
  double slope = 2.0 * kc.k1 * eps * theta;
  slope += plasticPressureSlope(plastic, pl, eps, plasticVoid, epsGStar);
  out.solidsPressureSlope[c] = slope;
}

double MultiFluidModel::plasticVoidFraction(double epsG, double eps) const {
  if (params_.plasticPressure == PlasticPressure::Shared || params_.solids.size() == 1) return epsG;
  return std::max(1.0 - eps, epsG);
}

MultiFluidModel::KineticCell MultiFluidModel::kineticCell(const fluid::FlowState& state,
                                                          const fluid::FlowProperties& properties, std::size_t m,
                                                          std::size_t c, const CellMixture& cell) const {
  const SolidsPhase& solids = params_.solids[m - 1];
  KineticCell k;
  k.state.solidFraction = cell.fractions[m - 1];
  k.state.granularTemperature = std::max(state.phases[m].granularTemperature[c], 0.0);
  k.state.diameter = solids.diameter;
  k.state.density = solids.density;
  k.state.restitution = solids.restitution;
  k.state.gasDragCoefficient = params_.granularGasCoupling ? properties.dragCoefficient[m][c] : 0.0;
  if (params_.radialDistribution == RadialDistributionModel::Lebowitz) {
    setMixtureContacts(cell, m, 0.0, k.state);
    k.g0 = k.state.g0;
  } else {
    k.g0 = closures::carnahanStarlingG0(k.state.solidFraction);
  }
  k.transport = params_.closure.evaluate(k.state);
  k.transport.dissipationRate *= dissipationScale_[m];  // Eq. 5.20 with the rotation model
  return k;
}

void MultiFluidModel::setMixtureContacts(const CellMixture& cell, std::size_t m, double shift,
                                         closures::KineticState& ks) const {
  const std::size_t own = m - 1;
  const CellSolidFractions fractions(cell.fractions, own, shift);
  // Called under Lebowitz's g0 only, where the cell's own mixture is there.
  const closures::LebowitzMixture mixture =
      shift == 0.0 ? cell.mixture.value() : closures::LebowitzMixture(fractions.values(), diameters_);
  closures::setMixtureContacts(mixture, fractions.values(), own, params_.mixtureKineticTheory, ks);
}

void MultiFluidModel::evaluatePde(const fluid::FlowState& state, fluid::FlowProperties& p, std::size_t m, std::size_t c,
                                  double epsG, double epsGStar, const CellMixture& cell) const {
  const auto& plastic = params_.plastic.params;
  fluid::PhaseProperties& out = p.phases[m];
  const KineticCell kin = kineticCell(state, p, m, c, cell);
  const double eps = kin.state.solidFraction;
  const double plasticVoid = plasticVoidFraction(epsG, eps);
  const closures::PlasticRegime::Result pl =
      params_.plastic.evaluate(plasticVoid, eps, fluid::strainRate(state.phases[m], c).deviatorInvariant(), epsGStar);
  out.solidsPressure[c] = kin.transport.pressure + pl.pressure;  // kinetic + Eq. 3.26
  out.plasticPressure[c] = pl.pressure;
  out.shearViscosity[c] = kin.transport.shearViscosity + plasticViscosityShare(cell.fractions, m, params_.plasticPressure) * pl.viscosity;
  out.bulkViscosity[c] = kin.transport.secondViscosity();  // lambda_s; the plastic regime has none
  // The kinetic slope at the cell's theta, by a one-sided difference of the kinetic-theory
  // model's pressure (never the table's: the slope only steers the fraction correction, and the
  // table's out-of-range count must count the solution's lookups alone).
  closures::KineticState shifted = kin.state;
  const double step = 1e-7;
  shifted.solidFraction = std::min(eps + step, 1.0 - 1e-12);
  if (params_.radialDistribution == RadialDistributionModel::Lebowitz)
    setMixtureContacts(cell, m, shifted.solidFraction - eps, shifted);
  // Where no table supplies the pressure the closure's is the model's: no second evaluation.
  const double p0 = params_.closure.modelPressure(kin.state, kin.transport);
  const double p1 = closures::evaluate(params_.closure.kineticModel(), shifted).pressure;
  double slope = std::max((p1 - p0) / (shifted.solidFraction - eps), 0.0);
  slope += plasticPressureSlope(plastic, pl, eps, plasticVoid, epsGStar);
  out.solidsPressureSlope[c] = slope;
  if (params_.wall) {
    const closures::JohnsonJackson::State ws{eps, kin.state.density, kin.g0, kin.state.granularTemperature, 0.0};
    out.wallSlipCoefficient[c] = wallFor(m).evaluate(ws).slipCoefficient;
  }
}

std::vector<fluid::TransportResidual> MultiFluidModel::solveTransport(fluid::FlowState& state,
                                                                      const fluid::FlowState& old,
                                                                      const fluid::FlowProperties& props,
                                                                      const fluid::FlowProperties& oldProps,
                                                                      const fluid::Boundaries& boundaries,
                                                                      double dt) const {
  std::vector<fluid::TransportResidual> residuals;
  if (params_.granularEnergy != GranularEnergyForm::Pde) return residuals;
  const fluid::StaggeredGrid& grid = state.grid();
  const int dims = grid.dimensions();
  const closures::GranularEnergyGasTerms gasTerms;
  // Pinned theta: the cells packed beyond their eps_g*, the same for every phase (the fractions do
  // not change here), found once.
  std::vector<char> plasticCells;
  if (params_.plasticTheta == PlasticTheta::Pinned) {
    plasticCells.assign(grid.paddedCount(), 0);
    for (int k = 0; k < grid.cells(2); ++k)
      for (int j = 0; j < grid.cells(1); ++j)
        for (int i = 0; i < grid.cells(0); ++i) {
          const std::size_t c = grid.index(i, j, k);
          plasticCells[c] = closureVoidFraction(state, c) < criticalVoidFraction(state, c) ? 1 : 0;
        }
  }
  // Every phase's terms in one sweep over the cells, each cell's mixture read once: a phase's terms
  // read its own theta and the fractions, which no phase's solve below changes.
  const std::size_t M = state.phases.size();
  std::vector<GranularEnergyTerms> phaseTerms;
  phaseTerms.reserve(M - 1);
  std::vector<double> scales(M, 1e-6);  // the residuals' theta scale: the phase's largest, or this floor [m^2/s^2]
  for (std::size_t m = 1; m < M; ++m) {
    phaseTerms.emplace_back(grid);
    phaseTerms.back().pinnedTheta = params_.pinnedTheta;
  }
  for (int k = 0; k < grid.cells(2); ++k) {
    for (int j = 0; j < grid.cells(1); ++j) {
      for (int i = 0; i < grid.cells(0); ++i) {
        const std::size_t c = grid.index(i, j, k);
        if (!plasticCells.empty() && plasticCells[c] != 0) {
          for (GranularEnergyTerms& terms : phaseTerms) terms.pinned[c] = 1;
          continue;
        }
        const CellMixture cell(state, c, diameters_, params_.radialDistribution == RadialDistributionModel::Lebowitz);
        for (std::size_t m = 1; m < M; ++m) {
          const fluid::PhaseFields& phase = state.phases[m];
          const SolidsPhase& solids = params_.solids[m - 1];
          GranularEnergyTerms& terms = phaseTerms[m - 1];
          double& scale = scales[m];
          const KineticCell kin = kineticCell(state, props, m, c, cell);
          const closures::KineticTransport& t = kin.transport;
          const double theta = kin.state.granularTemperature;
          const double eps = kin.state.solidFraction;
          scale = std::max(scale, theta);
          terms.conductivity[c] = t.conductivity;
          // S:grad v = -P tr(D) + tau:D, tau:D = 2 mu (D:D - tr(D)^2 / 3) + xi tr(D)^2 >= 0 with
          // the kinetic theory's mu and xi (the plastic stress does not heat the grains, as in
          // MFiX's source_granular_energy).
          const fluid::StrainRate D = fluid::strainRate(phase, c);
          const double trD = D.trace();
          double source =
              2.0 * t.shearViscosity * std::max(D.doubleDot() - trD * trD / 3.0, 0.0) + t.bulkViscosity * trD * trD;
          double sink = theta > 0.0 ? t.dissipationRate / theta : 0.0;  // J_coll = (J / theta*) theta
          if (trD < 0.0) {
            source -= t.pressure * trD;  // compression heats
          } else if (theta > 0.0) {
            sink += t.pressure / theta * trD;  // expansion cools, in proportion to theta
          }
          // The gas: slip production and viscous damping (GranularEnergyGasTerms.hpp).
          const double slip = slipSpeed(state.phases[0], phase, c);
          const auto gas = gasTerms.evaluate({eps, solids.diameter, solids.density, kin.g0, params_.gas.viscosity,
                                              slip, props.dragCoefficient[m][c]});
          if (params_.granularGasCoupling) {
            source += gas.slipProduction(std::max(theta, params_.temperatureFloor));
            sink += gas.viscousDissipationCoefficient;
          }
          terms.source[c] = source;
          terms.sink[c] = sink;
          if (params_.wall) {
            // The wall's slip speed from the cell-centred solids velocity along the wall, reduced
            // as the Robin ghost reduces it: v_wall = mu/h / (mu/h + c/2) v_cell.
            const Vec3 v = fluid::cellVelocity(phase, c);
            for (int a = 0; a < dims; ++a) {
              Vec3 along = v;
              along[a] = 0.0;
              const double conductance = props.phases[m].shearViscosity[c] / grid.spacing(a);
              const double coefficient = props.phases[m].wallSlipCoefficient[c];
              const double reduction =
                  conductance + 0.5 * coefficient > 0.0 ? conductance / (conductance + 0.5 * coefficient) : 1.0;
              const auto wall = wallFor(m).evaluate({eps, solids.density, kin.g0, theta, reduction * along.norm()});
              terms.wallProduction[static_cast<std::size_t>(a)][c] = wall.slipProduction;
              terms.wallSink[static_cast<std::size_t>(a)][c] = theta > 0.0 ? wall.wallDissipation / theta : 0.0;
            }
          }
        }
      }
    }
  }
  for (std::size_t m = 1; m < M; ++m) {
    fluid::PhaseFields& phase = state.phases[m];
    const GranularEnergyTerms& terms = phaseTerms[m - 1];
    const double scale = scales[m];
    GranularEnergyInputs in;
    in.state = &state;
    in.old = &old;
    in.oldDensity = &oldProps.phases[m].density;
    in.boundaries = &boundaries;
    in.dt = dt;
    in.diluteFraction = params_.diluteFraction;
    const auto flux = fluid::massFluxes(phase, props.phases[m].density, boundaries, {}, m);
    const fluid::StencilSystem system = assembleGranularEnergy(in, m, flux, terms);
    const auto r = system.normalisedResidual(phase.granularTemperature.values(), scale);
    const std::string& name = params_.solids[m - 1].name;
    residuals.push_back({r.value, (name.empty() ? "solids " + std::to_string(m) : name) + " granular energy", r.worst});
    system.solve(phase.granularTemperature);
    // The solution of this M-matrix system is non-negative; round-off alone can leave -0.
    for (double& theta : phase.granularTemperature.values()) theta = std::max(theta, 0.0);
  }
  return residuals;
}

MultiFluidModel::SolidsState MultiFluidModel::solidsState(const fluid::FlowState& state, std::size_t m,
                                                          std::size_t c) const {
  const SolidsPhase& solids = params_.solids[m - 1];
  const double epsG = closureVoidFraction(state, c);
  const double eps = closureSolidFraction(state, m, c);
  const closures::KineticState ks{eps, 0.0, solids.diameter, solids.density, solids.restitution, 0.0};
  const closures::SyamlalCoefficients kc = params_.kinetic.coefficients(ks);
  const fluid::StrainRate D = fluid::strainRate(state.phases[m], c);
  return {epsG, eps, kc, D, algebraicGranularTemperature(kc, eps, D.trace(), D.doubleDot())};
}

bool MultiFluidModel::tableCovers(const fluid::FlowState& state, std::size_t m, std::size_t c) const {
  const SolidsPhase& solids = params_.solids[m - 1];
  const closures::KineticState ks{closureSolidFraction(state, m, c),
                                  std::max(state.phases[m].granularTemperature[c], 0.0), solids.diameter,
                                  solids.density, solids.restitution, 0.0};
  return params_.closure.covers(ks);
}

double MultiFluidModel::granularTemperature(const fluid::FlowState& state, std::size_t m, std::size_t c) const {
  if (params_.granularEnergy == GranularEnergyForm::Pde) return state.phases[m].granularTemperature[c];
  return solidsState(state, m, c).theta;
}

}  // namespace grainbridge::mfm
