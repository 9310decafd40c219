#pragma once
// What a stage found, in the words and figures a report leads with (issue 16): a headline
// sentence, a small table (one line per row: which model, how far, where) and the figures that
// show it. A comparing stage sets it (StageContext::setFindings); it travels in the instance's
// manifest.json under "findings", and `report` and `grainbridge report` show every stage's
// findings first, whatever the stage type.
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace grainbridge::workflows::contract {

struct FindingsFigure {
  std::string svg, png;  // relative to the stage's instance folder
  std::string caption;
  bool wide = false;  // takes a page's full width (several runs against time), not a column
};

struct Findings {
  std::string title;                           // "DEM closures against kinetic theory"
  std::string headline;                        // one or two sentences, numbers with their units and where
  std::vector<std::string> columns;            // the headline table's heading
  std::vector<std::vector<std::string>> rows;  // as many cells as columns
  std::vector<FindingsFigure> figures;         // the first `firstScreen` lead the page
  int firstScreen = 3;
  std::string details;  // a fuller page of the stage's own, relative to its folder ("" if none)

  [[nodiscard]] bool empty() const { return headline.empty() && figures.empty(); }
  [[nodiscard]] nlohmann::json toJson() const;
  // Throws grainbridge::Error naming the field when `j` is not a findings object.
  static Findings fromJson(const nlohmann::json& j);
};

// The headline and table as plain text (for a terminal), columns aligned.
std::string findingsText(const Findings& findings);

}  // namespace grainbridge::workflows::contract
