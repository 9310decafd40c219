#pragma once
// The temperature ratio of a binary granular mixture in Garzo, Hrenya and Dufty's theory at zeroth
// order (Garzo, Hrenya and Dufty 2007, PRE 76, 031303, "Enskog theory for polydisperse granular
// mixtures. I."; Garzo and Dufty 1999, PRE 60, 5706, at low density): in the homogeneous cooling
// state every species' temperature decays at one rate, zeta_1 = zeta_2, with
//   zeta_i = (8 sqrt(pi) / 3) sum_j n_j chi_ij mu_ji sigma_ij^2 (1 + alpha_ij)
//            sqrt(2 T_i / m_i + 2 T_j / m_j) [1 - (mu_ji / 2)(1 + alpha_ij)(1 + m_i T_j / (m_j T_i))],
// mu_ji = m_j / (m_i + m_j), sigma_ij = (sigma_i + sigma_j) / 2, chi_ij the contact value of the
// pair distribution (Lebowitz's g0 here, as the multi-fluid model's), T_i in energy units. The
// papers could not be read from here (title and abstract only); the cooling rate is as MFiX's GHD
// option writes it (model/GhdTheory/cooling_rate.f and ghd.f, which cite the 2007 papers), checked
// against its limits in the tests: equal species give 1, elastic grains equipartition.
// The ratio depends on T_1 / T_2 only (zeta_i scales as sqrt(T)), so it is one root in r = T_1 / T_2.
#include <vector>

namespace grainbridge::closures {

struct CoolingSpecies {
  double solidFraction = 0.0;  // eps_i
  double diameter = 0.0;       // sigma_i [m]
  double density = 0.0;        // rho_i [kg/m^3]
};

// T_1 / T_2 (energy per grain) of two species with one restitution alpha for every pair. Throws
// grainbridge::Error unless there are two species with positive fractions, diameters and
// densities, 0 < alpha <= 1 and sum eps < 1.
[[nodiscard]] double ghdTemperatureRatio(const std::vector<CoolingSpecies>& species, double restitution);

}  // namespace grainbridge::closures
