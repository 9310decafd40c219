#include "engines/closures/MixtureSimpleShear.hpp"

#include <cmath>
#include <string>

#include "core/Error.hpp"
#include "engines/closures/RadialDistribution.hpp"

namespace grainbridge::closures {

std::vector<ShearedPhaseState> mixtureSimpleShear(KineticModelName model, MixtureKineticTheory form,
                                                  const std::vector<ShearedPhase>& phases, double shearRate) {
  if (phases.empty()) throw Error("mixture simple shear: no phase");
  std::vector<double> fractions, diameters;
  for (const ShearedPhase& p : phases) {
    fractions.push_back(p.solidFraction);
    diameters.push_back(p.diameter);
  }
  const LebowitzMixture mixture(fractions, diameters);
  std::vector<ShearedPhaseState> out;
  for (std::size_t m = 0; m < phases.size(); ++m) {
    KineticState s;
    s.solidFraction = phases[m].solidFraction;
    s.diameter = phases[m].diameter;
    s.density = phases[m].density;
    s.restitution = phases[m].restitution;
    setMixtureContacts(mixture, fractions, m, form, s);
    s.granularTemperature = 1.0;
    const KineticTransport unit = evaluate(model, s);
    s.granularTemperature = 4.0;
    const KineticTransport four = evaluate(model, s);
    const auto scales = [](double at4, double at1, double factor) {
      return std::abs(at4 - factor * at1) <= 1e-12 * std::abs(factor * at1);
    };
    if (!scales(four.shearViscosity, unit.shearViscosity, 2.0) ||
        !scales(four.dissipationRate, unit.dissipationRate, 8.0)) {
      throw Error("mixture simple shear: " + std::string(toString(model)) +
                  "'s viscosity and dissipation do not scale as sqrt(theta) and theta^(3/2)");
    }
    ShearedPhaseState state;
    const double dissipation = unit.dissipationRate * phases[m].dissipationScale;  // at theta = 1
    if (dissipation > 0.0) {
      const double theta = unit.shearViscosity * shearRate * shearRate / dissipation;
      state.granularTemperature = theta;
      state.pressure = unit.pressure * theta;  // p is proportional to theta
      state.kineticPressure = s.density * s.solidFraction * theta;
      state.viscosity = unit.shearViscosity * std::sqrt(theta);
      state.shearStress = state.viscosity * shearRate;
      state.dissipationRate = dissipation * theta * std::sqrt(theta);
    }
    out.push_back(state);
  }
  return out;
}

}  // namespace grainbridge::closures
