#pragma once
// Force statistics pooled over the averaged frames (force_statistics: true): the force PDF of
// f = F_n/<F_n> with its Eq. 6.11 and 6.13 fits, the force (Eq. 6.12) and velocity correlations
// with their lengths, the velocity kurtosis (Section 8.2.1.1); and, with the structure observer's
// tree contacts, the same PDF, fits and force correlation for the contacts each multi-pass MST
// pass found (Figs. 6.14-6.16).
//
// Writes force_pdf.csv and correlations.csv (and mst_force_pdf.csv, mst_correlations.csv),
// records force_statistics rows (source "contacts", "mst_pass<p>") and adds the correlation
// lengths and the kurtosis to the closure point. With no repulsive contact in any frame (a
// dilute gas) there is no force PDF: the point's extra_json says why (force_statistics_skipped).
// It keeps every frame until finish(), so it is registered last and takes the frames it is given.
#include <nlohmann/json.hpp>
#include <vector>

#include "extract/observe/ClosurePointObserver.hpp"
#include "extract/observe/FrameObserver.hpp"
#include "extract/observe/StructureObserver.hpp"

namespace grainbridge::extract::observe {

struct ForceStatisticsOptions {
  nlohmann::json family;
  double correlationRange = 10.0;  // in grain diameters (capped at half the shortest periodic edge)
};

class ForceStatisticsObserver final : public FrameObserver {
 public:
  // The closure point observer gives the grain diameter; `structure` (may be null) the tree
  // contacts of the MST passes.
  ForceStatisticsObserver(ForceStatisticsOptions options, const ClosurePointObserver& closurePoint,
                          const StructureObserver* structure)
      : options_(std::move(options)), closurePoint_(closurePoint), structure_(structure) {}
  void observe(ObservedFrame& frame) override;
  void finish(OutputSink& out, ExtractResult& result) override;

 private:
  ForceStatisticsOptions options_;
  const ClosurePointObserver& closurePoint_;
  const StructureObserver* structure_;
  std::vector<core::data::ParticleFrame> frames_;
};

}  // namespace grainbridge::extract::observe
