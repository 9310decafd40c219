#include "workflows/report/HtmlReport.hpp"

#include <cmath>
#include <cstdio>
#include <map>
#include <set>
#include <sstream>

#include "core/Error.hpp"
#include "core/Files.hpp"
#include "core/Log.hpp"
#include "core/io/XdmfText.hpp"
#include "workflows/report/CsvField.hpp"

namespace grainbridge::workflows::report {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

// The page's text goes through the same escaping as the XDMF sidecars.
std::string escapeHtml(const std::string& s) { return core::io::xmlEscape(s); }

std::string show(const json& v) { return v.is_string() ? v.get<std::string>() : v.dump(); }

// Six significant digits on the page; the CSV keeps every digit.
std::string showRounded(const json& v) {
  if (!v.is_number_float()) return show(v);
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", v.get<double>());
  return buf;
}

// Renders one plot with gnuplot; returns false (after a warning) if gnuplot is unavailable.
bool plotSvg(const fs::path& file, const std::string& xLabel, const std::string& yLabel,
             const std::vector<std::pair<double, double>>& points) {
  const std::string cmd = "gnuplot > '" + file.string() + "' 2>/dev/null";
  FILE* gp = ::popen(cmd.c_str(), "w");
  if (gp == nullptr) return false;
  std::ostringstream script;
  script << "set terminal svg size 480,360 font 'sans,11'\n"
         << "set xlabel '" << xLabel << "'\nset ylabel '" << yLabel << "'\n"
         << "set grid\nunset key\nplot '-' using 1:2 with linespoints pt 7\n";
  script.precision(17);
  for (const auto& [x, y] : points) script << x << ' ' << y << '\n';
  script << "e\n";
  const std::string text = script.str();
  std::fwrite(text.data(), 1, text.size(), gp);
  const int rc = ::pclose(gp);
  return rc == 0 && fs::exists(file) && fs::file_size(file) > 0;
}

}  // namespace

