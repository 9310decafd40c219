#pragma once
// The CSV tables a bed run writes beside its series (the mfm stage), as text: what a comparing
// stage or a spreadsheet reads back (report/NumericCsv), every number in round-trip precision.
#include <string>
#include <vector>

namespace grainbridge::workflows::report {

// block_start,block_end,<column>,samples: the means of `values` (sampled at `time`) over
// consecutive blocks of `block` seconds from time 0 (core/averaging/TimeBlocks), e.g. s_p's 1 s
// means, the experiment's reporting.
[[nodiscard]] std::string timeBlockMeansCsv(const std::vector<double>& time, const std::vector<double>& values,
                                            const std::string& column, double block);

// A named column against height.
struct HeightColumn {
  std::string name;
  std::vector<double> values;
};

// height,<name>,...: columns sampled at the same heights, e.g. each phase's eps_s over the width.
[[nodiscard]] std::string heightProfilesCsv(const std::vector<double>& heights, const std::vector<HeightColumn>& columns);

}  // namespace grainbridge::workflows::report
