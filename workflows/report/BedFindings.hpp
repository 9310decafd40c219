#pragma once
// The numbers of a comparison of bed runs (the bed_compare stage): beds.csv for programs and the
// findings table and headline for the report, both from the runs' products (BedRun).
#include <string>
#include <vector>

#include "workflows/contract/Findings.hpp"
#include "workflows/report/BedRun.hpp"

namespace grainbridge::workflows::report {

// A stage's findings are a product of its instance (workflows/contract).
using contract::Findings;
using contract::FindingsFigure;

// beds.csv: one row per run and reference value matched to it (a run without any: one row), in
// `referenceLabels` order; full precision, an empty field for a value the run did not record.
[[nodiscard]] std::string bedsCsv(const std::vector<BedRun>& runs, const std::vector<std::string>& referenceLabels);

// The findings' headline and table (a row per run, a column per reference label); no figures.
[[nodiscard]] Findings bedFindings(const std::vector<BedRun>& runs, const std::vector<std::string>& referenceLabels,
                                   const std::string& title);

}  // namespace grainbridge::workflows::report
