#pragma once
// The workflow report: an HTML page with, for each stage, one row per completed instance
// (swept parameters, summary values, stage key, links to its artifacts), the same table as
// CSV, and SVG plots (gnuplot) of every summary value that varies along a numeric sweep.
// Content is deterministic (no times, hosts or paths outside the results tree), so equal
// inputs give byte-equal reports whichever executor ran them.
#include <filesystem>
#include <string>
#include <vector>

#include "workflows/stages/StageContext.hpp"

namespace grainbridge::workflows::report {

struct ReportFiles {
  std::vector<stages::ArtifactEntry> files;  // paths relative to the output folder
};

// `outDir` is where files are written now; `publishedDir` is where they will finally live (for
// links to upstream artifacts: the two differ while a stage writes into its .partial folder).
ReportFiles writeHtmlReport(const std::string& title, const std::vector<stages::UpstreamInstance>& instances,
                            const std::filesystem::path& outDir, const std::filesystem::path& publishedDir);

}  // namespace grainbridge::workflows::report
