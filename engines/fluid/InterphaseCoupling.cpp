#include "engines/fluid/InterphaseCoupling.hpp"

#include <Eigen/Dense>

#include "engines/fluid/Momentum.hpp"

namespace grainbridge::fluid {

namespace {

// What one face's phases bring to the point-coupled solve.
struct FaceTerms {
  explicit FaceTerms(std::size_t M) : H(M), a(M), u(M), dilute(M, 0), X(Eigen::MatrixXd::Zero(M, M)) {}
  std::vector<double> H;      // neighbour sum plus b of each phase's equation
  std::vector<double> a;      // its diagonal
  std::vector<double> u;      // its velocity at the iterate
  std::vector<char> dilute;   // a dilute face (Momentum.hpp): kept out of the coupling
  Eigen::MatrixXd X;          // momentum-exchange coefficient times dV between phases, symmetric
};

// The buffers of a face's point-coupled solves, kept over the faces of an axis: sized once to
// the phases with an equation, they need no allocation per face (which, with an inverse and an
// LU per face, took a tenth of a binary bed's run time). Up to kStackPhases phases they live on
// the stack (Eigen's matrices of a bounded size); beyond, on the heap.
constexpr int kStackPhases = 8;
template <int MaxPhases>
struct PointWork {
  using Matrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::ColMajor, MaxPhases, MaxPhases>;
  using Vector = Eigen::Matrix<double, Eigen::Dynamic, 1, Eigen::ColMajor, MaxPhases, 1>;
  std::vector<std::size_t> coupled;  // the phases with an equation here (not dilute)
  Matrix K, inverse;
  Vector r, explicitPart, fractions, d;
  Eigen::PartialPivLU<Matrix> lu;
  // Selects the coupled phases of the face and zeroes K and explicitPart for them; their count.
  Eigen::Index select(const FaceTerms& t) {
    coupled.clear();
    for (std::size_t m = 0; m < t.dilute.size(); ++m) {
      if (t.dilute[m] == 0) coupled.push_back(m);
    }
    const auto n = static_cast<Eigen::Index>(coupled.size());
    K.setZero(n, n);
    explicitPart.setZero(n);
    return n;
  }
  // inverse = K^-1 over the first n rows and columns. Up to four phases (the gas and up to three
  // solids phases: every bed the reference runs) by Eigen's closed forms of a fixed size
  // (cofactors), beyond by its LU with partial pivoting. K is an M-matrix, diagonally dominant by
  // rows and columns (each diagonal is a_m plus the row's exchanges, which are the off-diagonals),
  // so partial pivoting would never swap a row and both are equally accurate; the closed forms
  // skip the dynamic LU's generic machinery, which took a fifth of a binary bed's run (issue 55).
  void invert(Eigen::Index n) {
    switch (n) {
      case 2:
        inverse = K.template topLeftCorner<2, 2>().inverse();
        break;
      case 3:
        inverse = K.template topLeftCorner<3, 3>().inverse();
        break;
      case 4:
        inverse = K.template topLeftCorner<4, 4>().inverse();
        break;
      default:
        lu.compute(K);
        inverse = lu.inverse();
    }
  }
};

// One solids phase (and no solids-solids drag): the closed form of Syamlal's partial elimination,
// written out as it has been since the engine's first bed (its results bit for bit).
void coupleGasAndOneSolids(std::vector<StencilSystem>& systems, const FaceTerms& t, std::size_t f) {
  const double drag = t.X(0, 1);
  const double gasDiagonal = t.a[0] + drag;
  if (t.dilute[1] != 0) {
    // The gas sees the dilute solids' drag at their current velocity.
    systems[0].ap(f) = gasDiagonal;
    systems[0].b(f) += drag * t.u[1];
    return;
  }
  const double solidsDiagonal = t.a[1] + drag;
  systems[0].ap(f) = gasDiagonal - drag * drag / solidsDiagonal;
  systems[0].b(f) += drag * t.H[1] / solidsDiagonal;
  systems[1].ap(f) = t.a[1] + drag - drag * drag / gasDiagonal;
  systems[1].b(f) += drag * t.H[0] / gasDiagonal;
}

// Any number of phases and exchanges: the point-coupled system K u = r over the phases with an
// equation here (K_mm = a_m + sum_l X_ml, K_ml = -X_ml; a dilute phase's exchange at its current
// velocity in r) is what the face's velocities satisfy when every neighbour is held at the
// iterate. Phase m's row of u = K^-1 r, divided by (K^-1)_mm, is again an equation for u_m alone,
//   u_m / (K^-1)_mm = r_m + sum_{l != m} (K^-1)_ml / (K^-1)_mm r_l,
// so each phase sees every exchange implicitly (Syamlal 1998's partial elimination, of which
// coupleGasAndOneSolids is the two-phase case).
template <class Work>
void couplePointMatrix(std::vector<StencilSystem>& systems, const FaceTerms& t, std::size_t f, Work& w) {
  const std::size_t M = systems.size();
  const Eigen::Index n = w.select(t);
  w.r.resize(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    const std::size_t m = w.coupled[static_cast<std::size_t>(i)];
    w.K(i, i) = t.a[m];
    for (std::size_t l = 0; l < M; ++l) {
      if (l == m) continue;
      w.K(i, i) += t.X(m, l);
      if (t.dilute[l] != 0) w.explicitPart[i] += t.X(m, l) * t.u[l];
    }
    for (Eigen::Index j = 0; j < n; ++j) {
      if (j != i) w.K(i, j) = -t.X(m, w.coupled[static_cast<std::size_t>(j)]);
    }
    w.r[i] = t.H[m] + w.explicitPart[i];
  }
  w.invert(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    const std::size_t m = w.coupled[static_cast<std::size_t>(i)];
    double b = systems[m].b(f) + w.explicitPart[i];
    for (Eigen::Index j = 0; j < n; ++j) {
      if (j != i) b += w.inverse(i, j) / w.inverse(i, i) * w.r[j];
    }
    systems[m].ap(f) = 1.0 / w.inverse(i, i);
    systems[m].b(f) = b;
  }
}

// The gas beside one given phase and nothing else (TF-DEM's particles): the general loop below
// with its matrices of one row written out, the same arithmetic in the same order (bit for bit),
// without the per-face bookkeeping that cost a coupled engine's gas step 3 %. The given phase's
// exchange is implicit in the gas's diagonal at its given velocity, and in the gas's correction
// coefficient d_g = eps_g A / (a_g / relaxation + X).
void coupleGasBesideGivenPhase(StencilSystem& gas, const FlowState& state, const FlowProperties& properties,
                               int axis, double relaxation, CorrectionCoefficients& out) {
  const StaggeredGrid& grid = state.grid();
  const double V = grid.cellVolume(), A = grid.faceArea(axis);
  const auto& given = state.phases[1].velocity[static_cast<std::size_t>(axis)].values();
  const CellField& drag = properties.dragCoefficient[1];
  const CellField& gasFraction = state.phases[0].fraction;
  FaceField& pressure = out.pressure[0];
  for (std::size_t f = 0; f < grid.paddedCount(); ++f) {
    if (!gas.active(f)) continue;
    const double a = gas.ap(f);
    const double x = meanOnFace(drag, axis, f) * V;
    gas.ap(f) = a + x;
    gas.b(f) += x * given[f];
    pressure[f] = meanOnFace(gasFraction, axis, f) * A / (a / relaxation + x);
  }
}

// Every face's point-coupled solve (the momentum exchange partially eliminated) and its correction
// coefficients, with the buffers Work.
template <class Work>
void coupleFaces(std::vector<StencilSystem>& systems, const FlowState& state, const FlowProperties& properties,
                 int axis, double relaxation, double diluteFraction, const std::vector<char>& given,
                 CorrectionCoefficients& out) {
  const StaggeredGrid& grid = state.grid();
  const std::size_t M = systems.size();
  const double V = grid.cellVolume(), A = grid.faceArea(axis);
  const auto isGiven = [&given](std::size_t m) { return !given.empty() && given[m] != 0; };
  const bool closedForm = M == 2 && properties.solidsDrag.empty();
  FaceTerms t(M);
  Work work;
  for (std::size_t f = 0; f < grid.paddedCount(); ++f) {
    if (!systems[0].active(f)) continue;
    t.X.setZero();
    for (std::size_t m = 0; m < M; ++m) {
      const auto& v = state.phases[m].velocity[static_cast<std::size_t>(axis)].values();
      const bool phaseGiven = isGiven(m);
      t.H[m] = phaseGiven ? 0.0 : systems[m].neighbourSum(f, v);
      t.a[m] = phaseGiven ? 0.0 : systems[m].ap(f);
      t.u[m] = v[f];
      t.dilute[m] = phaseGiven || diluteFace(state, m, axis, f, diluteFraction) ? 1 : 0;
      if (m > 0) t.X(0, m) = t.X(m, 0) = meanOnFace(properties.dragCoefficient[m], axis, f) * V;
    }
    for (const SolidsPairDrag& pair : properties.solidsDrag)
      t.X(pair.l, pair.m) = t.X(pair.m, pair.l) = meanOnFace(pair.coefficient, axis, f) * V;
    if (closedForm) {
      coupleGasAndOneSolids(systems, t, f);
    } else {
      couplePointMatrix(systems, t, f, work);
    }

    // The point-coupled matrix of the corrections over the phases with an equation here, its
    // diagonal relaxed as the systems are. A dilute phase's exchange stays out of it, as that
    // phase's velocity is not corrected.
    const Eigen::Index n = work.select(t);
    work.fractions.resize(n);
    for (Eigen::Index i = 0; i < n; ++i) {
      const std::size_t m = work.coupled[static_cast<std::size_t>(i)];
      work.fractions[i] = meanOnFace(state.phases[m].fraction, axis, f) * A;
      work.K(i, i) += t.a[m] / relaxation;
      for (Eigen::Index j = 0; j < n; ++j) {
        if (j == i) continue;
        const double x = t.X(m, work.coupled[static_cast<std::size_t>(j)]);
        work.K(i, i) += x;
        work.K(i, j) = -x;
      }
      for (std::size_t l = 1; l < M; ++l) {
        if (isGiven(l)) work.K(i, i) += t.X(m, l);
      }
    }
    if (n == 1) {
      // One phase with an equation here (the gas beside given or dilute solids): a division.
      const std::size_t m = work.coupled.front();
      out.pressure[m][f] = work.fractions[0] / work.K(0, 0);
      if (m > 0) out.solidsPressure[m][f] = A / work.K(0, 0);
      continue;
    }
    // d = K^-1 (eps A): each phase's velocity correction per unit gas pressure correction; and
    // (K^-1)_mm A, a solids phase's per unit of its own pressure gradient.
    work.invert(n);
    work.d.noalias() = work.inverse * work.fractions;
    for (Eigen::Index i = 0; i < n; ++i) {
      const std::size_t m = work.coupled[static_cast<std::size_t>(i)];
      out.pressure[m][f] = work.d[i];
      if (m > 0) out.solidsPressure[m][f] = work.inverse(i, i) * A;
    }
  }
}

}  // namespace

CorrectionCoefficients coupleAndRelax(std::vector<StencilSystem>& systems, const FlowState& state,
                                      const FlowProperties& properties, int axis, double relaxation,
                                      double diluteFraction, const std::vector<char>& given) {
  const StaggeredGrid& grid = state.grid();
  const std::size_t M = systems.size();
  CorrectionCoefficients out;
  for (std::size_t m = 0; m < M; ++m) {
    out.pressure.emplace_back(grid, axis);
    out.solidsPressure.emplace_back(grid, axis);
  }
  const auto isGiven = [&given](std::size_t m) { return !given.empty() && given[m] != 0; };
  const bool closedForm = M == 2 && properties.solidsDrag.empty();
  const bool gasBesideGiven = closedForm && isGiven(1);
  if (gasBesideGiven) {
    coupleGasBesideGivenPhase(systems[0], state, properties, axis, relaxation, out);
  } else if (M <= static_cast<std::size_t>(kStackPhases)) {
    coupleFaces<PointWork<kStackPhases>>(systems, state, properties, axis, relaxation, diluteFraction, given, out);
  } else {
    coupleFaces<PointWork<Eigen::Dynamic>>(systems, state, properties, axis, relaxation, diluteFraction, given, out);
  }
  for (std::size_t m = 0; m < M; ++m) {
    if (!isGiven(m)) systems[m].relax(relaxation, state.phases[m].velocity[static_cast<std::size_t>(axis)].values());
  }
  return out;
}

}  // namespace grainbridge::fluid
