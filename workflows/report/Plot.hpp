#pragma once
// The one plotting module: every figure a stage or a report draws goes through `drawFigure`,
// so all of them look alike. gnuplot draws each figure twice from one script: an SVG for the
// page and a PNG (twice the size) beside it for slides.
//
// What every figure gets, whoever calls:
// - text printed literally (gnuplot's enhanced mode off: `syamlal_algebraic` keeps its
//   underscore), symbols written in UTF-8 by the caller (p*, τ*, θ);
// - a unit on both axes (`Axis::unit`; "–" for a dimensionless quantity), required;
// - the legend below the plot, never on the data;
// - one colour per model across all figures (`seriesColour`), the series' `variant` (a
//   restitution, a friction) picking the dash or point shape within that colour; a comparison of
//   runs gives each run its own colour instead (`Series::colour`, `runColour`);
// - runs along x by name (`Axis::categories`), never as row numbers;
// - no timestamp, so equal data give byte-equal files.
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace grainbridge::workflows::report {

struct Axis {
  std::string label;  // "solid fraction", "p*"
  std::string unit;   // "Pa", "m/s"; "–" when dimensionless; none on a categorical axis
  bool logarithmic = false;
  // A categorical axis (x only): category k (from 0) at x = k + 1, labelled by its text ('\n'
  // breaks it into lines), the axis titled by `label` alone. Runs side by side are categories.
  std::vector<std::string> categories{};
};

struct Series {
  std::string label;  // the legend entry, printed as written
  std::string model;  // the colour key: "DEM", "lun1984", "experiment", ...
  // Band: a translucent area from y - yError to y + yError (an interpolated uncertainty).
  enum class Style { Points, PointsWithErrors, Line, Band } style = Style::Points;
  int variant = 0;                   // dash type (lines) or point shape (points) within the model's colour
  std::vector<double> x, y, yError;  // yError only for PointsWithErrors and Band
  std::string colour{};              // "#rrggbb" instead of the model's: a run's own (runColour)
};

struct Figure {
  std::string title;
  Axis x, y;
  std::vector<Series> series;
  bool wide = false;  // drawn for a page's full width: several runs against time
};

struct DrawnFigure {
  std::string svg, png;  // file names written beside each other
};

// Writes <dir>/<stem>.svg and <dir>/<stem>.png. Throws grainbridge::Error naming the figure
// when a series is malformed, an axis has no unit, or gnuplot is missing or fails.
DrawnFigure drawFigure(const Figure& figure, const std::filesystem::path& dir, const std::string& stem);

// A cell field on a 2-D grid, drawn as a colour map: `values` row-major [row][column], row 0 at
// the bottom, `columns` x `rows` cells of `dx` x `dy` from (x0, y0).
struct FieldMap {
  std::string title;  // the panel's title (which run); '\n' breaks it into lines
  int columns = 0, rows = 0;
  double x0 = 0.0, y0 = 0.0, dx = 1.0, dy = 1.0;
  std::vector<double> values;
};

// Writes <dir>/<stem>.svg and .png: the maps side by side on one colour scale from `low` to
// `high` (a time-averaged solid fraction per run), sharing the axes' labels and units and the
// colour bar's (`colour`). Throws as drawFigure does, or when a map's values do not fill its grid.
DrawnFigure drawFieldMaps(const std::vector<FieldMap>& maps, const Axis& x, const Axis& y, const Axis& colour,
                          double low, double high, const std::filesystem::path& dir, const std::string& stem);

// The colour (#rrggbb) of a model in every figure: fixed for the models the reports know,
// a stable choice from the Okabe–Ito palette for any other name.
std::string seriesColour(std::string_view model);

// The colour of the `index`-th run (from 0) of a comparison, each run its own: the Okabe–Ito
// colours that the reference kinds do not take (experiment, reference), in a fixed order, cycling
// after six.
std::string runColour(std::size_t index);

}  // namespace grainbridge::workflows::report
