#include "workflows/report/FindingsPage.hpp"

#include <sstream>

#include "core/Files.hpp"
#include "core/io/XdmfText.hpp"

namespace grainbridge::workflows::report {

void writeFindingsPage(const Findings& findings, const std::string& csv, const std::filesystem::path& file) {
  using core::io::xmlEscape;
  std::ostringstream html;
  const std::string title = xmlEscape(findings.title);
  html << "<!DOCTYPE html>\n<html><head><meta charset=\"utf-8\"><title>" << title
       << "</title><style>body{font-family:sans-serif;margin:1.5em;max-width:90em}table{border-collapse:collapse}"
       << "td,th{border:1px solid #ccc;padding:0.2em 0.5em}img{max-width:100%}</style></head><body>\n<h1>" << title
       << "</h1>\n<p>" << xmlEscape(findings.headline) << "</p>\n<table><tr>";
  for (const auto& c : findings.columns) html << "<th>" << xmlEscape(c) << "</th>";
  html << "</tr>\n";
  for (const auto& row : findings.rows) {
    html << "<tr>";
    for (const auto& c : row) html << "<td>" << xmlEscape(c) << "</td>";
    html << "</tr>\n";
  }
  html << "</table>\n<p>Every number: <a href=\"" << xmlEscape(csv) << "\">" << xmlEscape(csv)
       << "</a>. PNG copies for slides sit beside each SVG.</p>\n";
  for (const auto& f : findings.figures) {
    html << "<p><a href=\"" << f.png << "\"><img src=\"" << f.svg << "\" alt=\"" << xmlEscape(f.caption)
         << "\"></a><br>" << xmlEscape(f.caption) << "</p>\n";
  }
  html << "</body></html>\n";
  core::writeFileAtomically(file, html.str());
}

}  // namespace grainbridge::workflows::report
