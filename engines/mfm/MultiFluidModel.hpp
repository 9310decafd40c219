#pragma once
// The multi-fluid model of Chapters 3 and 5 as the SIMPLE solver of engines/fluid sees it: per
// cell, the gas's density and viscosity, each solids phase's stresses and the gas-solids drag,
// and the granular-energy equation it solves itself.
//   gas      incompressible or ideal, tau_g = 2 eps_g mu_g D_g - 2/3 eps_g mu_g tr(D_g) I (Eq. 3.20
//            with Stokes's hypothesis lambda_g = -2/3 mu_g);
//   solids   the viscous regime of kinetic theory in one of two forms:
//              pde        (the default, as Chapter 5 ran) theta from the granular-energy equation
//                         (Eq. 3.34, GranularEnergy.hpp) and every coefficient from the closure
//                         model (`ktgf`: a kinetic theory of engines/closures, lun1984 the
//                         default; `table`: DEM closure tables with the kinetic theory for what
//                         they lack);
//              algebraic  Eqs. 3.21-3.25 with MFiX's gt_algebraic theta (production S:grad v
//                         equals the dissipation K4 eps^2 theta^1.5), the grain bed of Chapter 4;
//            plus, below the critical void fraction eps_g*, the plastic regime of Eqs. 3.26-3.27
//            (Schaeffer's viscosity). The two add, as MFiX's Schaeffer option adds them, so the
//            stress has no jump at eps_g*, where P* vanishes.
//   drag     the gas-solids law by name (Syamlal-O'Brien, Eqs. 3.10-3.16, by default) at the
//            cell-centred slip.
//   walls    optionally Johnson-Jackson partial slip and wall energy flux for the solids at the
//            no-slip wall patches (Eqs. 5.8-5.10); without it the solids stick and no energy
//            crosses a wall.
//   rotation optionally the particle-rotation model (Eqs. 5.11-5.21): e_eff of each phase's
//            friction replaces e in the collisional dissipation (Eq. 5.20) and e_w,eff in the wall
//            dissipation (Eq. 5.21), as (1 + e)(1 - e_eff), and nowhere else: pressure,
//            viscosities and conductivity keep e. A table's dissipation is looked up at e (the
//            frictionless DEM's restitution) and scaled by (1 + e)(1 - e_eff) / (1 - e^2).
// The solids-pressure slope dP_s/deps_s the fraction correction needs is the plastic one,
// P* + eps_s n A (eps_g* - eps_g)^(n-1), plus the kinetic theory's at the cell's theta.
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "engines/closures/ClosureModel.hpp"
#include "engines/closures/GasSolidsDrag.hpp"
#include "engines/closures/JohnsonJackson.hpp"
#include "engines/closures/MixtureContacts.hpp"
#include "engines/closures/MixturePacking.hpp"
#include "engines/closures/PlasticRegime.hpp"
#include "engines/closures/SolidsSolidsDrag.hpp"
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
  double diameter = 0.0;         // d_p [m]
  double density = 0.0;          // rho_s [kg/m^3]
  double restitution = 0.9;      // e_mm [-]
  double wallRestitution = 0.9;  // e_w of Eq. 5.9 [-]
  // The rotation model's surface parameters (Table 5.1): Coulomb friction between particles and
  // with the wall, and the tangential restitution beta0 of Eq. 5.17 (both contacts).
  double friction = 0.0;
  double wallFriction = 0.0;
  double tangentialRestitution = 0.33;
  // The packing fraction of this kind alone, which a packing limit by composition starts from
  // (MixturePacking.hpp): MFiX's ep_s_max, 0.6 by default in its 2003-05 init_namelist.f.
  double maxPacking = 0.6;
};

enum class GranularEnergyForm { Pde, Algebraic };

// g0 at contact in the kinetic theory and the solids-solids drag: Carnahan-Starling of the phase's
// own fraction (one solids phase), or Lebowitz's for a mixture (closures/RadialDistribution.hpp),
// with MFIX's mixture sums in the kinetic theory (KineticState).
enum class RadialDistributionModel { CarnahanStarling, Lebowitz };

// Two solids phases l < m (1-based, as in FlowState) and the parameters of their drag, Eq. 3.18.
struct SolidsPair {
  std::size_t l = 1, m = 2;
  closures::SolidsSolidsDrag::Params drag;
};

// Theta where the solids are packed beyond the plastic regime's onset (eps_g < eps_g*):
// Solved, the granular-energy equation there as everywhere, so the kinetic stress adds to the
// plastic one; Pinned, theta held at pinnedTheta in those cells, so they carry the plastic stress
// alone, as MFIX does (solve_granular_energy.f with SCHAEFFER, 2005 and 21.3: "Adjusting the
// values of theta_m to zero when Ep_g < EP_star (Schaeffer, 1987)").
enum class PlasticTheta { Solved, Pinned };

