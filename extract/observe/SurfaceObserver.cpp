#include "extract/observe/SurfaceObserver.hpp"

#include <algorithm>
#include <limits>
#include <sstream>

#include "extract/structure/LocalFreeSurface.hpp"

namespace grainbridge::extract::observe {

void SurfaceObserver::observe(ObservedFrame& observed) {
  const auto& frame = observed.frame;
  const double coordination = observed.domain.coordinationNumber;
  if (frame.size() == 0) return;
  const double smallest = 2.0 * *std::min_element(frame.radius.begin(), frame.radius.end());
  const bool judged = coordination >= options_.minCoordination;
  for (const std::int64_t id : options_.ids) {
    const auto s = structure::localFreeSurface(frame, id, options_.up);
    const double gapDiameters = s.gap / smallest;
    rows_.push_back({frame.time, frame.step, id, s.top, s.surface, s.gap, gapDiameters, s.coveringGrains, coordination,
                     judged, judged && gapDiameters <= options_.tolerance});
  }
}

std::string SurfaceObserver::csv() const {
  std::ostringstream out;
  out.precision(std::numeric_limits<double>::max_digits10);  // full precision: a CSV is read back by programs
  out << "time,step,id,top,surface,gap,gap_diameters,covering_grains,coordination,judged,at_top\n";
  for (const Row& r : rows_) {
    out << r.time << ',' << r.step << ',' << r.id << ',' << r.top << ',' << r.surface << ',' << r.gap << ','
        << r.gapDiameters << ',' << r.covering << ',' << r.coordination << ',' << (r.judged ? 1 : 0) << ',';
    if (r.judged) out << (r.atTop ? 1 : 0);
    out << '\n';
  }
  return out.str();
}

void SurfaceObserver::finish(OutputSink& out, ExtractResult& result) {
  out.writeFile("surface.csv", csv(), "csv");
  result.summary.update(summary());
}

nlohmann::json SurfaceObserver::summary() const {
  nlohmann::json out = nlohmann::json::object();
  for (const std::int64_t id : options_.ids) {
    std::vector<const Row*> judged;
    for (const Row& r : rows_) {
      if (r.id == id && r.judged) judged.push_back(&r);
    }
    const std::string prefix = "surface_id" + std::to_string(id) + "_";
    out[prefix + "judged_frames"] = judged.size();
    const auto first = std::find_if(judged.begin(), judged.end(), [](const Row* r) { return r->atTop; });
    out[prefix + "first_at_top_time"] = first != judged.end() ? nlohmann::json((*first)->time) : nullptr;
    // Walk back from the last judged frame while the particle is at the top.
    auto settled = judged.end();
    while (settled != judged.begin() && (*std::prev(settled))->atTop) --settled;
    out[prefix + "settled_at_top_time"] = settled != judged.end() ? nlohmann::json((*settled)->time) : nullptr;
    out[prefix + "last_gap_diameters"] =
        judged.empty() ? nlohmann::json(nullptr) : nlohmann::json(judged.back()->gapDiameters);
  }
  return out;
}

}  // namespace grainbridge::extract::observe
