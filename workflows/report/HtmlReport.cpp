#include "workflows/report/HtmlReport.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <sstream>

#include "core/ClosureForms.hpp"
#include "core/Error.hpp"
#include "core/Files.hpp"
#include "core/io/XdmfText.hpp"
#include "core/text/NumberText.hpp"
#include "workflows/report/BuildDescription.hpp"
#include "workflows/report/CsvField.hpp"
#include "workflows/report/Plot.hpp"

namespace grainbridge::workflows::report {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

// The page's text goes through the same escaping as the XDMF sidecars.
std::string esc(const std::string& s) { return core::io::xmlEscape(s); }

constexpr std::size_t kMaxDefaultColumns = 6;  // summary columns of a stage that declares none
constexpr std::size_t kMaxCommonValues = 10;   // "same in every instance" entries on one line

const char* const kStyle =
    "body{font-family:system-ui,sans-serif;font-size:14px;margin:.8em 1.5em;max-width:1400px;color:#222}"
    "h1{font-size:1.45em;margin:.2em 0}h2{font-size:1.15em;margin:1.1em 0 .3em}"
    "h2 small{font-weight:normal;color:#666}p{margin:.3em 0}.meta{color:#555}"
    "#findings{border:1px solid #c9d6e3;background:#f7fafd;padding:.3em .9em .6em;margin:.6em 0}"
    "#findings h2{margin-top:.3em}.headline{font-size:1.05em}"
    "table{border-collapse:collapse;margin:.4em 0;font-size:13px}"
    "td,th{border:1px solid #ccc;padding:.15em .5em;text-align:right;white-space:nowrap}"
    "th{background:#eef1f4;font-weight:600}td.l,th.l{text-align:left}"
    ".si{color:#777;font-size:.9em}.common{color:#444;font-size:13px}"
    ".figures{display:grid;grid-template-columns:repeat(3,minmax(0,1fr));gap:.4em;margin:.4em 0}"
    ".figures figure{margin:0}.figures figure.wide{grid-column:1/-1}.figures img{width:100%;height:auto;display:block}"
    "footer{margin-top:2em;border-top:1px solid #ccc;padding-top:.4em;color:#666;font-size:12px}";

// A column heading: a closure form's symbol (p*, τ*), else the summary key as written.
std::string heading(const std::string& key, const std::string& unit) {
  std::string name = key;
  if (auto form = core::closureFormFromName(key)) name = std::string(core::closureFormInfo(*form).symbol);
  return unit.empty() || unit == "–" ? name : name + " [" + unit + "]";
}

struct StageGroup {
  std::string stage, type;
  std::vector<const contract::UpstreamInstance*> instances;
};

std::vector<StageGroup> groupByStage(const std::vector<contract::UpstreamInstance>& instances) {
  std::vector<StageGroup> groups;
  for (const auto& inst : instances) {
    auto it = std::find_if(groups.begin(), groups.end(), [&](const StageGroup& g) { return g.stage == inst.stage(); });
    if (it == groups.end()) {
      groups.push_back({inst.stage(), inst.stageTypeLabel(), {}});
      it = groups.end() - 1;
    }
    it->instances.push_back(&inst);
  }
  return groups;
}

json summaryOf(const contract::UpstreamInstance& inst) { return inst.summary(); }
json sweepOf(const contract::UpstreamInstance& inst) { return inst.sweepPoint(); }
json writtenSweepOf(const contract::UpstreamInstance& inst) { return inst.sweepWritten(); }

// Keys in first-seen order over every instance.
std::vector<std::string> keysOf(const StageGroup& g, json (*of)(const contract::UpstreamInstance&)) {
  std::vector<std::string> keys;
  for (const auto* inst : g.instances) {
    const json values = of(*inst);  // bound: items() of a temporary would outlive it
    for (const auto& [k, v] : values.items()) {
      if (std::find(keys.begin(), keys.end(), k) == keys.end()) keys.push_back(k);
    }
  }
  return keys;
}

bool variesAcross(const StageGroup& g, const std::string& key) {
  const json first = summaryOf(*g.instances.front()).value(key, json());
  return std::any_of(g.instances.begin(), g.instances.end(),
                     [&](const auto* inst) { return summaryOf(*inst).value(key, json()) != first; });
}

bool isError(const std::string& key) { return key.size() > 4 && key.ends_with("_err"); }

// The summary columns the table shows: the stage type's key results that vary, or, for a type
// that declares none, the first few values that vary. Constant values go to the common line.
std::vector<contract::ResultColumn> shownColumns(const StageGroup& g, const std::optional<contract::StageTypeView>& type) {
  const auto keys = keysOf(g, summaryOf);
  std::vector<contract::ResultColumn> out;
  const auto declared = type ? type->keyResults : std::vector<contract::ResultColumn>{};
  if (!declared.empty()) {
    for (const auto& c : declared) {
      if (std::find(keys.begin(), keys.end(), c.key) != keys.end() &&
          (g.instances.size() == 1 || variesAcross(g, c.key)))
        out.push_back(c);
    }
    return out;
  }
  const auto replicaKeys = type ? type->replicaKeys : std::vector<std::string>{};
  for (const auto& k : keys) {
    if (out.size() == kMaxDefaultColumns) break;
    if (std::find(replicaKeys.begin(), replicaKeys.end(), k) != replicaKeys.end()) continue;  // beside the sweep
    if (!isError(k) && (g.instances.size() == 1 || variesAcross(g, k))) out.push_back({k, ""});
  }
  return out;
}

// The summary values that tell the replicas of a sweep point apart (closure samples), where any
// instance records one: shown beside the sweep point, empty for the instance itself.
std::vector<std::string> replicaColumns(const StageGroup& g, const std::optional<contract::StageTypeView>& type) {
  std::vector<std::string> out;
  if (!type) return out;
  const auto keys = keysOf(g, summaryOf);
  for (const auto& k : type->replicaKeys) {
    if (std::find(keys.begin(), keys.end(), k) != keys.end()) out.push_back(k);
  }
  return out;
}

std::string cellValue(const json& summary, const std::string& key) {
  if (!summary.contains(key)) return "";
  const json& v = summary[key];
  const std::string err = key + "_err";
  if (v.is_number() && summary.contains(err) && summary[err].is_number()) {
    return core::humanWithError(v.get<double>(), summary[err].get<double>());
  }
  return core::humanText(v);
}

// The SI unit of a swept parameter ("m", "" when dimensionless or unknown).
std::string sweptUnit(const std::optional<contract::StageTypeView>& type, const std::string& param) {
  return type && type->sweptUnit ? type->sweptUnit(param) : "";
}

// A swept value as the config wrote it, with its SI value beside it when the two differ.
std::string sweptCell(const json& written, const json& si, const std::string& unit) {
  const std::string shown = core::humanText(written);
  std::string siText = core::humanText(si);
  if (!unit.empty() && unit != "1") siText += " " + unit;
  if (!written.is_string() && !(written.is_array() && !written.empty() && written.front().is_string()))
    return esc(shown);
  return esc(shown) + " <span class=\"si\">" + esc(siText) + "</span>";
}

// Outputs of one instance on one line: counts, size, the folder and the first .xmf.
std::string outputsCell(const contract::UpstreamInstance& inst, const fs::path& link) {
  const auto artifacts = inst.artifacts();
  std::uintmax_t bytes = 0;
  std::string xmf;
  for (const auto& a : artifacts) {
    std::error_code ec;
    const auto size = fs::file_size(inst.dir() / a.path, ec);
    if (!ec) bytes += size;
    if (xmf.empty() && a.path.ends_with(".xmf")) xmf = a.path;
  }
  std::string cell = std::to_string(artifacts.size()) + " file" + (artifacts.size() == 1 ? "" : "s") + ", " +
                     core::humanBytes(bytes) + " · <a href=\"" + esc(link.generic_string() + "/") + "\">folder</a>";
  if (!xmf.empty()) {
    cell += " · <a href=\"" + esc((link / xmf).generic_string()) + "\" title=\"open in ParaView\">" + esc(xmf) + "</a>";
  }
  return cell;
}

// A figure links to its PNG (for slides); it carries its own title, so the caption is alt text.
std::string figureHtml(const std::string& svg, const std::string& png, const std::string& caption, bool wide = false) {
  std::string out = std::string(wide ? "<figure class=\"wide\">" : "<figure>") + "<a href=\"" +
                    esc(png.empty() ? svg : png) + "\"><img src=\"" + esc(svg) + "\" alt=\"" + esc(caption) + "\"></a>";
  return out + "</figure>\n";
}

void writeFindings(std::ostringstream& html, const Findings& f, const fs::path& link, const std::string& stage,
                   bool first) {
  html << "<h2>" << esc(f.title.empty() ? stage : f.title) << " <small>stage " << esc(stage) << "</small></h2>\n";
  if (!f.headline.empty()) html << "<p class=\"headline\">" << esc(f.headline) << "</p>\n";
  if (!f.columns.empty()) {
    html << "<table class=\"findings\"><tr>";
    for (std::size_t c = 0; c < f.columns.size(); ++c)
      html << "<th" << (c == 0 ? " class=\"l\"" : "") << ">" << esc(f.columns[c]) << "</th>";
    html << "</tr>\n";
    for (const auto& row : f.rows) {
      html << "<tr>";
      for (std::size_t c = 0; c < row.size(); ++c)
        html << "<td" << (c == 0 ? " class=\"l\"" : "") << ">" << esc(row[c]) << "</td>";
      html << "</tr>\n";
    }
    html << "</table>\n";
  }
  const std::size_t lead =
      std::min<std::size_t>(f.figures.size(), static_cast<std::size_t>(std::max(0, f.firstScreen)));
  auto figures = [&](std::size_t from, std::size_t to, const char* cls) {
    if (from >= to) return;
    html << "<div class=\"" << cls << "\">\n";
    for (std::size_t i = from; i < to; ++i) {
      const auto& fig = f.figures[i];
      html << figureHtml((link / fig.svg).generic_string(), fig.png.empty() ? "" : (link / fig.png).generic_string(),
                         fig.caption, fig.wide);
    }
    html << "</div>\n";
  };
  figures(0, lead, first ? "figures first-screen" : "figures");
  figures(lead, f.figures.size(), "figures");
  if (!f.details.empty()) {
    html << "<p>Details: <a href=\"" << esc((link / f.details).generic_string()) << "\">" << esc(f.details)
         << "</a> (every figure has a PNG copy for slides: click it).</p>\n";
  }
}

}  // namespace

