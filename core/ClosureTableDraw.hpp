#pragma once
// One realisation of a measured closure table within its errors, for carrying the DEM's
// statistical uncertainty through a continuum run (issue 31).
//
// Each node of a table is one closure point, that is one independent DEM run, so the nodes are
// drawn independently: value_k + SE_k z_k with z_k standard normal, SE_k the point's
// block-averaging error. The quantities of one node (p_theta, eta_theta, j_theta) share the
// run's granular temperature and are correlated through it; a draw of one quantity's table
// ignores that, which the one-at-a-time mode (one quantity drawn, the others nominal) does not
// need. A closure coefficient is positive: a draw at or below zero of a positive value is drawn
// again (the normal truncated at zero, which moves the mean by less than 1e-3 SE for
// SE < value / 3).
//
// The stream is std::mt19937_64 seeded from (seed, quantity), so the tables of one sample are
// independent of each other and reproducible from the seed; a zero error leaves its node's value
// bit for bit.
#include <cstdint>
#include <span>

#include "core/ClosureTable.hpp"

namespace grainbridge::core {

// Throws grainbridge::Error when the errors are not one per value, or one is negative or not
// finite.
[[nodiscard]] ClosureTable drawClosureTable(const ClosureTable& nominal, std::span<const double> standardErrors,
                                            std::uint64_t seed);

}  // namespace grainbridge::core
