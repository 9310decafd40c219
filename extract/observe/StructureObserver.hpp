#pragma once
// Force networks and the multi-pass minimum spanning tree of each averaged frame (Sections
// 6.3.2-6.3.3), recorded as structure_statistics rows. With force statistics on, it also keeps
// per frame the contacts each MST pass found, for their force PDFs (Figs. 6.14-6.16).
#include <cstddef>
#include <nlohmann/json.hpp>
#include <vector>

#include "extract/observe/FrameObserver.hpp"

namespace grainbridge::extract::observe {

struct StructureOptions {
  nlohmann::json family;
  int mstPasses = 1;
  double mstElongation = 1.0;
  bool keepTreeContacts = false;  // for ForceStatisticsObserver's MST statistics
};

class StructureObserver final : public FrameObserver {
 public:
  explicit StructureObserver(StructureOptions options) : options_(std::move(options)) {}
  void observe(ObservedFrame& frame) override;
  void finish(OutputSink& out, ExtractResult& result) override;

  // treeContacts()[f][p]: indices into frame f's contacts that MST passes 1..p+1 found.
  [[nodiscard]] const std::vector<std::vector<std::vector<std::size_t>>>& treeContacts() const { return treeContacts_; }

 private:
  StructureOptions options_;
  std::vector<nlohmann::json> rows_;
  std::vector<std::vector<std::vector<std::size_t>>> treeContacts_;
};

}  // namespace grainbridge::extract::observe
