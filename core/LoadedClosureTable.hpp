#pragma once
// A closure table as a continuum run receives it from the workflow database: the table itself
// plus where it came from (its name, the run that made it, the sha256 of its content, which is
// what enters a consuming instance's key) and the filter it was made under. db::ClosureStore
// loads it on rank 0 and it reaches the stage as it is (the instance task and the stage context
// hold this type); only to cross to a worker rank does it become JSON (to_json, and
// loadedClosureTableFromJson there), so the engine never rebuilds a table from loose fields.
#include <map>
#include <nlohmann/json_fwd.hpp>
#include <string>
#include <vector>

#include "core/ClosureTable.hpp"

namespace grainbridge::core {

struct LoadedClosureTable {
  std::string name;    // the tables' name (tabulate's `table`)
  std::string runKey;  // the run that made it
  std::string sha256;  // over the content alone (contentSha256)
  // The grains' friction the DEM runs behind the table had (tabulate's filter); 0 for frictionless.
  double friction = 0.0;
  ClosureTable table;
  // The standard error of each node's value (the closure point's block-averaging error), in the
  // layout of table.values(); empty when the database row has none. Not in sha256: a nominal
  // run does not depend on it.
  std::vector<double> uncertainties;
  // Per other quantity of the same closure points, the correlation coefficient of the two at each
  // node (issue 63; empty for tables made before it). Not in sha256 either.
  std::map<std::string, std::vector<double>> correlations{};

  [[nodiscard]] const std::string& quantity() const { return table.quantity(); }
};

// The sha256 of a table's content (quantity, axes, values): equal tables hash equal whatever
// their name or run.
[[nodiscard]] std::string contentSha256(const ClosureTable& table);

void to_json(nlohmann::json& j, const LoadedClosureTable& t);
// Throws grainbridge::Error naming what is missing or wrong (ClosureTable's own checks).
[[nodiscard]] LoadedClosureTable loadedClosureTableFromJson(const nlohmann::json& j);

}  // namespace grainbridge::core
