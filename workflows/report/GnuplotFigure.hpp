#pragma once
// A figure drawn by gnuplot into an SVG file: several series, each points (optionally with
// error bars) or a line. Report plots go through here so every stage draws the same way, and
// the SVG carries no timestamp (equal data give equal files).
#include <filesystem>
#include <string>
#include <vector>

namespace grainbridge::workflows::report {

struct FigureSeries {
  std::string label;
  enum class Style { Points, PointsWithErrors, Line, DashedLine } style = Style::Points;
  std::vector<double> x, y, yError;  // yError only for PointsWithErrors
};

struct Figure {
  std::string title, xLabel, yLabel;
  bool logY = false;
  std::vector<FigureSeries> series;
};

// Throws grainbridge::Error naming the file when gnuplot is missing or fails.
void drawSvg(const Figure& figure, const std::filesystem::path& file);

}  // namespace grainbridge::workflows::report
