#include "workflows/stages/FluidSchema.hpp"

namespace grainbridge::workflows::stages {

using core::units::Dimension;
using nlohmann::json;
using params::ParamSchema;
using params::ParamSpec;

std::shared_ptr<const ParamSchema> boundarySchema() {
  auto s = std::make_shared<ParamSchema>();
  s->add(ParamSpec::string("side")
             .required()
             .options({"x_low", "x_high", "y_low", "y_high", "z_low", "z_high"})
             .doc("the domain side the patch lies on"))
      .add(ParamSpec::string("kind")
               .required()
               .options({"no_slip_wall", "free_slip_wall", "velocity_inlet", "pressure_outlet"})
               .doc("boundary condition (ghost-cell rules, Eqs. 3.66-3.67)"))
      .add(ParamSpec::quantityList("from", Dimension::lengthDim(), 2)
               .doc("start of the patch along the side's two tangential axes (x before y before z); on cell faces"))
      .add(ParamSpec::quantityList("to", Dimension::lengthDim(), 2).doc("end of the patch, likewise (a jet)"))
      .add(ParamSpec::quantity("gas_inflow", Dimension::velocity())
               .defaultValue(0.0)
               .doc("inlet: gas speed into the domain, normal to the side (outlet: of gas flowing back in)"))
      .add(ParamSpec::quantityList("solids_fractions", Dimension::none(), 0)
               .defaultValue(json::array())
               .doc("inlet: each solids phase's fraction entering (outlet: of the backflow); default none"))
      .add(ParamSpec::quantityList("solids_inflow", Dimension::velocity(), 0)
               .defaultValue(json::array())
               .doc("inlet: each solids phase's speed into the domain; default 0"))
      .add(ParamSpec::quantity("pressure", Dimension::pressure())
               .defaultValue("101325 Pa")
               .doc("outlet: the pressure beyond the outlet face"));
  return s;
}

std::shared_ptr<const ParamSchema> tapSchema() {
  auto s = std::make_shared<ParamSchema>();
  s->add(ParamSpec::string("name").required().doc("column name: series.csv gets dp_<name>"))
      .add(ParamSpec::quantity("low", Dimension::lengthDim())
               .required()
               .min(0.0)
               .doc("lower tap, height above the bottom"))
      .add(ParamSpec::quantity("high", Dimension::lengthDim()).required().doc("upper tap"));
  return s;
}

// A block average as summary values: <key> and <key>_err.
}  // namespace grainbridge::workflows::stages
