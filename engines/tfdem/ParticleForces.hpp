#pragma once
// What the gas gives each particle for the next DEM sub-steps (Eq. 7.28, its viscous term
// neglected as the reference does, line 1882), written into the DEM's coupling arrays
// (dem::FluidPressure, dem::FluidCoupling):
//   pressure  -V_p grad P_g, the cells' pressure gradients weighted by the particle's shares;
//   drag, by DragTransfer:
//     cell_average  Eq. 7.33's cell drag beta (v_g - v_sm) shared by solids volume: V_p w_ic
//                   beta_c (v_g,c - v_sm,c) / eps_s,c summed over its cells (a_p, held over the
//                   fluid step), so a cell's particles receive exactly its exchange;
//     per_particle  Eq. 7.29: B_p (u_p - v_p) with B_p = eps_g pi d^3 beta / (6 eps_g eps_s), beta of
//                   Eq. 7.30 at the particle's own slip and its cells' eps, u_p the gas at the
//                   particle (GasVelocity: its cells' centre velocities, or interpolated at its
//                   centre), the particle's velocity current at every sub-step.
#include <vector>

#include "engines/closures/GasSolidsDrag.hpp"
#include "engines/dem/Particles.hpp"
#include "engines/fluid/FlowState.hpp"
#include "engines/tfdem/ParticleDeposit.hpp"
#include "engines/tfdem/ParticleGasModel.hpp"

namespace grainbridge::tfdem {

enum class DragTransfer { CellAverage, PerParticle };
enum class GasVelocity { Cell, Interpolated };

struct ParticleForceSettings {
  DragTransfer transfer = DragTransfer::CellAverage;
  GasVelocity gasVelocity = GasVelocity::Cell;
  Gas gas;
};

// Eq. 7.33's drag per unit solids volume in each padded cell, beta_c (v_g,c - v_s,c) / eps_s,c with
// the gas's cell-centre velocity and Eq. 7.34's `cellBeta` [N/m^3]; zero without particles.
[[nodiscard]] std::vector<Vec3> cellDragPerSolidsVolume(const fluid::FlowState& state, const ParticleDeposit& deposit,
                                                        const std::vector<double>& cellBeta);

// Fills couplingPressure, couplingA, couplingB and couplingU of the owned particles from the
// converged gas `state` and the deposit the step was taken with (whose shares are the particles'
// in their current order). `cellDrag` is cellDragPerSolidsVolume (read with cell_average only).
void setParticleForces(dem::Particles& particles, const fluid::FlowState& state, const ParticleDeposit& deposit,
                       const std::vector<Vec3>& cellDrag, const closures::GasSolidsDrag& law,
                       const ParticleForceSettings& settings);

}  // namespace grainbridge::tfdem