// Which void fraction a mixture's plastic pressure and viscosity (Eqs. 3.26-3.27) are of: Shared,
// the cell's (P* of the total solids fraction, each phase taking eps_sm P* and eps_sm / eps_s of
// the viscosity, as MFiX does); PerPhase, each phase's own as if it were alone (P*(1 - eps_sm),
// all of its own viscosity), so that one phase's packing does not push another. PerPhase is a
// diagnostic (issue 56: does the grain's packing hold the combine's chaff in the feed's plume?),
// not a model from the reference; with one solids phase the two are the same.
enum class PlasticPressure { Shared, PerPhase };

// How a phase of a mixture counts contacts in its kinetic theory (Lebowitz g0): Summed (MFiX's
// SUM_EpsGo) or PerPhase (the equations as printed), closures/MixtureContacts.hpp.
using MixtureKineticTheory = closures::MixtureKineticTheory;

struct MultiFluidParams {
  GasPhase gas;
  std::vector<SolidsPhase> solids;
  // The solver's dilute_fraction (fluid::SimpleSettings::diluteFraction): cells with less solids
  // take the granular temperature of their neighbours instead of solving Eq. 3.34 (GranularEnergy).
  double diluteFraction = 1e-4;
  // The solids pairs that exchange momentum by Eq. 3.18; with several solids phases, every pair
  // (the set-up fills an unlisted one with C_f 0 and the mean of the two restitutions).
  std::vector<SolidsPair> solidsPairs;
  RadialDistributionModel radialDistribution = RadialDistributionModel::CarnahanStarling;
  closures::GasSolidsDrag drag = closures::GasSolidsDrag::byName("syamlal_obrien");
  GranularEnergyForm granularEnergy = GranularEnergyForm::Pde;
  closures::ClosureModel closure = closures::ClosureModel::kineticTheory();  // the pde form's
  closures::SyamlalAlgebraic kinetic;                                        // the algebraic form's
  closures::PlasticRegime plastic;
  // Johnson-Jackson walls for the solids (pde form): phi' and eps_s,max; e_w is per phase.
  std::optional<closures::JohnsonJackson::Params> wall;
  bool rotation = false;  // the particle-rotation model (pde form)
  PlasticTheta plasticTheta = PlasticTheta::Solved;  // (pde form)
  PlasticPressure plasticPressure = PlasticPressure::Shared;
  MixtureKineticTheory mixtureKineticTheory = MixtureKineticTheory::Summed;  // (pde form, Lebowitz g0)
  // eps_g* of each cell: the plastic regime's criticalVoidFraction (fixed), or the packing limit of
  // the cell's composition from each phase's maxPacking (MixturePacking.hpp), in the plastic
  // pressure and viscosity (Eqs. 3.26-3.27), the theta pinning threshold and Eq. 3.68's packed
  // fraction (FlowProperties::packedFraction).
  closures::PackingLimit packingLimit = closures::PackingLimit::Fixed;
  // The theta of a pinned cell: MFIX's smallTheta, ZERO_EP_S = 1e-8 in cm^2/s^2 [m^2/s^2].
  double pinnedTheta = 1e-12;
  // The gas's terms in the granular energy (gamma_slip, J_vis) and in the transport coefficients
  // (Ma-Ahmadi); off only to compare with a granular flow without gas (DEM closures, Haff's law).
  bool granularGasCoupling = true;
  // The least theta the gas's slip production gamma_slip = a / sqrt(theta) is evaluated at: it
  // diverges at theta = 0, where a packed bed sits [m^2/s^2].
  double temperatureFloor = 1e-10;
};

// The packing limit these params pack each cell by (MixturePacking.hpp): the model's, and what a
// feed or an initial region is checked against. Throws grainbridge::Error as MixturePacking does.
[[nodiscard]] closures::MixturePacking mixturePackingOf(const MultiFluidParams& params);

