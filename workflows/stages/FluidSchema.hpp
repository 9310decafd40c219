#pragma once
// The gas keys the stages on engines/fluid share (`mfm`, and `tfdem` with particles in the gas):
// a boundary patch (fluid::FluidSetup's patches as the user writes them) and a pressure tap.
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

#include "core/engine/SetupProblem.hpp"
#include "engines/fluid/StencilSystem.hpp"
#include "workflows/params/ParamSchema.hpp"

namespace grainbridge::workflows::stages {

// The gas grid and gas keys every stage on engines/fluid starts with: cells, lengths, gravity
// (default along -y), gas_density.
void addGasGridParams(params::ParamSchema& s);

// One boundary patch: side, kind, from/to, gas_inflow, solids_fractions, solids_inflow, pressure.
std::shared_ptr<const params::ParamSchema> boundarySchema();
// One pressure tap: name, low, high (heights above the bottom).
std::shared_ptr<const params::ParamSchema> tapSchema();

// How one family of linear systems is solved (fluid::LinearSolve): `<family>_solver`, direct |
// bicgstab | gauss_seidel | petsc (default `method`; `doc` says which systems and what the choice
// does), `<family>_solver_tolerance` (default `tolerance`), the iterative solves' residual norm
// over the right-hand side's (petsc: KSP's rtol), and `<family>_petsc_options` (default
// `petscOptions`), the PETSc options string of petsc.
void addLinearSolveParams(params::ParamSchema& s, const std::string& family, const std::string& method,
                          double tolerance, const std::string& petscOptions, const std::string& doc);
// fluid::linearSolveFromJson reads the three keys back.

// The default `<family>_petsc_options` of every family (issue 58): BiCGSTAB with the point Jacobi
// preconditioner, right-preconditioned so that KSP's relative tolerance is on the true residual as
// the other iterative solvers' is. Measured on one rank (bench/README "Multi-fluid through PETSc
// on one rank") for the pressure correction: level with block Jacobi (ILU(0)) on 3,200 cells and
// 20 % faster on 72,000; hypre's BoomerAMG, set up again at every solve, slower at both sizes. And
// a point preconditioner does not depend on how the grid is split over ranks.
inline constexpr const char* kPetscOptions = "-ksp_type bcgs -ksp_pc_side right -pc_type jacobi";

struct PressureTap {
  std::string name;
  double low = 0.0, high = 0.0;  // heights above the bottom along gravity [m]
};

// The params' pressure_taps (none when absent); a pair not 0 <= low < high <= `height` (the
// domain's height) is a problem (pointer below /params, message).
std::vector<PressureTap> readTaps(const nlohmann::json& params, double height,
                                  std::vector<core::engine::SetupProblem>& problems);

}  // namespace grainbridge::workflows::stages
