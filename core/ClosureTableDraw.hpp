#pragma once
// One realisation of a measured closure table within its errors, for carrying the DEM's
// statistical uncertainty through a continuum run (issue 31).
//
// Each node of a table is one closure point, that is one independent DEM run, so the nodes are
// drawn independently: value_k + SE_k z_k with z_k standard normal, SE_k the point's
// block-averaging error. The quantities of one node (p_theta, eta_theta, j_theta) share the
// run's granular temperature (and under shear its shear stress) and are correlated through it:
// drawClosureTablesJointly draws a node's quantities together, z = L u with L L^T the point's
// correlation matrix (extract records the coefficients, tabulate keeps them per node; issue 63),
// which the one-at-a-time mode (one quantity drawn, the others nominal) does not need. A closure
// coefficient is positive: a draw at or below zero of a positive value is drawn
// again (the normal truncated at zero, which moves the mean by less than 1e-3 SE for
// SE < value / 3).
//
// The stream is std::mt19937_64 seeded from (seed, quantity), so the tables of one sample are
// independent of each other and reproducible from the seed; a zero error leaves its node's value
// bit for bit.
#include <cstdint>
#include <map>
#include <span>
#include <string>
#include <vector>

#include "core/ClosureTable.hpp"

namespace grainbridge::core {

// Throws grainbridge::Error when the errors are not one per value, or one is negative or not
// finite.
[[nodiscard]] ClosureTable drawClosureTable(const ClosureTable& nominal, std::span<const double> standardErrors,
                                            std::uint64_t seed);

// One table of a joint draw: its nominal values, their standard errors, and per other quantity
// the correlation coefficient of the two at each node (extract's <a>_<b>_corr, in the table's
// node layout; a quantity not named there is uncorrelated with this one).
struct TableToDraw {
  const ClosureTable* nominal = nullptr;
  std::span<const double> standardErrors;
  const std::map<std::string, std::vector<double>>* correlations = nullptr;
};

// The tables of one realisation, drawn together: node k of every table from one correlated
// normal vector. A coefficient is taken from the first of the two tables that has it; a matrix
// that is not positive definite (each coefficient has its own error) has its off-diagonal
// entries shrunk towards zero until it is. Tables without correlations, or not on one node layout,
// are drawn one by one as drawClosureTable does (bit for bit). The stream is seeded from (seed,
// the quantities' names). Throws as drawClosureTable, and for a coefficient outside [-1, 1] or
// a correlation vector not one per node.
[[nodiscard]] std::vector<ClosureTable> drawClosureTablesJointly(std::span<const TableToDraw> tables,
                                                                 std::uint64_t seed);

}  // namespace grainbridge::core
