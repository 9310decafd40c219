#include "workflows/stages/FluidSchema.hpp"

#include "core/text/NumberText.hpp"

namespace grainbridge::workflows::stages {

using core::units::Dimension;
using nlohmann::json;
using params::ParamSchema;
using params::ParamSpec;

void addGasGridParams(ParamSchema& s) {
  s.add(ParamSpec::integerList("cells", 3).required().min(1).doc("cells along x, y, z (z = 1: a 2D x-y grid)"))
      .add(ParamSpec::quantityList("lengths", Dimension::lengthDim(), 3)
               .required()
               .doc("domain size along x, y, z (z of a 2D grid: its depth)"))
      .add(ParamSpec::quantityList("gravity", Dimension::acceleration(), 3)
               .defaultValue(json::array({0, -9.81, 0}))
               .doc("gravitational acceleration; default along -y, the vertical of a 2D x-y grid (the dem "
                    "stage's is along -z)"))
      .add(ParamSpec::quantity("gas_density", Dimension::density())
               .defaultValue("1.2 kg/m3")
               .positive()
               .doc("gas density rho_g (incompressible gas)"));
}

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
      .add(ParamSpec::quantityList("solids_temperature", Dimension::granularTemperature(), 0)
               .defaultValue(json::array())
               .doc("inlet: the granular temperature each solids phase's inflow carries (MFiX's BC_THETA_M); "
                    "default the interior's (zero gradient)"))
      .add(ParamSpec::quantity("pressure", Dimension::pressure())
               .defaultValue("101325 Pa")
               .doc("outlet: the pressure beyond the outlet face"));
  return s;
}

void addLinearSolveParams(ParamSchema& s, const std::string& family, const std::string& method, double tolerance,
                          const std::string& petscOptions, const std::string& doc) {
  s.add(ParamSpec::string(family + "_solver")
            .defaultValue(method)
            .options({"direct", "bicgstab", "gauss_seidel", "petsc"})
            .doc(doc + "; petsc: PETSc's KSP with " + family + "_petsc_options (the LU where it fails)"))
      .add(ParamSpec::number(family + "_solver_tolerance")
               .defaultValue(tolerance)
               .positive()
               .doc("bicgstab, gauss_seidel, petsc: each " + family +
                    " solve's residual norm over its right-hand side's (petsc: KSP's -ksp_rtol)"))
      .add(ParamSpec::string(family + "_petsc_options")
               .defaultValue(petscOptions)
               .doc("petsc: PETSc options for the " + family +
                    " solves (-ksp_type, -pc_type, ...), in their own database; checked at load"));
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

std::vector<PressureTap> readTaps(const json& p, double height, std::vector<core::engine::SetupProblem>& problems) {
  std::vector<PressureTap> out;
  const json taps = p.value("pressure_taps", json::array());  // optional lists: absent when not given
  for (std::size_t k = 0; k < taps.size(); ++k) {
    const json& t = taps[k];
    PressureTap tap{t.at("name").get<std::string>(), t.at("low").get<double>(), t.at("high").get<double>()};
    if (!(tap.low < tap.high) || tap.low < 0.0 || tap.high > height * (1.0 + 1e-9)) {
      problems.emplace_back(
          "/pressure_taps/" + std::to_string(k) + "/high",
          "the taps must satisfy 0 <= low < high <= " + core::humanNumber(height) + " m (the domain's height)");
    }
    out.push_back(std::move(tap));
  }
  return out;
}

}  // namespace grainbridge::workflows::stages
