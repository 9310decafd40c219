#pragma once
// Time average of a quantity over saved frames with a standard error that accounts for the
// correlation between successive frames: the blocking transformation of Flyvbjerg and Petersen
// (J. Chem. Phys. 91, 461, 1989). Neighbouring samples are averaged in pairs level after level;
// the naive standard error of the block means grows with the block size until blocks are longer
// than the correlation time, then levels off. The level reported is the smallest block size B
// (in frames) with B^3 > 2 n (SE_B / SE_1)^4 (Lee, Conduit, Nemec, Lopez Rios and Drummond,
// Phys. Rev. E 83, 066706, 2011, Eq. 14; also pyblock's rule), which balances the residual
// correlation bias against the noise of having few blocks.
//
// Fewer than kMinSamplesForBlocking frames give the plain standard error sqrt(var / (n - 1)),
// which assumes independent frames (method PlainFewSamples says so). When no level meets the
// criterion (levels of fewer than kMinBlocks blocks never count: their error is chance) the
// largest estimate over levels with at least kMinBlocks blocks is reported, flagged
// plateauReached = false: the run is too short for its correlation time.
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
  double standardErrorUncertainty = 0.0;  // SE / sqrt(2 (blocks - 1)) at the reported level
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
