#pragma once
// A comparing stage's own page (bed_compare.html, ...): its findings' title, headline, table and
// figures with their captions, and a link to the CSV that holds every number. The workflow report
// (HtmlReport) leads with the same findings and links here for the details.
#include <filesystem>
#include <string>

#include "workflows/contract/Findings.hpp"

namespace grainbridge::workflows::report {

// A stage's findings are a product of its instance (workflows/contract).
using contract::Findings;
using contract::FindingsFigure;

// Writes the page to `file` atomically; `csv` is the CSV's name relative to the page.
void writeFindingsPage(const Findings& findings, const std::string& csv, const std::filesystem::path& file);

}  // namespace grainbridge::workflows::report