ReportFiles writeHtmlReport(const ReportPage& page, const std::vector<contract::UpstreamInstance>& instances,
                            const fs::path& outDir, const fs::path& publishedDir) {
  ReportFiles files;
  const auto groups = groupByStage(instances);

  std::ostringstream html;
  html << "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">"
       << "<meta name=\"viewport\" content=\"width=device-width\"><title>" << esc(page.title) << "</title>\n<style>"
       << kStyle << "</style></head><body>\n<h1>" << esc(page.title) << "</h1>\n<p class=\"meta\">" << groups.size()
       << " stage" << (groups.size() == 1 ? "" : "s") << ", " << instances.size() << " instance"
       << (instances.size() == 1 ? "" : "s")
       << ". Values in SI unless a heading says otherwise; every value at full precision in "
       << "<a href=\"summary.csv\">summary.csv</a>. Frames (.xmf) open in ParaView.</p>\n";

  // 1. What the workflow found.
  bool firstFinding = true;
  std::ostringstream findingsHtml;
  for (const auto& g : groups) {
    for (const auto* inst : g.instances) {
      const auto found = inst->findings();
      if (!found || found->empty()) continue;
      const Findings& f = *found;
      writeFindings(findingsHtml, f, inst->dir().lexically_relative(publishedDir), g.stage, firstFinding);
      firstFinding = false;
      files.findings.push_back(f);
    }
  }
  if (!files.findings.empty()) html << "<section id=\"findings\">\n" << findingsHtml.str() << "</section>\n";

  // 2. Per stage.
  std::ostringstream csv;
  csv << "stage,stage_type,key,parameter,value\n";
  for (const auto& g : groups) {
    const auto type = page.stageTypes ? page.stageTypes(g.type) : std::nullopt;
    const auto sweepKeys = keysOf(g, sweepOf);
    const auto replicaKeys = replicaColumns(g, type);
    const auto columns = shownColumns(g, type);
    html << "<section class=\"stage\" id=\"stage-" << esc(g.stage) << "\">\n<h2>Stage " << esc(g.stage) << " <small>"
         << esc(g.type) << ", " << g.instances.size() << " instance" << (g.instances.size() == 1 ? "" : "s")
         << "</small></h2>\n";

    // What is the same everywhere: one line instead of a column each.
    if (g.instances.size() > 1) {
      std::vector<std::string> common;
      for (const auto& k : keysOf(g, summaryOf)) {
        if (isError(k) || variesAcross(g, k)) continue;
        const json v = summaryOf(*g.instances.front()).value(k, json());
        if (!v.is_null()) common.push_back(k + " " + cellValue(summaryOf(*g.instances.front()), k));
      }
      if (!common.empty()) {
        html << "<p class=\"common\">Same in every instance: ";
        for (std::size_t i = 0; i < common.size() && i < kMaxCommonValues; ++i)
          html << (i ? " · " : "") << esc(common[i]);
        if (common.size() > kMaxCommonValues)
          html << " · … (" << common.size() - kMaxCommonValues << " more in the CSV)";
        html << "</p>\n";
      }
    }

    html << "<table class=\"instances\"><tr>";
    for (const auto& k : sweepKeys) html << "<th>" << esc(k) << "</th>";
    for (const auto& k : replicaKeys) html << "<th>" << esc(k) << "</th>";
    for (const auto& c : columns) html << "<th>" << esc(heading(c.key, c.unit)) << "</th>";
    html << "<th class=\"l\">outputs</th><th class=\"l\">key</th></tr>\n";
    for (const auto* inst : g.instances) {
      const json sweep = sweepOf(*inst);
      const json written = writtenSweepOf(*inst);
      const json summary = summaryOf(*inst);
      html << "<tr>";
      for (const auto& k : sweepKeys) {
        html << "<td>" << (sweep.contains(k) ? sweptCell(written.value(k, sweep[k]), sweep[k], sweptUnit(type, k)) : "")
             << "</td>";
      }
      for (const auto& k : replicaKeys) html << "<td>" << esc(cellValue(summary, k)) << "</td>";
      for (const auto& c : columns) html << "<td>" << esc(cellValue(summary, c.key)) << "</td>";
      const fs::path link = inst->dir().lexically_relative(publishedDir);
      html << "<td class=\"l\">" << outputsCell(*inst, link) << "</td><td class=\"l\"><code>"
           << esc(inst->shortKey()) << "</code></td></tr>\n";
      for (const auto& [k, v] : sweep.items())
        csv << csvField(g.stage) << ',' << csvField(g.type) << ',' << inst->key() << ",sweep." << csvField(k) << ','
            << csvField(v.is_string() ? v.get<std::string>() : v.dump()) << '\n';
      for (const auto& [k, v] : summary.items())
        csv << csvField(g.stage) << ',' << csvField(g.type) << ',' << inst->key() << ',' << csvField(k) << ','
            << csvField(v.is_string() ? v.get<std::string>() : v.dump()) << '\n';
    }
    html << "</table>\n";

    // Figures a stage drew that are not among its findings.
    std::vector<std::string> figureLinks;
    for (const auto* inst : g.instances) {
      std::set<std::string> inFindings;
      if (const auto found = inst->findings()) {
        for (const auto& f : found->figures) inFindings.insert(f.svg);
      }
      for (const auto& a : inst->artifacts()) {
        if (a.kind == "svg" && !inFindings.contains(a.path))
          figureLinks.push_back((inst->dir().lexically_relative(publishedDir) / a.path).generic_string());
      }
    }

    // Plots: each key result that varies, against the first numeric swept parameter.
    std::ostringstream plots;
    if (g.instances.size() >= 2 && !sweepKeys.empty() && type && !type->keyResults.empty()) {
      const std::string x = sweepKeys.front();
      for (const auto& c : columns) {
        Series series;
        series.label = g.stage;
        series.model = g.type;
        series.style = Series::Style::PointsWithErrors;
        std::vector<std::array<double, 3>> points;
        for (const auto* inst : g.instances) {
          const json sweep = sweepOf(*inst);
          const json summary = summaryOf(*inst);
          if (sweep.contains(x) && sweep[x].is_number() && summary.contains(c.key) && summary[c.key].is_number()) {
            const std::string err = c.key + "_err";
            points.push_back({sweep[x].get<double>(), summary[c.key].get<double>(),
                              summary.contains(err) && summary[err].is_number() ? summary[err].get<double>() : 0.0});
          }
        }
        if (points.size() < 2) continue;
        // Values equal up to round-off (a temperature set exactly by construction) are no plot.
        const auto [lo, hi] =
            std::minmax_element(points.begin(), points.end(), [](const auto& a, const auto& b) { return a[1] < b[1]; });
        if ((*hi)[1] - (*lo)[1] <= 1e-9 * std::max(std::abs((*hi)[1]), std::abs((*lo)[1]))) continue;
        std::sort(points.begin(), points.end());
        for (const auto& p : points) {
          series.x.push_back(p[0]);
          series.y.push_back(p[1]);
          series.yError.push_back(p[2]);
        }
        Figure fig;
        fig.title = heading(c.key, "") + " against " + x + " (stage " + g.stage + ")";
        const std::string xUnit = sweptUnit(type, x);
        fig.x = {x, xUnit.empty() || xUnit == "1" ? "–" : xUnit};
        fig.y = {heading(c.key, ""), c.unit};
        fig.series.push_back(std::move(series));
        const auto drawn = drawFigure(fig, outDir, "plot_" + g.stage + "_" + c.key);
        files.files.push_back({drawn.svg, "svg"});
        files.files.push_back({drawn.png, "png"});
        plots << figureHtml(drawn.svg, drawn.png, fig.title);
      }
    }
    if (!figureLinks.empty() || !plots.str().empty()) {
      html << "<div class=\"figures\">\n";
      for (const auto& f : figureLinks) html << figureHtml(f, "", "");
      html << plots.str() << "</div>\n";
    }

    // Every column of every instance, full precision.
    std::ostringstream stageCsv;
    const auto summaryKeys = keysOf(g, summaryOf);
    stageCsv << "key";
    for (const auto& k : sweepKeys) stageCsv << ',' << csvField("sweep." + k);
    for (const auto& k : summaryKeys) stageCsv << ',' << csvField(k);
    stageCsv << '\n';
    for (const auto* inst : g.instances) {
      const json sweep = sweepOf(*inst);
      const json summary = summaryOf(*inst);
      stageCsv << inst->key();
      for (const auto& k : sweepKeys) stageCsv << ',' << csvValue(sweep.value(k, json()));
      for (const auto& k : summaryKeys) stageCsv << ',' << csvValue(summary.value(k, json()));
      stageCsv << '\n';
    }
    const std::string stageCsvName = "stage_" + g.stage + ".csv";
    core::writeFileAtomically(outDir / stageCsvName, stageCsv.str());
    files.files.push_back({stageCsvName, "csv"});
    html << "<p class=\"common\">Every column: <a href=\"" << esc(stageCsvName) << "\">" << esc(stageCsvName)
         << "</a></p>\n</section>\n";
  }

  // 3. What made this page, and where its database is.
  html << "<footer>Made by " << esc(codeDescription()) << " with " << esc(librariesDescription()) << ".";
  if (!page.database.empty()) html << " Database: <code>" << esc(page.database) << "</code>.";
  html << "</footer>\n</body></html>\n";
  core::writeFileAtomically(outDir / "report.html", html.str());
  core::writeFileAtomically(outDir / "summary.csv", csv.str());
  files.files.insert(files.files.begin(), {{"report.html", "report_html"}, {"summary.csv", "csv"}});
  return files;
}

}  // namespace grainbridge::workflows::report
