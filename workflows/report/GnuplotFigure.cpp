#include "workflows/report/GnuplotFigure.hpp"

#include <cstdio>
#include <sstream>

#include "core/Error.hpp"

namespace grainbridge::workflows::report {

namespace {

// gnuplot strings are single-quoted; a quote inside is doubled.
std::string quoted(const std::string& s) {
  std::string out = "'";
  for (char c : s) out += c == '\'' ? std::string("''") : std::string(1, c);
  return out + "'";
}

}  // namespace

void drawSvg(const Figure& figure, const std::filesystem::path& file) {
  std::ostringstream script;
  script.precision(17);
  script << "set terminal svg size 560,400 font 'sans,11'\n"
         << "set title " << quoted(figure.title) << "\nset xlabel " << quoted(figure.xLabel) << "\nset ylabel "
         << quoted(figure.yLabel) << "\nset grid\nset key top left\n";
  if (figure.logY) script << "set logscale y\n";
  std::string plot;
  int plotted = 0;
  for (std::size_t s = 0; s < figure.series.size(); ++s) {
    const auto& series = figure.series[s];
    if (series.x.empty()) continue;
    const char* style = "";
    switch (series.style) {
      case FigureSeries::Style::Points:
        style = "using 1:2 with points pt 7";
        break;
      case FigureSeries::Style::PointsWithErrors:
        style = "using 1:2:3 with yerrorbars pt 7";
        break;
      case FigureSeries::Style::Line:
        style = "using 1:2 with lines lw 2";
        break;
      case FigureSeries::Style::DashedLine:
        style = "using 1:2 with lines lw 2 dt 2";
        break;
    }
    plot += std::string(plotted++ ? ", " : "plot ") + "'-' " + style + " lc " + std::to_string(s + 1) + " title " +
            quoted(series.label);
  }
  if (plotted == 0) throw Error("figure " + file.string() + ": nothing to plot");
  script << plot << "\n";
  for (const auto& series : figure.series) {
    if (series.x.empty()) continue;
    for (std::size_t i = 0; i < series.x.size(); ++i) {
      script << series.x[i] << ' ' << series.y[i];
      if (series.style == FigureSeries::Style::PointsWithErrors) script << ' ' << series.yError[i];
      script << '\n';
    }
    script << "e\n";
  }
  const std::string cmd = "gnuplot > '" + file.string() + "' 2>/dev/null";
  FILE* gp = ::popen(cmd.c_str(), "w");
  if (gp == nullptr) throw Error("could not start gnuplot for " + file.string());
  const std::string text = script.str();
  std::fwrite(text.data(), 1, text.size(), gp);
  const int rc = ::pclose(gp);
  if (rc != 0 || !std::filesystem::exists(file) || std::filesystem::file_size(file) == 0) {
    throw Error("gnuplot could not draw " + file.string() + " (is gnuplot installed? Debian package gnuplot-nox)");
  }
}

}  // namespace grainbridge::workflows::report