class MultiFluidModel final : public fluid::FlowModel {
 public:
  // Throws grainbridge::Error naming a combination the model cannot run (the rotation model or
  // Johnson-Jackson walls with the algebraic form; a solids pair naming no phase, or twice).
  explicit MultiFluidModel(MultiFluidParams params);
  [[nodiscard]] const MultiFluidParams& params() const { return params_; }
  void evaluate(const fluid::FlowState& state, fluid::FlowProperties& properties) const override;
  [[nodiscard]] std::vector<std::array<std::size_t, 2>> solidsPairs() const override;
  [[nodiscard]] bool packedFractionByCell() const override { return packing_.byComposition(); }
  // eps_g* at interior cell c: the fixed one, or the packing limit of the cell's composition.
  [[nodiscard]] double criticalVoidFraction(const fluid::FlowState& state, std::size_t c) const;
  // The share of all solids (every phase, by volume) in cells packed beyond their eps_g*, where
  // the plastic regime holds (Eqs. 3.26-3.27); 0 without solids.
  [[nodiscard]] double plasticSolidsShare(const fluid::FlowState& state) const;
  // The pde form's granular energy of every solids phase (Eq. 3.34).
  std::vector<fluid::TransportResidual> solveTransport(fluid::FlowState& state, const fluid::FlowState& old,
                                                       const fluid::FlowProperties& properties,
                                                       const fluid::FlowProperties& oldProperties,
                                                       const fluid::Boundaries& boundaries, double dt) const override;
  // The granular temperature of solids phase m (1..M) at interior cell c [m^2/s^2]: the state's
  // (pde) or the algebraic one.
  [[nodiscard]] double granularTemperature(const fluid::FlowState& state, std::size_t m, std::size_t c) const;
  // (1 + e)(1 - e_eff) / (1 - e^2) of phase m (1..M): the rotation model's factor on the
  // collisional dissipation (1 without it).
  [[nodiscard]] double dissipationScale(std::size_t m) const { return dissipationScale_[m]; }
  // Whether the closure's tables hold the state of phase m at interior cell c (true for ktgf).
  [[nodiscard]] bool tableCovers(const fluid::FlowState& state, std::size_t m, std::size_t c) const;
  // e_w,eff of phase m with the rotation model.
  [[nodiscard]] std::optional<double> wallEffectiveRestitution(std::size_t m) const { return wallEffective_[m]; }

 private:
  // Kinetic theory (pde form) of phase m at cell c: the state the closures see and their result.
  struct KineticCell {
    closures::KineticState state;
    closures::KineticTransport transport;
    double g0 = 1.0;
  };
  // A cell's solids as the closures see them, read once per cell and sweep: every phase's closure
  // fraction and, under Lebowitz's g0, their mixture. The kinetic theory, its pressure slope, the
  // plastic viscosity's share and the solids drag each read them anew before, seven times per cell
  // and iteration in the binary bed (issue 55); the values are the same, bit for bit.
  class CellMixture;
  // Phase m's g0_mm and mixture sums under the Lebowitz distribution, with eps_m raised by
  // `shift` (the pressure slope's neighbouring state; 0: the cell's own mixture).
  void setMixtureContacts(const CellMixture& cell, std::size_t m, double shift, closures::KineticState& ks) const;
  // F_sml of every solids pair at cell c (Eq. 3.18, g0_lm of the mixture).
  void evaluateSolidsDrag(const fluid::FlowState& state, fluid::FlowProperties& properties, std::size_t c,
                          const CellMixture& cell) const;
  // evaluate()'s sweep over the cells with the drag law chosen once (params_.drag visited
  // outside the loop), so the loop calls the law directly.
  template <class Drag>
  void evaluateCells(const Drag& drag, const fluid::FlowState& state, fluid::FlowProperties& p) const;
  [[nodiscard]] KineticCell kineticCell(const fluid::FlowState& state, const fluid::FlowProperties& properties,
                                        std::size_t m, std::size_t c, const CellMixture& cell) const;
  [[nodiscard]] closures::JohnsonJackson wallFor(std::size_t m) const;
  // Phase m's stresses at cell c of void fraction epsG and critical void fraction epsGStar.
  void evaluateAlgebraic(const fluid::FlowState& state, fluid::FlowProperties& p, std::size_t m, std::size_t c,
                         double epsG, double epsGStar, const CellMixture& cell) const;
  void evaluatePde(const fluid::FlowState& state, fluid::FlowProperties& p, std::size_t m, std::size_t c, double epsG,
                   double epsGStar, const CellMixture& cell) const;

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
  // The void fraction phase m's plastic stress is of (PlasticPressure): the cell's epsG, or 1 minus
  // the phase's own eps when per phase in a mixture.
  [[nodiscard]] double plasticVoidFraction(double epsG, double eps) const;

  MultiFluidParams params_;
  std::vector<double> dissipationScale_;              // per phase, [0] unused
  std::vector<double> diameters_;                     // d_p of each solids phase, [m - 1] (Lebowitz's g0)
  std::vector<std::optional<double>> wallEffective_;  // per phase, [0] unused
  closures::MixturePacking packing_;
};

// The algebraic granular temperature of MFiX's gt_algebraic: the positive root x = sqrt(theta) of
//   K4 eps x^2 + K1 eps tr(D) x - (K2 tr(D)^2 + 2 K3 D:D) = 0,
// zero where the solids do not shear, and zero where eps <= 1e-15 (MFiX's SMALL_NUMBER, calc_mu_s.f):
// as eps -> 0 the root grows as eps^-1/2, and in a cell of round-off solids (5e-316 of the chaff
// in the combine) theta overflowed to infinity, the pressure slope with it, and the fraction
// correction met 0 * inf. [m^2/s^2]
[[nodiscard]] double algebraicGranularTemperature(const closures::SyamlalCoefficients& k, double solidFraction,
                                                  double traceD, double doubleDotD);

}  // namespace grainbridge::mfm
