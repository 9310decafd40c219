#pragma once
// One fluidized-bed run as a comparison of runs reads it (the bed_compare stage): its products
// alone (summary values, series.csv columns, its phases' names, the CSV tables it wrote) and the
// reference values matched to it. The report's figures and tables are built from these.
#include <cmath>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "workflows/report/ClosureSpread.hpp"

namespace grainbridge::workflows::report {

// A published or measured mean height matched to a run.
struct ReferenceHeight {
  std::string label;  // "Table 5.3"
  std::string kind;   // "reference" | "experiment": the colour key
  double height = 0.0;
};

// One bed run as the figures read it.
struct BedRun {
  std::string label;  // the table's entry: "bed (gas_inflow 1.92 m/s, rotation_model true)"
  // What tells it from the other runs compared, the legend's entry: "rotation_model true" (the
  // swept values that differ between the runs; the stage's name where the stages differ); and
  // the same a line per part, an axis category's label. The label when nothing differs.
  std::string shortLabel, category;
  std::string closure;  // the colour key: a kinetic model, or "table"
  double meanHeight = 0.0, meanHeightError = 0.0;
  std::vector<ReferenceHeight> references;                  // the values matched to this run
  std::map<std::string, std::vector<double>> series;        // series.csv, by column
  std::vector<std::string> phases;                          // solids phase names, in order
  std::string pressureDrop;                                 // the compared series column (dp_<tap>)
  std::vector<std::filesystem::path> segregationBlocks;     // segregation_blocks.csv files
  std::vector<std::filesystem::path> profiles;              // profiles.csv files
  // Further summary values, by beds.csv column: pressure_drop(_err) (of the compared tap),
  // dp_frequency, dp_amplitude, table_coverage_cell_steps, table_coverage_solids, solver_steps,
  // retries, segregation_percentage(_err), bed_weight, and a particle run's mean_height_fields(_err),
  // coordination(_err) and multi_contact_ratio(_err); NaN where the run did not record one.
  std::map<std::string, double> values;
  // The spread over the run's closure samples of mean_height, pressure_drop and, for a binary bed,
  // segregation_percentage (issue 31); empty for a run without closure samples.
  std::map<std::string, ClosureSpread> closureSpreads;
  int closureSamples = 0;
  [[nodiscard]] double value(const std::string& column) const;
};

// A measured or published curve drawn beside the runs (bed_compare's reference_series): the
// experiment's 1 s means of s_p, say, read from a CSV of time and value.
struct ReferenceSeries {
  std::string label;     // the legend's words: "Goldschmidt et al. (2003), 1 s means"
  std::string citation;  // where the numbers come from, printed beside the label
  std::string kind;      // "experiment" | "reference": the colour key
  std::string output;    // the series column it is of: "segregation_percentage" | "mean_height"
  std::vector<double> time, value;
};

inline double BedRun::value(const std::string& column) const {
  const auto it = values.find(column);
  return it == values.end() ? NAN : it->second;
}

}  // namespace grainbridge::workflows::report
