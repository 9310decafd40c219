#include "workflows/contract/Findings.hpp"

#include <algorithm>

#include "core/Error.hpp"

namespace grainbridge::workflows::contract {

using nlohmann::json;

json Findings::toJson() const {
  json figs = json::array();
  for (const auto& f : figures) {
    figs.push_back({{"svg", f.svg}, {"png", f.png}, {"caption", f.caption}});
    if (f.wide) figs.back()["wide"] = true;  // absent when not: older manifests read the same
  }
  return {{"title", title},  {"headline", headline},        {"columns", columns}, {"rows", rows},
          {"figures", figs}, {"first_screen", firstScreen}, {"details", details}};
}

Findings Findings::fromJson(const json& j) {
  try {
    Findings f;
    f.title = j.value("title", "");
    f.headline = j.value("headline", "");
    f.columns = j.value("columns", std::vector<std::string>{});
    f.rows = j.value("rows", std::vector<std::vector<std::string>>{});
    for (const auto& fig : j.value("figures", json::array())) {
      f.figures.push_back({fig.at("svg"), fig.value("png", ""), fig.value("caption", ""), fig.value("wide", false)});
    }
    f.firstScreen = j.value("first_screen", 3);
    f.details = j.value("details", "");
    return f;
  } catch (const json::exception& e) {
    throw Error(std::string("manifest findings: ") + e.what());
  }
}

std::string findingsText(const Findings& f) {
  std::string out = f.title.empty() ? "" : f.title + "\n";
  if (!f.headline.empty()) out += "  " + f.headline + "\n";
  if (f.columns.empty()) return out;
  // Widths in code points, so UTF-8 symbols (τ*, φ) align.
  auto width = [](const std::string& s) {
    return static_cast<std::size_t>(std::count_if(s.begin(), s.end(), [](char c) { return (c & 0xC0) != 0x80; }));
  };
  std::vector<std::size_t> widths(f.columns.size(), 0);
  for (std::size_t c = 0; c < f.columns.size(); ++c) widths[c] = width(f.columns[c]);
  for (const auto& row : f.rows)
    for (std::size_t c = 0; c < row.size() && c < widths.size(); ++c) widths[c] = std::max(widths[c], width(row[c]));
  auto line = [&](const std::vector<std::string>& cells) {
    std::string s = "  ";
    for (std::size_t c = 0; c < cells.size() && c < widths.size(); ++c) {
      s += cells[c] + std::string(widths[c] - width(cells[c]) + 2, ' ');
    }
    while (!s.empty() && s.back() == ' ') s.pop_back();
    return s + "\n";
  };
  out += line(f.columns);
  for (const auto& row : f.rows) out += line(row);
  return out;
}

}  // namespace grainbridge::workflows::contract
