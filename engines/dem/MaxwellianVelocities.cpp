#include "engines/dem/MaxwellianVelocities.hpp"

#include <cmath>

namespace grainbridge::dem {

std::vector<Vec3> maxwellianVelocities(std::size_t n, double temperature, std::mt19937_64& rng) {
  std::vector<Vec3> velocity(n, Vec3::Zero());
  std::normal_distribution<double> normal(0.0, 1.0);
  Vec3 mean = Vec3::Zero();
  for (auto& v : velocity) {
    v = Vec3(normal(rng), normal(rng), normal(rng));
    mean += v;
  }
  mean /= static_cast<double>(n);
  double sumC2 = 0.0;
  for (auto& v : velocity) {
    v -= mean;
    sumC2 += v.squaredNorm();
  }
  const double scale =
      (n > 1 && sumC2 > 0.0 && temperature > 0.0) ? std::sqrt(3.0 * static_cast<double>(n) * temperature / sumC2) : 0.0;
  for (auto& v : velocity) v *= scale;
  return velocity;
}

}  // namespace grainbridge::dem
