#pragma once
// The closure point of an extraction: per frame the whole-domain solid fraction, granular
// temperature, pressure, shear stress, dissipation rate, coordination and bond-orientational order
// (written as frames.csv),
// time-averaged with block-averaging errors (core/averaging) into the point's row with its
// closure forms (core/ClosureForms) and the state it belongs to (the materials the frames carry).
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "core/ClosureForms.hpp"
#include "core/data/Materials.hpp"
#include "extract/observe/FrameObserver.hpp"

namespace grainbridge::extract::observe {

struct ClosurePointOptions {
  nlohmann::json family;            // the closure family the point is filed under ("simple_shear")
  double shearRate = 0.0;           // imposed Lees-Edwards rate of the frames (0: none)
  core::data::Materials materials;  // of the frames: restitution, friction of the first pair
  double startTime = 0.0;           // first averaged frame's time window start (provenance)
  std::string upstreamStage;        // provenance
};

class ClosurePointObserver final : public FrameObserver {
 public:
  explicit ClosurePointObserver(ClosurePointOptions options);
  void observe(ObservedFrame& frame) override;
  // Writes frames.csv and puts the point's row in result.point (whether or not the stage records
  // it: force statistics add to it).
  void finish(OutputSink& out, ExtractResult& result) override;

  // Number-mean diameter and material density of the grains (of the first frame).
  [[nodiscard]] double diameter() const { return diameter_; }

 private:
  ClosurePointOptions options_;
  // Neighbours of the bond-orientational order: within this many mean diameters (the first shell,
  // short of an fcc lattice's second at 1.41 d).
  static constexpr double kBondOrderCutoff = 1.3;
  // A point whose time-averaged crystalline share exceeds this is flagged ordered (issue 61).
  static constexpr double kOrderedShare = 0.2;
  std::vector<double> solidFraction_, temperature_, pressure_, shearStress_, dissipation_, coordination_;
  std::vector<double> bondOrderQ6_, crystallineShare_;
  std::ostringstream perFrame_;
  std::size_t frames_ = 0;
  double diameter_ = 0.0, density_ = 0.0;
};

// The forms of a point's stresses (core/ClosureForms), each with its block-averaging error (the
// theta forms' by quadrature, which both callers then replace by addThetaFormErrors'): p_theta
// where theta > 0; under shear (state.shearRate > 0) also shear_rate, shear_stress, viscosity and
// the shear-scaled forms, and eta_theta where theta > 0. A mixture's species use it too.
void addStressForms(nlohmann::json& row, const core::MeasuredValue& pressure, const core::MeasuredValue& shearStress,
                    const core::MeasuredValue& temperature, const core::ClosureFormState& state);

// The closure point as the CSV beside it: one line per numeric quantity, full precision.
std::string closurePointCsv(const nlohmann::json& point);

}  // namespace grainbridge::extract::observe