ReportFiles writeHtmlReport(const std::string& title, const std::vector<stages::UpstreamInstance>& instances,
                            const fs::path& outDir, const fs::path& publishedDir) {
  ReportFiles files;
  // Group instances by stage, keeping first-seen order.
  std::vector<std::string> stageOrder;
  std::map<std::string, std::vector<const stages::UpstreamInstance*>> byStage;
  for (const auto& inst : instances) {
    if (byStage.find(inst.stage) == byStage.end()) stageOrder.push_back(inst.stage);
    byStage[inst.stage].push_back(&inst);
  }

  std::ostringstream html;
  std::ostringstream csv;
  csv << "stage,stage_type,key,parameter,value\n";
  html << "<!DOCTYPE html>\n<html><head><meta charset=\"utf-8\"><title>" << escapeHtml(title) << "</title>\n"
       << "<style>body{font-family:sans-serif;margin:2em;max-width:80em}table{border-collapse:collapse;margin:1em 0}"
       << "td,th{border:1px solid #bbb;padding:.25em .6em;text-align:right}th{background:#eee}"
       << "td.l{text-align:left;font-family:monospace}img{margin:.5em}</style></head><body>\n"
       << "<h1>" << escapeHtml(title) << "</h1>\n"
       << "<p>Values are SI. Summary CSV: <a href=\"summary.csv\">summary.csv</a>. "
       << "Particle and field outputs (.xmf) open in ParaView; the database opens in sqlite3.</p>\n";

  for (const auto& stage : stageOrder) {
    const auto& list = byStage[stage];
    std::vector<std::string> sweepKeys;
    std::vector<std::string> summaryKeys;
    for (const auto* inst : list) {
      // Bound to locals: iterating items() of a temporary would outlive it.
      const json sweep = inst->manifest.value("sweep_point", json::object());
      const json summary = inst->manifest.value("summary", json::object());
      for (const auto& [k, v] : sweep.items()) {
        if (std::find(sweepKeys.begin(), sweepKeys.end(), k) == sweepKeys.end()) sweepKeys.push_back(k);
      }
      for (const auto& [k, v] : summary.items()) {
        if (std::find(summaryKeys.begin(), summaryKeys.end(), k) == summaryKeys.end()) summaryKeys.push_back(k);
      }
    }
    html << "<h2>Stage " << escapeHtml(stage) << " (" << escapeHtml(list.front()->stageType) << ", " << list.size()
         << " instance" << (list.size() == 1 ? "" : "s") << ")</h2>\n<table><tr>";
    for (const auto& k : sweepKeys) html << "<th>" << escapeHtml(k) << "</th>";
    for (const auto& k : summaryKeys) html << "<th>" << escapeHtml(k) << "</th>";
    html << "<th>key</th><th>artifacts</th></tr>\n";
    std::vector<std::string> figures;
    for (const auto* inst : list) {
      html << "<tr>";
      const json sweep = inst->manifest.value("sweep_point", json::object());
      const json summary = inst->manifest.value("summary", json::object());
      for (const auto& k : sweepKeys)
        html << "<td>" << (sweep.contains(k) ? escapeHtml(showRounded(sweep[k])) : "") << "</td>";
      for (const auto& k : summaryKeys)
        html << "<td>" << (summary.contains(k) ? escapeHtml(showRounded(summary[k])) : "") << "</td>";
      html << "<td class=\"l\">" << inst->key.substr(0, 12) << "</td><td class=\"l\">";
      const fs::path link = inst->dir.lexically_relative(publishedDir);
      const json artifacts = inst->manifest.value("artifacts", json::array());
      for (const auto& a : artifacts) {
        const std::string p = a.at("path");
        html << "<a href=\"" << escapeHtml((link / p).generic_string()) << "\">" << escapeHtml(p) << "</a> ";
      }
      html << "</td></tr>\n";
      // Figures an upstream stage drew (compare's plots) are shown under its table.
      for (const auto& a : artifacts) {
        if (a.value("kind", "") == "svg") {
          figures.push_back((link / a.at("path").get<std::string>()).generic_string());
        }
      }
      for (const auto& [k, v] : sweep.items())
        csv << csvField(stage) << ',' << csvField(inst->stageType) << ',' << inst->key << ",sweep." << csvField(k)
            << ',' << csvField(show(v)) << '\n';
      for (const auto& [k, v] : summary.items())
        csv << csvField(stage) << ',' << csvField(inst->stageType) << ',' << inst->key << ',' << csvField(k) << ','
            << csvField(show(v)) << '\n';
    }
    html << "</table>\n";
    for (const auto& f : figures) html << "<img src=\"" << escapeHtml(f) << "\" alt=\"" << escapeHtml(f) << "\">\n";

    // Plots: each summary value that varies, against the first numeric swept parameter.
    if (list.size() >= 2 && !sweepKeys.empty()) {
      const std::string x = sweepKeys.front();
      for (const auto& y : summaryKeys) {
        std::vector<std::pair<double, double>> points;
        std::set<double> ys;
        for (const auto* inst : list) {
          const json sweep = inst->manifest.value("sweep_point", json::object());
          const json summary = inst->manifest.value("summary", json::object());
          if (sweep.contains(x) && sweep[x].is_number() && summary.contains(y) && summary[y].is_number()) {
            points.emplace_back(sweep[x].get<double>(), summary[y].get<double>());
            ys.insert(summary[y].get<double>());
          }
        }
        // Values equal up to round-off (a temperature set exactly by construction) are no plot.
        const double spread = ys.empty() ? 0.0 : *ys.rbegin() - *ys.begin();
        const double scale = ys.empty() ? 0.0 : std::max(std::abs(*ys.rbegin()), std::abs(*ys.begin()));
        if (points.size() < 2 || spread <= 1e-9 * scale) continue;
        std::sort(points.begin(), points.end());
        const std::string name = "plot_" + stage + "_" + y + ".svg";
        if (!plotSvg(outDir / name, x, y, points)) {
          throw Error("gnuplot could not draw " + name + " (is gnuplot installed? Debian package gnuplot-nox)");
        }
        files.files.push_back({name, "svg"});
        html << "<img src=\"" << escapeHtml(name) << "\" alt=\"" << escapeHtml(y + " against " + x) << "\">\n";
      }
    }
  }
  html << "</body></html>\n";
  core::writeFileAtomically(outDir / "report.html", html.str());
  core::writeFileAtomically(outDir / "summary.csv", csv.str());
  files.files.insert(files.files.begin(), {{"report.html", "report_html"}, {"summary.csv", "csv"}});
  return files;
}

}  // namespace grainbridge::workflows::report
