#pragma once
// Time average of a quantity over saved frames with a standard error that accounts for the
// correlation between successive frames: the blocking transformation of Flyvbjerg and Petersen
// (J. Chem. Phys. 91, 461, 1989). Neighbouring samples are averaged in pairs level after level;
// the naive standard error of the block means grows with the block size until blocks are longer
// than the correlation time, then levels off at the plateau, the error of the mean. The level
// used is the smallest block size B (in frames) with B^3 > 2 n (SE_B / SE_1)^4 (Lee, Conduit,
// Nemec, Lopez Rios and Drummond, Phys. Rev. E 83, 066706, 2011, Eq. 14; also pyblock's rule),
// which balances the residual correlation against the noise of having few blocks.
//
// The error reported is that level's, extrapolated to the plateau: at a level not far beyond the
// correlation time the blocked error is still below it (the 1/B approach), and for the 80-400
// frames a closure point has, the level alone is short by 10-30 %. The extrapolation takes the
// series' correlation as exponential (an AR(1) process, whose blocking curve is known in closed
// form) with the integrated correlation time the extrapolated error itself implies, and solves
// for the variance of the mean; white noise is left as it is, and the correction is capped at a
// factor 2 in variance (beyond it the level says too little, plateauReached = false). Issue 63:
// over 400 AR(1) series of correlation 0.9 (integrated time 9.5 samples), the level alone gave
// 0.865 of the true error at n = 200 and 0.940 at 400 (root mean square; BlockAverageTest), the
// extrapolated 1.066 and 1.041; a sheared gas's temperature has that correlation at 5 ms frames.
// A slower component the level has not seen (white noise plus a weak slow exponential) stays
// underestimated, by about 5 % in a prototype of that test, as by the level alone.
//
// Fewer than kMinSamplesForBlocking frames give the plain standard error sqrt(var / (n - 1)),
// which assumes independent frames (method PlainFewSamples says so). When no level meets the
// criterion (levels of fewer than kMinBlocks blocks never count: their error is chance) the
// deepest level with at least kMinBlocks blocks is used, extrapolated the same way, and
// plateauReached = false: the run is too short for its correlation time, and its error is a
// lower bound (a closure point records the warning).
#include <cstddef>
#include <span>
#include <vector>

namespace grainbridge::core::averaging {

struct BlockAverage {
  enum class Method { Blocking, PlainFewSamples };
  static constexpr std::size_t kMinSamplesForBlocking = 16;
  // No level with fewer blocks is reported, by the criterion or the fallback.
  static constexpr std::size_t kMinBlocks = 4;

  double mean = 0.0;
  double standardError = 0.0;             // of the mean
  // Of the standard error: from the blocked variances' own errors, 2 / (blocks - 1) relative.
  double standardErrorUncertainty = 0.0;
  double levelStandardError = 0.0;  // the naive SE at the level used, before the extrapolation
  std::size_t samples = 0;
  std::size_t blockSize = 1;  // frames per block at the reported level
  Method method = Method::PlainFewSamples;
  bool plateauReached = false;
  std::vector<double> standardErrorByLevel;  // naive SE at block sizes 1, 2, 4, ...
};

// Throws grainbridge::Error for an empty series or one with a non-finite value.
BlockAverage blockAverage(std::span<const double> samples);

// Per-cell time average of a field over frames: frames[f][cell]. Every frame must have the
// same number of cells (grainbridge::Error otherwise).
std::vector<BlockAverage> blockAverageCells(const std::vector<std::vector<double>>& frames);

}  // namespace grainbridge::core::averaging
