#pragma once
// A comparing stage's own page (bed_compare.html, ...): its findings' title, headline, table and
// figures with their captions, and a link to the CSV that holds every number. The workflow report
// (HtmlReport) leads with the same findings and links here for the details.
#include <filesystem>
#include <string>

#include "workflows/report/Findings.hpp"

namespace grainbridge::workflows::report {

// Writes the page to `file` atomically; `csv` is the CSV's name relative to the page.
void writeFindingsPage(const Findings& findings, const std::string& csv, const std::filesystem::path& file);

}  // namespace grainbridge::workflows::report
