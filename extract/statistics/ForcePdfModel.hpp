#pragma once
// The empirical force PDFs of the reference:
//   Eq. 6.11 (Mueth et al. 1998):  P(f) = a (1 - b e^{-f^2}) e^{-beta f}
//   Eq. 6.13 (shifted, for MST forces):  P(f) = a (1 - b e^{-(f - alpha)^2}) e^{-beta (f - gamma)}
// with f = F_n / <F_n>. Eq. 6.11 is Eq. 6.13 with alpha = gamma = 0, so one model serves both.
// Neither is normalised by construction: the reference's a = 2.46, b = 0.83, beta = 1.35
// integrates to 0.85 over f >= 0, while b = 0.68 (Fig. 6.12 caption) gives 1.03.
#include <array>
#include <string>

namespace grainbridge::extract::statistics {

struct ForcePdfParams {
  double a = 1.0;
  double b = 0.0;
  double beta = 1.0;
  double alpha = 0.0;
  double gamma = 0.0;

  // Order used by gradients, covariances and the free-parameter mask: a, b, beta, alpha, gamma.
  static constexpr std::size_t kCount = 5;
  [[nodiscard]] std::array<double, kCount> toArray() const { return {a, b, beta, alpha, gamma}; }
  static ForcePdfParams fromArray(const std::array<double, kCount>& v) { return {v[0], v[1], v[2], v[3], v[4]}; }
  static const char* name(std::size_t k);
};

// P(f) of Eq. 6.13 (Eq. 6.11 when alpha = gamma = 0).
[[nodiscard]] double forcePdf(const ForcePdfParams& p, double f);
// dP/d(a, b, beta, alpha, gamma) at f.
[[nodiscard]] std::array<double, ForcePdfParams::kCount> forcePdfGradient(const ForcePdfParams& p, double f);
// Z = integral of P over [0, inf), in closed form:
//   Z = a e^{beta gamma} [ 1/beta - b (sqrt(pi)/2) e^{beta^2/4 - beta alpha} erfc(beta/2 - alpha) ].
// Throws grainbridge::Error if beta <= 0 (the density is then not integrable).
[[nodiscard]] double forcePdfIntegral(const ForcePdfParams& p);

}  // namespace grainbridge::extract::statistics
