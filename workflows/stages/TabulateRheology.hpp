#pragma once
// The tabulate stage's dense-flow part (issue 30): from sheared closure points that carry an
// inertial number, per restitution, the mu(I) table (stress ratio against I) and the phi(I)
// table (solid fraction against I), each with its fit (extract/statistics/InertialRheologyFit)
// over the points with I <= fitMax. Rows go to the `rheology` database table; the CSVs and the
// summary say the same for people.
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace grainbridge::workflows::stages {

struct TabulatedRheology {
  std::vector<nlohmann::json> rows;  // one per (restitution, relation): the database's rheology rows
  std::string pointsCsv;             // rheology_points.csv
  std::string fitsCsv;               // rheology_fits.csv
  nlohmann::json summary = nlohmann::json::array();  // per row: restitution, relation, parameters and errors
};

// `points` are closure-point summaries of one friction. Points without an inertial number
// (unsheared, or without pressure) are left out; none left gives no rows. Throws
// grainbridge::Error when the points are of different grains (diameter or density): a rheology
// is of one kind of grain.
TabulatedRheology tabulateRheology(const std::vector<nlohmann::json>& points, const std::string& name,
                                   double fitMax);

}  // namespace grainbridge::workflows::stages
