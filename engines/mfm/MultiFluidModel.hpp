#pragma once
// The multi-fluid model of Chapter 3 as the SIMPLE solver of engines/fluid sees it: per cell,
// the gas's density and viscosity, each solids phase's stresses and the gas-solids drag.
//   gas      incompressible, tau_g = 2 eps_g mu_g D_g - 2/3 eps_g mu_g tr(D_g) I (Eq. 3.20 with
//            Stokes's hypothesis lambda_g = -2/3 mu_g);
//   solids   the viscous regime of kinetic theory in its algebraic form (Eqs. 3.21-3.25 with the
//            granular temperature of MFiX's gt_algebraic: production S:grad v equals the
//            dissipation K4 eps^2 theta^1.5, convection and conduction neglected), plus, below
//            the critical void fraction eps_g*, the plastic regime of Eqs. 3.26-3.27 (Schaeffer's
//            viscosity). The two add, as MFiX's Schaeffer option adds them, so the stress has no
//            jump at eps_g*, where P* vanishes.
//   drag     the gas-solids law by name (Syamlal-O'Brien, Eqs. 3.10-3.16, by default) at the
//            cell-centred slip.
// The solids-pressure slope dP_s/deps_s the fraction correction needs is the plastic one,
// P* + eps_s n A (eps_g* - eps_g)^(n-1), plus the kinetic 2 K1 eps_s theta (theta held).
#include <string>
#include <vector>

#include "engines/closures/GasSolidsDrag.hpp"
#include "engines/closures/PlasticRegime.hpp"
#include "engines/closures/SyamlalAlgebraic.hpp"
#include "engines/fluid/SimpleStep.hpp"
#include "engines/fluid/StrainRate.hpp"

namespace grainbridge::mfm {

// Incompressible (rho_g fixed) or an ideal gas, rho_g = P_g M / (R T) at a fixed temperature
// (the reference's 101325 Pa outlet suggests one, VALIDATION.md; the energy equation is not
// solved). The pressure is then absolute.
struct GasPhase {
  double density = 1.2;       // rho_g of an incompressible gas [kg/m^3]
  double viscosity = 1.8e-5;  // mu_g [Pa s]
  bool ideal = false;
  double molarMass = 0.028964;                         // M [kg/mol] (air)
  double temperature = 293.15;                         // T [K]
  static constexpr double kGasConstant = 8.314462618;  // R [J/(mol K)]
  // rho_g at pressure P, and d rho_g / dP.
  [[nodiscard]] double densityAt(double pressure) const {
    return ideal ? pressure * molarMass / (kGasConstant * temperature) : density;
  }
  [[nodiscard]] double compressibility() const { return ideal ? molarMass / (kGasConstant * temperature) : 0.0; }
};

struct SolidsPhase {
  std::string name;
  double diameter = 0.0;     // d_p [m]
  double density = 0.0;      // rho_s [kg/m^3]
  double restitution = 0.9;  // e_mm [-]
};

struct MultiFluidParams {
  GasPhase gas;
  std::vector<SolidsPhase> solids;
  closures::GasSolidsDrag drag = closures::GasSolidsDrag::byName("syamlal_obrien");
  closures::SyamlalAlgebraic kinetic;
  closures::PlasticRegime plastic;
};

class MultiFluidModel final : public fluid::FlowModel {
 public:
  explicit MultiFluidModel(MultiFluidParams params) : params_(std::move(params)) {}
  [[nodiscard]] const MultiFluidParams& params() const { return params_; }
  void evaluate(const fluid::FlowState& state, fluid::FlowProperties& properties) const override;
  // The algebraic granular temperature of solids phase m (1..M) at interior cell c [m^2/s^2].
  [[nodiscard]] double granularTemperature(const fluid::FlowState& state, std::size_t m, std::size_t c) const;

 private:
  // What the solids stress of phase m at cell c is built from: the fractions the closures see
  // (clamped into range, the state itself is not), Eqs. 3.23-3.25's coefficients, the strain
  // rate and the algebraic temperature.
  struct SolidsState {
    double voidFraction, solidFraction;
    closures::SyamlalCoefficients coefficients;
    fluid::StrainRate strain;
    double theta;
  };
  [[nodiscard]] SolidsState solidsState(const fluid::FlowState& state, std::size_t m, std::size_t c) const;

  MultiFluidParams params_;
};

// The algebraic granular temperature of MFiX's gt_algebraic: the positive root x = sqrt(theta) of
//   K4 eps x^2 + K1 eps tr(D) x - (K2 tr(D)^2 + 2 K3 D:D) = 0,
// zero where the solids do not shear. [m^2/s^2]
[[nodiscard]] double algebraicGranularTemperature(const closures::SyamlalCoefficients& k, double solidFraction,
                                                  double traceD, double doubleDotD);

}  // namespace grainbridge::mfm
