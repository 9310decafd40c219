#include "extract/observe/StructureObserver.hpp"

#include <algorithm>
#include <limits>

#include "extract/structure/ForceNetworks.hpp"
#include "extract/structure/MstTreeContacts.hpp"
#include "extract/structure/MultiPassMst.hpp"

namespace grainbridge::extract::observe {

using nlohmann::json;

void StructureObserver::observe(ObservedFrame& observed) {
  const auto& frame = observed.frame;
  const auto networks = structure::analyzeForceNetworks(frame);
  json n = {{"family", options_.family},
            {"kind", "force_networks"},
            {"pass", 0},
            {"frame_step", frame.step},
            {"time", frame.time},
            {"networks", networks.networks.size()},
            {"strong_particles", networks.strongParticles}};
  if (!networks.networks.empty()) {
    const auto& largest = networks.networks.front();
    n["largest_particles"] = largest.particleIds.size();
    n["largest_edges"] = largest.contacts;
    n["largest_coordination"] = largest.coordination;
    n["largest_extent"] = largest.extent.largestCentreDistance;
    // The reference gives the extent in d0, the small grains' diameter (52.2 d0, Section
    // 6.3.2): record it in units of the smallest diameter in the frame too.
    double smallest = std::numeric_limits<double>::infinity();
    for (const double r : frame.radius) smallest = std::min(smallest, 2.0 * r);
    n["extra_json"] = {{"smallest_diameter", smallest},
                       {"largest_extent_diameters", largest.extent.largestCentreDistance / smallest}};
  }
  rows_.push_back(n);
  structure::MultiPassMstOptions mstOptions;
  mstOptions.passes = options_.mstPasses;
  mstOptions.elongationFactor = options_.mstElongation;
  const auto mst = structure::runMultiPassMst(frame, mstOptions);
  if (options_.keepTreeContacts) {
    auto& perPass = treeContacts_.emplace_back();
    for (std::size_t pass = 1; pass <= mst.passes.size(); ++pass) {
      perPass.push_back(structure::treeContactsUpToPass(mst, static_cast<int>(pass)));
    }
  }
  for (std::size_t pass = 0; pass < mst.passes.size(); ++pass) {
    const auto& mp = mst.passes[pass];
    rows_.push_back({{"family", options_.family},
                     {"kind", "mst"},
                     {"pass", pass + 1},
                     {"frame_step", frame.step},
                     {"time", frame.time},
                     {"largest_particles", mp.largestTree.particles},
                     {"largest_edges", mp.largestTree.edges},
                     {"other_trees", mp.otherTrees},
                     {"other_edges", mp.otherTreeEdges}});
  }
}

void StructureObserver::finish(OutputSink& out, ExtractResult& /*result*/) {
  for (auto& row : rows_) out.addRecord("structure_statistics", std::move(row));
  rows_.clear();
}

}  // namespace grainbridge::extract::observe
