#pragma once
// One analysis of the extraction, fed frame by frame (MercuryDPM's split: the coarse-graining
// kernel, the directions and fields, and the time averaging are separate layers; here each
// analysis is an observer with its own parameters, and time averaging with block errors comes
// from core/averaging). The extract stage reads each averaged frame once, computes its
// whole-domain values once, and hands both to every observer in turn; after the last frame it
// asks each, in a fixed order, to finish: write its files and records and add what belongs to
// the closure point and the summary.
#include <nlohmann/json.hpp>
#include <string>

#include "core/data/ParticleFrame.hpp"
#include "extract/coarse/DomainAverages.hpp"
#include "extract/observe/OutputSink.hpp"

namespace grainbridge::extract::observe {

struct ObservedFrame {
  // Mutable so that the observer that keeps frames (force statistics, registered last) can move
  // it instead of copying; every other observer only reads it.
  core::data::ParticleFrame& frame;
  const coarse::DomainAverages& domain;  // Eq. 2.3 over the whole domain, with coordination
};

// What the observers build together: the closure point's row (ClosurePointObserver starts it,
// others add to it) and the values of the stage's summary beyond the closure point.
struct ExtractResult {
  nlohmann::json point = nlohmann::json::object();
  nlohmann::json summary = nlohmann::json::object();
};

class FrameObserver {
 public:
  virtual ~FrameObserver() = default;
  virtual void observe(ObservedFrame& frame) = 0;
  virtual void finish(OutputSink& out, ExtractResult& result) = 0;
  // The stage parameter this analysis's input errors are reported against ("surface_particles"),
  // or "" to report them as they are.
  [[nodiscard]] virtual std::string parameter() const { return ""; }
};

}  // namespace grainbridge::extract::observe
