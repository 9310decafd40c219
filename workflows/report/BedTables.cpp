#include "workflows/report/BedTables.hpp"

#include <sstream>

#include "core/averaging/TimeBlocks.hpp"
#include "core/text/NumberText.hpp"

namespace grainbridge::workflows::report {

std::string timeBlockMeansCsv(const std::vector<double>& time, const std::vector<double>& values,
                              const std::string& column, double block) {
  std::ostringstream csv;
  csv << "block_start,block_end," << column << ",samples\n";
  for (const auto& b : core::averaging::timeBlockMeans(time, values, block)) {
    csv << core::roundTripText(b.start) << ',' << core::roundTripText(b.end) << ',' << core::roundTripText(b.mean)
        << ',' << b.samples << '\n';
  }
  return csv.str();
}

std::string heightProfilesCsv(const std::vector<double>& heights, const std::vector<HeightColumn>& columns) {
  std::ostringstream csv;
  csv << "height";
  for (const auto& column : columns) csv << ',' << column.name;
  csv << '\n';
  for (std::size_t k = 0; k < heights.size(); ++k) {
    csv << core::roundTripText(heights[k]);
    for (const auto& column : columns) csv << ',' << core::roundTripText(column.values.at(k));
    csv << '\n';
  }
  return csv.str();
}

}  // namespace grainbridge::workflows::report
