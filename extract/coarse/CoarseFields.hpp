#pragma once
// Coarse-grained fields of one particle frame on a CellGrid (cell arrays in C order [k][j][i],
// like core's FieldFrame). SI units. Fields a kernel spreads (first block) follow the chosen
// kernel; the contact statistics of Figs. 7.5-7.7 and 7.11 (second block) count each particle in
// the cell holding its centre, as the reference does.
#include <cstdint>
#include <vector>

#include "core/Types.hpp"
#include "core/grid/CellGrid.hpp"
#include "extract/coarse/CoarseGrainingKernel.hpp"

namespace grainbridge::extract::coarse {

struct SpeciesCellFields {
  std::int32_t species = 0;
  std::vector<double> solidFraction;  // eps_sm [-]
  std::vector<double> density;        // partial bulk density, mass per cell volume [kg/m^3]
  std::vector<Vec3> velocity;         // mass-weighted mean velocity [m/s]
  // T_m = <C^2>/3 (Eq. 3.38), mass-weighted, C about this species' own local mean velocity (each
  // solids phase has its own velocity and temperature in the multi-fluid model) and, under
  // Lees-Edwards shear, about the streaming profile at each particle [m^2/s^2]
  std::vector<double> granularTemperature;
};

struct CoarseFields {
  CoarseFields(const core::grid::CellGrid& g, const CoarseGrainingKernel& k) : grid(g), kernel(k) {}

  core::grid::CellGrid grid;  // with the frame's Lees-Edwards offset applied
  CoarseGrainingKernel kernel;

  std::vector<double> solidFraction;  // all species [-]
  std::vector<double> density;        // bulk density [kg/m^3]
  std::vector<Vec3> velocity;         // mass-weighted mean velocity (lab frame) [m/s]
  // Mixture T = tr(kinetic stress) / (3 density) [m^2/s^2]: C about the mixture's local mean
  // velocity (and the streaming profile under shear).
  std::vector<double> granularTemperature;
  // Eq. 2.3, positive in compression [Pa]: kinetic part sum m C C phi, contact part r_ij F_ij
  // spread along the contact line (wall contacts from the centre to the contact point).
  std::vector<Mat3> kineticStress, contactStress, stress;
  std::vector<double> pressure;          // tr(stress) / 3 [Pa]
  std::vector<double> shearStress;       // stress xy [Pa]
  std::vector<double> deviatoricStress;  // sqrt(s:s / 2), s the deviator [Pa]
  std::vector<SpeciesCellFields> species;

  // By particle centre:
  std::vector<double> particleCount;
  std::vector<double> coordinationNumber;  // mean particle-particle contacts per particle
  // particles with N_c >= 2 over particles with N_c >= 1 (Fig. 7.11); 0 where none is in contact
  std::vector<double> multiContactRatio;
  // |sum of contact forces| and |sum of drag (external) forces| over the particles of a cell
  // (Fig. 7.7) [N], and their ratio; the ratio is -1 where the drag is zero, as in Fig. 7.7.
  std::vector<double> contactForce, dragForce, contactToDragRatio;
};

}  // namespace grainbridge::extract::coarse
