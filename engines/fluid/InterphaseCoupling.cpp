#include "engines/fluid/InterphaseCoupling.hpp"

#include <Eigen/Dense>

#include "engines/fluid/Momentum.hpp"

namespace grainbridge::fluid {

CorrectionCoefficients coupleAndRelax(std::vector<StencilSystem>& systems, const FlowState& state,
                                      const FlowProperties& properties, int axis, double relaxation,
                                      double diluteFraction) {
  const StaggeredGrid& grid = state.grid();
  const std::size_t M = systems.size();
  const double V = grid.cellVolume(), A = grid.faceArea(axis);
  CorrectionCoefficients out;
  for (std::size_t m = 0; m < M; ++m) {
    out.pressure.emplace_back(grid, axis);
    out.solidsPressure.emplace_back(grid, axis);
  }
  std::vector<double> H(M), a(M), dragV(M, 0.0), u(M);
  std::vector<char> dilute(M, 0);
  for (std::size_t f = 0; f < grid.paddedCount(); ++f) {
    if (!systems[0].active(f)) continue;
    for (std::size_t m = 0; m < M; ++m) {
      const auto& v = state.phases[m].velocity[static_cast<std::size_t>(axis)].values();
      H[m] = systems[m].neighbourSum(f, v);
      a[m] = systems[m].ap(f);
      u[m] = v[f];
      dragV[m] = m == 0 ? 0.0 : meanOnFace(properties.dragCoefficient[m], axis, f) * V;
      dilute[m] = diluteFace(state, m, axis, f, diluteFraction) ? 1 : 0;
    }
    double gasDiagonal = a[0];
    for (std::size_t m = 1; m < M; ++m) gasDiagonal += dragV[m];
    // The gas: each solids velocity eliminated through its own equation; a dilute phase's drag
    // at its current velocity.
    double apGas = gasDiagonal, bGas = systems[0].b(f);
    for (std::size_t m = 1; m < M; ++m) {
      if (dilute[m] != 0) {
        bGas += dragV[m] * u[m];
        continue;
      }
      const double solidsDiagonal = a[m] + dragV[m];
      apGas -= dragV[m] * dragV[m] / solidsDiagonal;
      bGas += dragV[m] * H[m] / solidsDiagonal;
    }
    // Each solids phase: the gas velocity eliminated through the gas equation, the other solids
    // phases at their current iterate.
    for (std::size_t m = 1; m < M; ++m) {
      if (dilute[m] != 0) continue;
      double gasSide = H[0];
      for (std::size_t l = 1; l < M; ++l) {
        if (l != m) gasSide += dragV[l] * u[l];
      }
      systems[m].ap(f) = a[m] + dragV[m] - dragV[m] * dragV[m] / gasDiagonal;
      systems[m].b(f) += dragV[m] * gasSide / gasDiagonal;
    }
    systems[0].ap(f) = apGas;
    systems[0].b(f) = bGas;

    // The point-coupled matrix of the corrections over the phases with an equation here, its
    // diagonal relaxed as the systems are.
    std::vector<std::size_t> coupled;
    for (std::size_t m = 0; m < M; ++m) {
      if (dilute[m] == 0) coupled.push_back(m);
    }
    const auto n = static_cast<Eigen::Index>(coupled.size());
    Eigen::MatrixXd K = Eigen::MatrixXd::Zero(n, n);
    Eigen::VectorXd fractions(n);
    for (Eigen::Index i = 0; i < n; ++i) {
      const std::size_t m = coupled[static_cast<std::size_t>(i)];
      fractions[i] = meanOnFace(state.phases[m].fraction, axis, f) * A;
      K(i, i) += a[m] / relaxation;
      if (m > 0) {
        K(i, i) += dragV[m];
        K(0, 0) += dragV[m];
        K(0, i) = K(i, 0) = -dragV[m];
      }
    }
    const Eigen::PartialPivLU<Eigen::MatrixXd> lu(K);
    const Eigen::VectorXd d = lu.solve(fractions);
    for (Eigen::Index i = 0; i < n; ++i) {
      const std::size_t m = coupled[static_cast<std::size_t>(i)];
      out.pressure[m][f] = d[i];
      if (m > 0) {
        Eigen::VectorXd unit = Eigen::VectorXd::Zero(n);
        unit[i] = A;
        out.solidsPressure[m][f] = lu.solve(unit)[i];
      }
    }
  }
  for (std::size_t m = 0; m < M; ++m) {
    systems[m].relax(relaxation, state.phases[m].velocity[static_cast<std::size_t>(axis)].values());
  }
  return out;
}

}  // namespace grainbridge::fluid
