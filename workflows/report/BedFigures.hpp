#pragma once
// The figures a comparison of fluidized-bed runs draws (the bed_compare stage), assembled from
// each run's products alone: its summary's mean height, its series.csv columns, its phases'
// names and the CSV tables it wrote (segregation_blocks.csv, profiles.csv). Drawing is Plot's.
#include <string>
#include <vector>

#include "workflows/report/BedRun.hpp"
#include "workflows/report/Plot.hpp"
#include "workflows/report/Realisations.hpp"

namespace grainbridge::workflows::report {

// s_p as every figure and table shows it: Eq. 5.23 in percent (0 mixed, 100 fully segregated).
inline const Axis kSegregationAxis{"segregation percentage s_p", "%"};

// Every figure gives each run its colour (runColour of its index) and names it by its shortLabel;
// where runs are along x they are categories, labelled by their `category`. The reference curves
// (`references`) of the figure's output are drawn beside the runs, each in its kind's colour.

// The time-averaged mean heights, a run per category along x, with the reference values matched
// to each: a legend entry per run and per reference label.
[[nodiscard]] Figure averagedHeightFigure(const std::vector<BedRun>& runs);

// Each run's mean height against time, a line per solids phase, and its compared pressure drop
// (`tap` named in the title when not empty), the run's first line's dash in both.
struct TimeFigures {
  Figure height, pressureDrop;
};
[[nodiscard]] TimeFigures timeFigures(const std::vector<BedRun>& runs, const std::string& tap,
                                      const std::vector<ReferenceSeries>& references = {});

// The coordination number and the multi-contact ratio against time (Figs. 7.5, 7.6, 7.11) of the
// runs whose series record them (particle runs), a line each; no series when none does.
[[nodiscard]] Figure contactFigure(const std::vector<BedRun>& runs);

// Binary beds: s_p (Eqs. 5.23-5.25) of every run that records it against time with its 1 s block
// means, and each phase's time-averaged solid fraction over the width against height (Fig. 5.6)
// from its profiles.csv. No series in either when no run records s_p.
struct SegregationFigures {
  Figure segregation, profiles;
};
[[nodiscard]] SegregationFigures segregationFigures(const std::vector<BedRun>& runs,
                                                    const std::vector<ReferenceSeries>& references = {});

// Statistics over realisations against time (issue 55): per arm of at least two realisations
// whose runs all record the series column `column`, the mean over its runs (a line) and ± one
// standard error across them (a band) at each time, a colour per arm (runColour of its place
// among the arms drawn). Taken at the times all of an arm's runs sampled (all of them, at one
// output_interval); throws naming the runs when those are fewer than two. No series when no arm
// qualifies. `arms` are grouped from `runs` (report/groupArms).
[[nodiscard]] Figure realisationsFigure(const std::vector<BedRun>& runs, const std::vector<Arm>& arms,
                                        const std::string& column, const std::string& title, const Axis& y,
                                        const std::vector<ReferenceSeries>& references = {});

}  // namespace grainbridge::workflows::report
