#include "engines/fluid/InterphaseCoupling.hpp"

#include <Eigen/Dense>

#include "engines/fluid/Momentum.hpp"

namespace grainbridge::fluid {

CorrectionCoefficients coupleAndRelax(std::vector<StencilSystem>& systems, const FlowState& state,
                                      const FlowProperties& properties, int axis, double relaxation) {
  const StaggeredGrid& grid = state.grid();
  const std::size_t M = systems.size();
  const double V = grid.cellVolume(), A = grid.faceArea(axis);
  CorrectionCoefficients out;
  for (std::size_t m = 0; m < M; ++m) {
    out.pressure.emplace_back(grid, axis);
    out.solidsPressure.emplace_back(grid, axis);
  }
  std::vector<double> H(M), a(M), dragV(M, 0.0), u(M);
  Eigen::MatrixXd K(M, M);
  Eigen::VectorXd fractions(M);
  for (std::size_t f = 0; f < grid.paddedCount(); ++f) {
    if (!systems[0].active(f)) continue;
    for (std::size_t m = 0; m < M; ++m) {
      const auto& v = state.phases[m].velocity[static_cast<std::size_t>(axis)].values();
      H[m] = systems[m].neighbourSum(f, v);
      a[m] = systems[m].ap(f);
      u[m] = v[f];
      dragV[m] = m == 0 ? 0.0 : meanOnFace(properties.dragCoefficient[m], axis, f) * V;
      fractions[static_cast<Eigen::Index>(m)] = meanOnFace(state.phases[m].fraction, axis, f);
    }
    double gasDiagonal = a[0];
    for (std::size_t m = 1; m < M; ++m) gasDiagonal += dragV[m];
    // The gas: each solids velocity eliminated through its own equation.
    double apGas = gasDiagonal, bGas = systems[0].b(f);
    for (std::size_t m = 1; m < M; ++m) {
      const double solidsDiagonal = a[m] + dragV[m];
      if (solidsDiagonal <= 0.0) continue;
      apGas -= dragV[m] * dragV[m] / solidsDiagonal;
      bGas += dragV[m] * H[m] / solidsDiagonal;
    }
    // Each solids phase: the gas velocity eliminated through the gas equation, the other solids
    // phases at their current iterate.
    for (std::size_t m = 1; m < M; ++m) {
      double gasSide = H[0];
      for (std::size_t l = 1; l < M; ++l) {
        if (l != m) gasSide += dragV[l] * u[l];
      }
      const double ap = a[m] + dragV[m] - dragV[m] * dragV[m] / gasDiagonal;
      if (ap <= 1e-30 * (std::abs(a[0]) + 1.0)) {  // no solids and no drag: follow the gas
        systems[m].ap(f) = 1.0;
        for (int nb = 0; nb < 6; ++nb) systems[m].anb(f, nb) = 0.0;
        systems[m].b(f) = u[0];
        continue;
      }
      systems[m].ap(f) = ap;
      systems[m].b(f) += dragV[m] * gasSide / gasDiagonal;
    }
    systems[0].ap(f) = apGas;
    systems[0].b(f) = bGas;

    // The point-coupled matrix of the corrections, its diagonal relaxed as the systems are.
    K.setZero();
    for (std::size_t m = 0; m < M; ++m) {
      const auto i = static_cast<Eigen::Index>(m);
      K(i, i) = std::max(a[m], 0.0) / relaxation;
      if (m > 0) {
        K(i, i) += dragV[m];
        K(0, 0) += dragV[m];
        K(0, i) = K(i, 0) = -dragV[m];
      }
      if (K(i, i) <= 0.0) K(i, i) = 1e-30;
    }
    const Eigen::PartialPivLU<Eigen::MatrixXd> lu(K);
    const Eigen::VectorXd d = lu.solve(fractions * A);
    for (std::size_t m = 0; m < M; ++m) out.pressure[m][f] = d[static_cast<Eigen::Index>(m)];
    for (std::size_t m = 1; m < M; ++m) {
      Eigen::VectorXd unit = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(M));
      unit[static_cast<Eigen::Index>(m)] = A;
      out.solidsPressure[m][f] = lu.solve(unit)[static_cast<Eigen::Index>(m)];
    }
  }
  for (std::size_t m = 0; m < M; ++m) {
    systems[m].relax(relaxation, state.phases[m].velocity[static_cast<std::size_t>(axis)].values());
  }
  return out;
}

}  // namespace grainbridge::fluid
