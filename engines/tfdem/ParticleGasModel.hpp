#pragma once
// The gas step's model in TF-DEM (Section 7.2.3): an incompressible gas (the viscous stress of
// Eqs. 3.19-3.20) and one given phase, the particles deposited on the grid (ParticleDeposit),
// whose fraction and velocity the gas solver does not touch (fluid::FlowModel::givenPhase). What
// the gas receives from the particles (`GasReaction`):
//   cell_average  Eq. 7.33: beta (v_g - v_sm) per cell, beta of Eq. 7.34 from the cell's mean
//                 velocities and Sauter diameter; implicit in the gas momentum, as the reference
//                 did in all its runs (line 1882);
//   summed        Eq. 7.32: minus the particles' drag, summed per cell over the last fluid step's
//                 DEM sub-steps and averaged over them, an explicit momentum source.
// The pressure-gradient part of Eq. 7.32 (-eps_s grad P_g) is the gas momentum's own -eps_g grad
// P_g complement: the gas equation carries eps_g grad P_g, the particles -V_p grad P_g.
#include <cstddef>
#include <vector>

#include "core/Types.hpp"
#include "engines/closures/GasSolidsDrag.hpp"
#include "engines/fluid/SimpleStep.hpp"
#include "engines/tfdem/ParticleDeposit.hpp"

namespace grainbridge::tfdem {

enum class GasReaction { CellAverage, Summed };

struct Gas {
  double density = 1.2;       // rho_g [kg/m^3], incompressible
  double viscosity = 1.8e-5;  // mu_g [Pa s]
};

class ParticleGasModel final : public fluid::FlowModel {
 public:
  // `deposit` and, for summed, `drag` (the particles' drag per padded cell and unit volume
  // [N/m^3], one per axis) are read at every evaluation and must outlive the model's use.
  ParticleGasModel(Gas gas, closures::GasSolidsDrag law, GasReaction reaction, const ParticleDeposit& deposit,
                   const std::vector<Vec3>* summedDrag);

  void evaluate(const fluid::FlowState& state, fluid::FlowProperties& properties) const override;
  [[nodiscard]] bool givenPhase(std::size_t m) const override { return m == 1; }

  // Eq. 7.34's beta in cell c at the state's gas velocity [kg/(m^3 s)]; 0 without particles.
  [[nodiscard]] double cellBeta(const fluid::FlowState& state, std::size_t c) const;
  // cellBeta of every interior cell, 0 in the padding: one sweep, the law chosen once.
  [[nodiscard]] std::vector<double> cellBetas(const fluid::FlowState& state) const;

 private:
  // evaluate()'s sweep with the drag law chosen once, outside the loop over cells.
  template <class Law>
  void evaluateWith(const Law& law, const fluid::FlowState& state, fluid::FlowProperties& properties) const;

  Gas gas_;
  closures::GasSolidsDrag law_;
  GasReaction reaction_;
  const ParticleDeposit* deposit_;
  const std::vector<Vec3>* summedDrag_;
};

}  // namespace grainbridge::tfdem
