#pragma once
// The workflow report (issue 16): one HTML page a researcher opens first.
//   1. Findings: every stage that set findings (compare: DEM against each kinetic-theory model)
//      leads with its headline, its table and its figures, on the first screen.
//   2. Per stage: what is the same in every instance on one line, then one compact row per
//      instance (the swept parameters as the config wrote them, the stage's key results with
//      their errors, its outputs summarised: file count, size, one link to the folder and one to
//      the .xmf ParaView opens), the full columns in stage_<name>.csv, and plots of each key
//      result that varies along a numeric sweep (workflows/report/Plot).
//   3. A footer with the code and library versions and the workflow's database.
// summary.csv keeps every summary value at full precision (long format). The page has no
// times or hosts, so equal inputs give equal reports whichever executor ran them; only the
// footer changes with the build.
#include <filesystem>
#include <string>
#include <vector>

#include "workflows/contract/Findings.hpp"
#include "workflows/contract/UpstreamInstance.hpp"

namespace grainbridge::workflows::report {

// A stage's findings are a product of its instance (workflows/contract).
using contract::Findings;
using contract::FindingsFigure;

struct ReportPage {
  std::string title;
  std::string database;  // the workflow database's path, for the footer
  contract::StageTypeLookup stageTypes;  // key results and parameter units per stage type
};

struct ReportFiles {
  std::vector<contract::ArtifactEntry> files;  // paths relative to the output folder
  std::vector<Findings> findings;            // what the page leads with, in page order
};

// `outDir` is where files are written now; `publishedDir` is where they will finally live (for
// links to upstream artifacts: the two differ while a stage writes into its .partial folder).
ReportFiles writeHtmlReport(const ReportPage& page, const std::vector<contract::UpstreamInstance>& instances,
                            const std::filesystem::path& outDir, const std::filesystem::path& publishedDir);

}  // namespace grainbridge::workflows::report
