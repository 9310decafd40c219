#pragma once
// The closure points of a mixture's species and species pairs (issue 60), beside the mixture's
// own (ClosurePointObserver): per frame each species' partial solid fraction, granular
// temperature and partial stress, and each pair's contact stress and dashpot power
// (coarse/SpeciesStress.hpp); time-averaged with block-averaging errors into one closure_points
// row per species (its name in `species`, its own diameter, density and partial fraction, the
// mixture's total fraction and its share x of the solids volume; under shear its J, the shear work
// on its partial stress, which the species' add up to the mixture's) and one per pair
// ("small+large": the pair's contacts only, the collisional part a mixture theory sums over
// pairs, with the two species' temperature ratio). species_points.csv holds the rows too, and
// species_frames.csv the per-frame values.
#include <cstdint>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "extract/observe/ClosurePointObserver.hpp"

namespace grainbridge::extract::observe {

class SpeciesClosurePoints final : public FrameObserver {
 public:
  explicit SpeciesClosurePoints(ClosurePointOptions options);
  void observe(ObservedFrame& frame) override;
  // Adds the rows to closure_points and writes the CSVs; nothing when the frames hold one species.
  void finish(OutputSink& out, ExtractResult& result) override;

 private:
  struct Series {
    std::vector<double> solidFraction, temperature, pressure, pressureKinetic, pressureContact, shearStress;
  };
  struct PairSeries {
    std::vector<double> pressure, shearStress, dissipation, contacts;
  };
  ClosurePointOptions options_;
  std::vector<std::int32_t> species_;  // of the first frame; every frame must hold the same
  std::vector<Series> perSpecies_;
  std::vector<PairSeries> perPair_;
  std::vector<double> mixtureFraction_;
  std::vector<double> diameter_, density_;  // per species, from the materials or the first frame
  std::ostringstream perFrame_;
  std::size_t frames_ = 0;
};

}  // namespace grainbridge::extract::observe
