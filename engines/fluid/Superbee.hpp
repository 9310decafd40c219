#pragma once
// The superbee TVD scheme of Section 3.3.2.1 in the down-wind-factor form of Eq. 3.60 (MFiX's
// xsi formulation, Syamlal 1998): the face value is a blend of the cells on either side,
//   u_e >= 0:  Phi_e = dwf Phi_E + (1 - dwf) Phi_P
//   u_e <  0:  Phi_e = dwf Phi_P + (1 - dwf) Phi_E
// with dwf = psi(r) / 2, psi the superbee limiter max(0, min(2r, 1), min(r, 2)) of the ratio r of
// the upwind gradient to the gradient across the face. r = 1 (a linear profile) gives dwf = 1/2,
// the second-order central value; an extremum (r <= 0) gives dwf = 0, first-order upwind; and
// 0 <= dwf <= 1 keeps the face value between its two cells (no new extrema: TVD).
// The solver uses it by deferred correction: upwind in the matrix, the difference to this face
// value in the source term.

namespace grainbridge::fluid {

// Superbee's limiter psi(r).
[[nodiscard]] constexpr double superbeeLimiter(double r) {
  const double a = r * 2.0 < 1.0 ? r * 2.0 : 1.0;
  const double b = r < 2.0 ? r : 2.0;
  const double m = a > b ? a : b;
  return m > 0.0 ? m : 0.0;
}

// The down-wind factor of a face from the values at the upwind cell's upwind neighbour
// (`farUpwind`), the upwind cell and the downwind cell. A face with no gradient across it takes
// the upwind value (dwf = 0).
[[nodiscard]] constexpr double superbeeDownwindFactor(double farUpwind, double upwind, double downwind) {
  const double across = downwind - upwind;
  if (across == 0.0) return 0.0;
  return 0.5 * superbeeLimiter((upwind - farUpwind) / across);
}

// Eq. 3.60 along one line of cells W, P, E, EE with the face e between P and E: the face value
// for the face velocity `u` (its sign picks the upwind side).
[[nodiscard]] constexpr double superbeeFaceValue(double u, double phiW, double phiP, double phiE, double phiEE) {
  if (u >= 0.0) {
    const double dwf = superbeeDownwindFactor(phiW, phiP, phiE);
    return dwf * phiE + (1.0 - dwf) * phiP;
  }
  const double dwf = superbeeDownwindFactor(phiEE, phiE, phiP);
  return dwf * phiP + (1.0 - dwf) * phiE;
}

}  // namespace grainbridge::fluid
