#include "workflows/report/BedFigures.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "core/Error.hpp"
#include "workflows/contract/NumericCsv.hpp"

namespace grainbridge::workflows::report {

using contract::readNumericCsv;

namespace {

// The sample times all of an arm's runs share, and each run's sample index at each of them.
struct CommonTimes {
  std::vector<double> times;
  std::vector<std::vector<std::size_t>> index;  // [run of the arm][common time]
};

CommonTimes commonTimes(const std::vector<BedRun>& runs, const Arm& arm) {
  const auto timeOf = [&](std::size_t r) -> const std::vector<double>& {
    const auto time = runs.at(r).series.find("time");
    if (time == runs.at(r).series.end()) throw Error("bed figures: the series of " + runs.at(r).label + " has no time");
    return time->second;
  };
  CommonTimes common;
  common.times = timeOf(arm.runs.front());
  common.index.emplace_back(common.times.size());
  std::iota(common.index.front().begin(), common.index.front().end(), std::size_t{0});
  for (std::size_t i = 1; i < arm.runs.size(); ++i) {
    const std::vector<double>& t = timeOf(arm.runs[i]);
    CommonTimes kept;
    kept.index.resize(i + 1);
    std::size_t j = 0;
    for (std::size_t k = 0; k < common.times.size(); ++k) {
      // Equal times as written (round-trip text), up to a sum of steps' rounding.
      const double tolerance = 1e-9 * std::max(1.0, std::abs(common.times[k]));
      while (j < t.size() && t[j] < common.times[k] - tolerance) ++j;
      if (j == t.size() || std::abs(t[j] - common.times[k]) > tolerance) continue;
      kept.times.push_back(common.times[k]);
      for (std::size_t p = 0; p < i; ++p) kept.index[p].push_back(common.index[p][k]);
      kept.index[i].push_back(j);
    }
    common = std::move(kept);
  }
  if (common.times.size() < 2) {
    std::string names;
    for (const std::size_t r : arm.runs) names += (names.empty() ? "" : ", ") + runs.at(r).label;
    throw Error("bed figures: the realisations of " + arm.label + " (" + names + ") share " +
                std::to_string(common.times.size()) +
                " sample time(s) in their series' time column: give them one output_interval");
  }
  return common;
}

// A series drawn in run `b`'s own colour.
Series runSeries(const BedRun& run, std::size_t b, std::string label, Series::Style style, int variant,
                 std::vector<double> x = {}, std::vector<double> y = {}) {
  return {std::move(label), run.closure, style, variant, std::move(x), std::move(y), {}, runColour(b)};
}

// The reference curves of one output, as points in their kind's colour, each labelled with its
// citation; a point shape each.
void addReferenceSeries(Figure& figure, const std::vector<ReferenceSeries>& references, const std::string& output) {
  int variant = 0;
  for (const auto& r : references) {
    if (r.output != output) continue;
    figure.series.push_back(
        {r.label + " (" + r.citation + ")", r.kind, Series::Style::Points, variant++, r.time, r.value, {}});
  }
}

}  // namespace

Figure averagedHeightFigure(const std::vector<BedRun>& runs) {
  Figure figure{"Time-averaged mean particle height", {"run", "", false, {}}, {"mean particle height", "m"}, {}};
  std::map<std::string, Series> byReference;
  std::vector<Series> byRun;
  for (std::size_t b = 0; b < runs.size(); ++b) {
    const BedRun& run = runs[b];
    figure.x.categories.push_back(run.category);
    Series points = runSeries(run, b, run.shortLabel, Series::Style::PointsWithErrors, 0);
    points.x.push_back(static_cast<double>(b + 1));
    points.y.push_back(run.meanHeight);
    points.yError.push_back(std::isfinite(run.meanHeightError) ? run.meanHeightError : 0.0);
    byRun.push_back(std::move(points));
    // A particle run's mean height is its particles'; Eq. 5.22 of its deposited fraction beside it.
    if (const double deposited = run.value("mean_height_fields"); std::isfinite(deposited)) {
      Series fields = runSeries(run, b, run.shortLabel + ", Eq. 5.22 of the deposited fraction",
                                Series::Style::PointsWithErrors, 1);
      fields.x.push_back(static_cast<double>(b + 1) - 0.2);
      fields.y.push_back(deposited);
      const double err = run.value("mean_height_fields_err");
      fields.yError.push_back(std::isfinite(err) ? err : 0.0);
      byRun.push_back(std::move(fields));
    }
    // Beside it, the spread its closure samples give (the DEM closures' statistical error).
    if (const auto it = run.closureSpreads.find("mean_height"); it != run.closureSpreads.end()) {
      Series spread =
          runSeries(run, b, run.shortLabel + ", spread over the closure samples", Series::Style::PointsWithErrors, 2);
      spread.x.push_back(static_cast<double>(b + 1) + 0.2);
      spread.y.push_back(run.meanHeight);
      spread.yError.push_back(it->second.spread);
      byRun.push_back(std::move(spread));
    }
    for (const auto& r : run.references) {
      const bool first = !byReference.contains(r.label);
      auto& ref = byReference[r.label];
      if (first) {  // a point shape per reference label, kept for all its runs
        ref.label = r.label;
        ref.model = r.kind;
        ref.style = Series::Style::Points;
        ref.variant = static_cast<int>(byReference.size());
      }
      ref.x.push_back(static_cast<double>(b + 1));
      ref.y.push_back(r.height);
    }
  }
  for (auto& series : byRun) figure.series.push_back(std::move(series));
  for (auto& [k, series] : byReference) figure.series.push_back(std::move(series));
  return figure;
}

TimeFigures timeFigures(const std::vector<BedRun>& runs, const std::string& tap,
                        const std::vector<ReferenceSeries>& references) {
  TimeFigures out{{"Mean particle height (Eq. 5.22)", {"time", "s"}, {"mean particle height", "m"}, {}, true},
                  {"Pressure drop" + (tap.empty() ? std::string() : " (" + tap + ")"),
                   {"time", "s"},
                   {"pressure drop", "Pa"},
                   {},
                   true}};
  for (std::size_t b = 0; b < runs.size(); ++b) {
    const BedRun& run = runs[b];
    const auto time = run.series.find("time");
    if (time == run.series.end()) throw Error("bed figures: the series of " + run.label + " has no time");
    // A colour per run, a dash per solids phase (a mixture's segregate) named beside the run.
    int variant = 0;
    for (std::size_t m = 0; m < run.phases.size(); ++m) {
      const auto h = run.series.find("mean_height_" + run.phases[m]);
      if (h == run.series.end()) continue;
      out.height.series.push_back(runSeries(run, b,
                                            run.shortLabel + (run.phases.size() > 1 ? ", " + run.phases[m] : ""),
                                            Series::Style::Line, variant++, time->second, h->second));
    }
    // A particle run: its particles' arithmetic mean height, and Eq. 5.22 of its deposited fraction.
    for (const auto& [column, what] : {std::pair{"mean_height", ", particles"},
                                       std::pair{"mean_height_fields", ", Eq. 5.22 of the deposited fraction"}}) {
      const auto h = run.series.find(column);
      if (h == run.series.end()) continue;
      out.height.series.push_back(
          runSeries(run, b, run.shortLabel + what, Series::Style::Line, variant++, time->second, h->second));
    }
    if (const auto dp = run.series.find(run.pressureDrop); dp != run.series.end()) {
      out.pressureDrop.series.push_back(
          runSeries(run, b, run.shortLabel, Series::Style::Line, 0, time->second, dp->second));
    }
  }
  addReferenceSeries(out.height, references, "mean_height");
  return out;
}

Figure contactFigure(const std::vector<BedRun>& runs) {
  Figure figure{
      "Contact numbers (Figs. 7.5, 7.6, 7.11)", {"time", "s"}, {"coordination / multi-contact ratio", "–"}, {}, true};
  for (std::size_t b = 0; b < runs.size(); ++b) {
    const BedRun& run = runs[b];
    const auto time = run.series.find("time");
    if (time == run.series.end()) continue;
    int variant = 0;
    for (const auto& [column, what] :
         {std::pair{"coordination", ", coordination"}, std::pair{"multi_contact_ratio", ", multi-contact ratio"}}) {
      const auto v = run.series.find(column);
      if (v == run.series.end()) continue;
      figure.series.push_back(
          runSeries(run, b, run.shortLabel + what, Series::Style::Line, variant++, time->second, v->second));
    }
  }
  return figure;
}

SegregationFigures segregationFigures(const std::vector<BedRun>& runs, const std::vector<ReferenceSeries>& references) {
  SegregationFigures out{
      {"Segregation percentage s_p (Eqs. 5.23-5.25): every sample and 1 s means",
       {"time", "s"},
       kSegregationAxis,
       {},
       true},
      {"Time-averaged solid fraction over the width (Fig. 5.6)", {"solid fraction", "–"}, {"height", "m"}, {}}};
  for (std::size_t b = 0; b < runs.size(); ++b) {
    const BedRun& run = runs[b];
    const auto sp = run.series.find("segregation_percentage");
    if (sp == run.series.end()) continue;
    out.segregation.series.push_back(
        runSeries(run, b, run.shortLabel, Series::Style::Line, 0, run.series.at("time"), sp->second));
    for (const auto& file : run.segregationBlocks) {
      const auto blocks = readNumericCsv(file);
      Series means = runSeries(run, b, run.shortLabel + ", 1 s means", Series::Style::Points, 1);
      for (std::size_t k = 0; k < blocks.at("block_start").size(); ++k)
        means.x.push_back(0.5 * (blocks.at("block_start")[k] + blocks.at("block_end")[k]));
      means.y = blocks.at("segregation_percentage");
      out.segregation.series.push_back(std::move(means));
    }
    for (const auto& file : run.profiles) {
      const auto columns = readNumericCsv(file);
      int phaseVariant = 0;
      for (const auto& [name, values] : columns) {
        if (name.rfind("ep_s_", 0) != 0) continue;
        out.profiles.series.push_back(runSeries(run, b, run.shortLabel + ", " + name.substr(5), Series::Style::Line,
                                                phaseVariant++, values, columns.at("height")));
      }
    }
  }
  if (!out.segregation.series.empty()) addReferenceSeries(out.segregation, references, "segregation_percentage");
  return out;
}

Figure realisationsFigure(const std::vector<BedRun>& runs, const std::vector<Arm>& arms, const std::string& column,
                          const std::string& title, const Axis& y, const std::vector<ReferenceSeries>& references) {
  Figure figure{title, {"time", "s"}, y, {}, true};
  std::size_t drawn = 0;
  for (const Arm& arm : arms) {
    const bool recorded = std::all_of(arm.runs.begin(), arm.runs.end(),
                                      [&](std::size_t r) { return runs.at(r).series.contains(column); });
    if (arm.runs.size() < 2 || !recorded) continue;
    const CommonTimes common = commonTimes(runs, arm);
    const std::string over = ", mean over " + std::to_string(arm.runs.size()) + " realisations";
    // A colour per arm, as a run has its own in the figures of single runs.
    Series mean{arm.label + over, arm.label, Series::Style::Line, 0, common.times, {}, {}, runColour(drawn)};
    Series band{
        arm.label + ", ± 1 standard error", arm.label, Series::Style::Band, 0, common.times, {}, {}, runColour(drawn)};
    ++drawn;
    for (std::size_t k = 0; k < common.times.size(); ++k) {
      std::vector<double> values;
      for (std::size_t i = 0; i < arm.runs.size(); ++i)
        values.push_back(runs.at(arm.runs[i]).series.at(column).at(common.index[i][k]));
      const RealisationStatistics s = overRealisations(values);
      mean.y.push_back(s.mean);
      band.y.push_back(s.mean);
      band.yError.push_back(s.se);
    }
    // The band first, so the line is drawn over it.
    figure.series.push_back(std::move(band));
    figure.series.push_back(std::move(mean));
  }
  if (!figure.series.empty()) addReferenceSeries(figure, references, column);
  return figure;
}

}  // namespace grainbridge::workflows::report
