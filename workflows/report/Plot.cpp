#include "workflows/report/Plot.hpp"

#include <unistd.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "core/Error.hpp"
#include "core/text/NumberText.hpp"

namespace grainbridge::workflows::report {

namespace fs = std::filesystem;

namespace {

// gnuplot strings are single-quoted; a quote inside is doubled. With enhanced text off,
// nothing else in a label is markup.
std::string gnuplotString(std::string_view s) {
  std::string out = "'";
  for (char c : s) out += c == '\'' ? std::string("''") : std::string(1, c);
  return out + "'";
}

// A double-quoted gnuplot string: the one kind in which "\n" breaks a line (panel titles).
std::string gnuplotLines(std::string_view s) {
  std::string out = "\"";
  for (char c : s) {
    if (c == '\n') {
      out += "\\n";
    } else {
      if (c == '"' || c == '\\') out += '\\';
      out += c;
    }
  }
  return out + "\"";
}

std::string axisTitle(const Axis& axis) {
  return axis.categories.empty() ? axis.label + " [" + axis.unit + "]" : axis.label;
}

// Filled circle, square, triangle, diamond, inverted triangle, pentagon (gnuplot pt codes).
constexpr std::array<int, 6> kPointTypes = {7, 5, 9, 13, 11, 15};

std::string plotClause(const Series& s, std::size_t block) {
  const std::string colour = "lc rgb '" + (s.colour.empty() ? seriesColour(s.model) : s.colour) + "'";
  const std::string data = "$s" + std::to_string(block);
  const int variant = s.variant < 0 ? 0 : s.variant;
  switch (s.style) {
    case Series::Style::Points:
      return data + " using 1:2 with points pt " + std::to_string(kPointTypes[variant % kPointTypes.size()]) +
             " ps 1.2 " + colour + " title " + gnuplotString(s.label);
    case Series::Style::PointsWithErrors:
      return data + " using 1:2:3 with yerrorbars pt " + std::to_string(kPointTypes[variant % kPointTypes.size()]) +
             " ps 1.2 " + colour + " title " + gnuplotString(s.label);
    case Series::Style::Line:
      return data + " using 1:2 with lines lw 2 dt " + std::to_string(variant % 5 + 1) + " " + colour + " title " +
             gnuplotString(s.label);
    case Series::Style::Band:
      return data + " using 1:($2-$3):($2+$3) with filledcurves fs transparent solid 0.2 noborder " + colour +
             " title " + gnuplotString(s.label);
  }
  return {};
}

void checkFigure(const Figure& f, const std::string& name) {
  if ((f.x.unit.empty() && f.x.categories.empty()) || f.y.unit.empty()) {
    throw Error("figure " + name + ": every axis needs a unit (\"–\" when dimensionless)");
  }
  if (!f.y.categories.empty()) throw Error("figure " + name + ": only the x axis can hold categories");
  for (const auto& s : f.series) {
    const bool errors = s.style == Series::Style::PointsWithErrors || s.style == Series::Style::Band;
    if (s.y.size() != s.x.size() || (errors && s.yError.size() != s.x.size())) {
      throw Error("figure " + name + ": series '" + s.label + "' has columns of different lengths");
    }
  }
}

// Feeds `script` to gnuplot; throws naming the figure when it fails or leaves a file empty.
void runGnuplot(const std::string& text, const fs::path& dir, const std::string& stem, const DrawnFigure& out) {
  const fs::path errors = dir / (stem + ".gnuplot-errors");
  const std::string cmd = "gnuplot 2> '" + errors.string() + "'";
  FILE* gp = ::popen(cmd.c_str(), "w");
  if (gp == nullptr) throw Error("could not start gnuplot for figure " + (dir / stem).string());
  std::fwrite(text.data(), 1, text.size(), gp);
  const int rc = ::pclose(gp);
  std::ostringstream said;
  if (std::ifstream in(errors); in) said << in.rdbuf();
  std::error_code ignored;
  fs::remove(errors, ignored);
  for (const auto& f : {out.svg, out.png}) {
    if (rc != 0 || !fs::exists(dir / f) || fs::file_size(dir / f) == 0) {
      throw Error("gnuplot could not draw " + (dir / f).string() +
                  (rc == 127 || said.str().find("not found") != std::string::npos
                       ? " (is gnuplot installed? Debian package gnuplot-nox)"
                       : ": " + said.str()));
    }
  }
}

}  // namespace

std::string seriesColour(std::string_view model) {
  // Okabe–Ito: distinguishable with the common colour-vision deficiencies, and in grey print.
  if (model == "DEM") return "#000000";
  if (model == "lun1984") return "#0072B2";
  if (model == "lun1984_mfix") return "#56B4E9";  // sky blue beside lun1984's blue
  if (model == "syamlal_algebraic") return "#D55E00";
  if (model == "syamlal_algebraic_mfix") return "#009E73";
  if (model == "table") return "#E69F00";
  if (model == "experiment") return "#CC79A7";
  if (model == "reference") return "#555555";  // a published model value: neutral, beside the runs
  static constexpr std::array<const char*, 3> others = {"#56B4E9", "#F0E442", "#999999"};
  std::size_t h = 0;
  for (char c : model) h = h * 31 + static_cast<unsigned char>(c);
  return others[h % others.size()];
}

std::string runColour(std::size_t index) {
  // Okabe–Ito without its reddish purple and grey (experiment, reference) and its yellow (too
  // pale on white): blue, vermillion, bluish green, orange, sky blue, black.
  static constexpr std::array<const char*, 6> runs = {"#0072B2", "#D55E00", "#009E73", "#E69F00", "#56B4E9", "#000000"};
  return runs[index % runs.size()];
}

DrawnFigure drawFigure(const Figure& figure, const fs::path& dir, const std::string& stem) {
  checkFigure(figure, stem);
  std::vector<const Series*> plotted;
  for (const auto& s : figure.series) {
    if (!s.x.empty()) plotted.push_back(&s);
  }
  if (plotted.empty()) throw Error("figure " + (dir / stem).string() + ": nothing to plot");
  DrawnFigure out{stem + ".svg", stem + ".png"};

  // The canvas grows to hold the title and the key's columns (long run labels, such as a
  // sweep's "bed (gas_inflow 1.30 m/s, rotation_model true), 1 s means", ran off the right edge
  // of a fixed 540 px SVG): the title at about 7 px per character of the 13 px font, each key
  // column at 10 px per character (gnuplot sizes key columns by its own, wider, estimate of the
  // text) plus its sample and gap.
  const std::size_t keyRows = std::max<std::size_t>(2, (plotted.size() + 1) / 2);
  const std::size_t keyColumns = (plotted.size() + keyRows - 1) / keyRows;
  std::size_t longestLabel = 0;
  for (const Series* s : plotted) longestLabel = std::max(longestLabel, s->label.size());
  // A wide figure (several runs against time) is drawn for a page's full width, so that scaled
  // to it its text stays at the page's size.
  // Categories (runs by name) take about 8 px per character of their longest line, and a gap.
  std::size_t longestCategoryLine = 0;
  for (const auto& category : figure.x.categories) {
    std::size_t line = 0;
    for (char c : category) {
      line = c == '\n' ? 0 : line + 1;
      longestCategoryLine = std::max(longestCategoryLine, line);
    }
  }
  const std::size_t width = std::max<std::size_t>({figure.wide ? std::size_t{1200} : std::size_t{540},
                                                   keyColumns * (10 * longestLabel + 80), 7 * figure.title.size() + 80,
                                                   figure.x.categories.size() * (8 * longestCategoryLine + 24) + 120});
  const std::size_t height = 430 + 20 * (keyRows > 4 ? keyRows - 4 : 0);

  std::ostringstream script;
  script << "set encoding utf8\nset termoption noenhanced\n";
  for (std::size_t b = 0; b < plotted.size(); ++b) {
    const Series& s = *plotted[b];
    script << "$s" << b << " << EOD\n";
    for (std::size_t i = 0; i < s.x.size(); ++i) {
      script << core::roundTripText(s.x[i]) << ' ' << core::roundTripText(s.y[i]);
      if (s.style == Series::Style::PointsWithErrors || s.style == Series::Style::Band)
        script << ' ' << core::roundTripText(s.yError[i]);
      script << '\n';
    }
    script << "EOD\n";
  }
  script << "set title " << gnuplotString(figure.title) << "\nset xlabel " << gnuplotString(axisTitle(figure.x))
         << "\nset ylabel " << gnuplotString(axisTitle(figure.y)) << "\n"
         << "set grid lc rgb '#dddddd'\nset border lc rgb '#444444'\n"
         // Below the plot in two columns (gnuplot wraps a below-key by rows, not columns).
         << "set key outside below center vertical maxrows " << keyRows << " Left reverse samplen 2\n"
         << "set format x '%g'\nset format y '%g'\n";
  // A margin around linear data so no point sits on the frame; a log axis ends at decades.
  script << "set offsets graph " << (figure.x.logarithmic ? "0" : "0.02") << ", graph "
         << (figure.x.logarithmic ? "0" : "0.02") << ", graph " << (figure.y.logarithmic ? "0" : "0.05") << ", graph "
         << (figure.y.logarithmic ? "0" : "0.05") << "\n";
  if (!figure.x.categories.empty()) {
    // Runs by name: category k at x = k + 1, half a category of room at either end.
    script << "set xrange [0.5:" << core::roundTripText(static_cast<double>(figure.x.categories.size()) + 0.5)
           << "]\nset offsets 0, 0, graph 0.05, graph 0.05\nset xtics (";
    for (std::size_t k = 0; k < figure.x.categories.size(); ++k)
      script << (k ? ", " : "") << gnuplotLines(figure.x.categories[k]) << ' ' << k + 1;
    script << ")\n";
  }
  if (figure.x.logarithmic) script << "set logscale x\n";
  if (figure.y.logarithmic) script << "set logscale y\n";
  std::string plot = "plot ";
  for (std::size_t b = 0; b < plotted.size(); ++b) plot += (b ? ", " : "") + plotClause(*plotted[b], b);
  // The same plot twice: SVG for the page, PNG at twice the size for slides.
  script << "set terminal svg size " << width << ',' << height
         << " font 'sans,13' noenhanced background rgb 'white'\nset output " << gnuplotString((dir / out.svg).string())
         << "\n"
         << plot << "\nset output\n"
         << "set terminal pngcairo size " << 2 * width << ',' << 2 * height
         << " font 'sans,22' noenhanced lw 2\nset output "
         << gnuplotString((dir / out.png).string()) << "\nreplot\nset output\n";

  runGnuplot(script.str(), dir, stem, out);
  return out;
}

DrawnFigure drawFieldMaps(const std::vector<FieldMap>& maps, const Axis& x, const Axis& y, const Axis& colour,
                          double low, double high, const fs::path& dir, const std::string& stem) {
  if (maps.empty()) throw Error("figure " + (dir / stem).string() + ": nothing to plot");
  if (x.unit.empty() || y.unit.empty() || colour.unit.empty()) {
    throw Error("figure " + stem + ": every axis needs a unit (\"–\" when dimensionless)");
  }
  for (const auto& m : maps) {
    if (m.columns < 1 || m.rows < 1 || m.values.size() != static_cast<std::size_t>(m.columns) * m.rows) {
      throw Error("figure " + stem + ": map '" + m.title + "' has " + std::to_string(m.values.size()) +
                  " values for " + std::to_string(m.columns) + " x " + std::to_string(m.rows) + " cells");
    }
  }
  DrawnFigure out{stem + ".svg", stem + ".png"};
  std::ostringstream script;
  script << "set encoding utf8\nset termoption noenhanced\n";
  for (std::size_t b = 0; b < maps.size(); ++b) {
    const FieldMap& m = maps[b];
    script << "$m" << b << " << EOD\n";
    for (int r = 0; r < m.rows; ++r) {
      for (int c = 0; c < m.columns; ++c) {
        script << core::roundTripText(m.x0 + (c + 0.5) * m.dx) << ' ' << core::roundTripText(m.y0 + (r + 0.5) * m.dy)
               << ' ' << core::roundTripText(m.values[static_cast<std::size_t>(r) * m.columns + c]) << '\n';
      }
    }
    script << "EOD\n";
  }
  // Perceptually uniform and readable in grey (viridis's end points and quartiles); the maps
  // are drawn as cells (`pixels`), so the SVG holds no embedded raster.
  std::ostringstream panels;
  panels << "set palette defined (0 '#440154', 0.25 '#3b528b', 0.5 '#21918c', 0.75 '#5ec962', 1 '#fde725')\n"
         << "set cbrange [" << core::roundTripText(low) << ':' << core::roundTripText(high) << "]\n"
         << "set cblabel " << gnuplotString(axisTitle(colour)) << "\nset format x '%g'\nset format y '%g'\n"
         << "set xlabel " << gnuplotString(axisTitle(x)) << "\nset ylabel " << gnuplotString(axisTitle(y)) << "\n"
         << "set size ratio -1\nset border lc rgb '#444444'\n"
         // Equal panels in the left 88 %, one colour bar for all of them at the right (a bar
         // beside the last panel would shrink it).
         << "set colorbox user origin 0.91,0.15 size 0.015,0.7\n"
         << "set multiplot layout 1," << maps.size() << " margins 0.075,0.88,0.1,0.85 spacing 0.05,0\n";
  for (std::size_t b = 0; b < maps.size(); ++b) {
    const FieldMap& m = maps[b];
    // A tall narrow bed's panel is drawn at its aspect ratio (size ratio -1): about 390 px high in
    // the SVG, so width = 390 Lx / Ly px at most (230 px a panel). Three labels of up to n digits
    // (about 8 px each at 13 pt) fit when the panel is wider than 3 (8 n + 12) px; else only its
    // ends are labelled (the labels of a 15 x 90 cm jet overlapped).
    const double lx = m.columns * m.dx, ly = m.rows * m.dy;
    const double panelWidth = std::min(230.0 * 0.8, 390.0 * lx / ly);
    const std::string lo = core::roundTripText(m.x0), mid = core::roundTripText(m.x0 + 0.5 * lx),
                      hi = core::roundTripText(m.x0 + lx);
    const double label = 8.0 * static_cast<double>(std::max({lo.size(), mid.size(), hi.size()})) + 12.0;
    const std::string ticks = panelWidth >= 3.0 * label ? lo + ", " + mid + ", " + hi : lo + ", " + hi;
    panels << (b + 1 == maps.size() ? "set colorbox\n" : "unset colorbox\n") << "set title "
           << gnuplotLines(m.title) << "\nset xtics (" << ticks << ")\nset xrange [" << core::roundTripText(m.x0) << ':'
           << core::roundTripText(m.x0 + m.columns * m.dx) << "]\nset yrange [" << core::roundTripText(m.y0) << ':'
           << core::roundTripText(m.y0 + m.rows * m.dy) << "]\nplot $m" << b << " using 1:2:3 with image pixels notitle\n";
  }
  panels << "unset multiplot\n";
  const std::size_t width = 230 * maps.size() + 140;
  script << "set terminal svg size " << width << ",520 font 'sans,13' noenhanced background rgb 'white'\nset output "
         << gnuplotString((dir / out.svg).string()) << "\n"
         << panels.str() << "set output\n"
         << "set terminal pngcairo size " << 2 * width << ",1040 font 'sans,22' noenhanced\nset output "
         << gnuplotString((dir / out.png).string()) << "\n"
         << panels.str() << "set output\n";
  runGnuplot(script.str(), dir, stem, out);
  return out;
}

}  // namespace grainbridge::workflows::report
