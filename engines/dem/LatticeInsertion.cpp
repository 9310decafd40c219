#include "engines/dem/LatticeInsertion.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/Error.hpp"

namespace grainbridge::dem {

std::vector<Vec3> fccLatticeSites(const Vec3& lo, const Vec3& hi, std::size_t count, double diameter,
                                  std::mt19937_64& rng) {
  const Vec3 length = hi - lo;
  if (count == 0) return {};
  // Cubic cells of 4 sites: start from the cell size that gives exactly `count` sites, round the
  // cell counts down, then add cells along the axis with the widest cells until there is room.
  const double a0 = std::cbrt(4.0 * length.prod() / static_cast<double>(count));
  std::array<long, 3> cells{};
  for (int d = 0; d < 3; ++d)
    cells[static_cast<std::size_t>(d)] = std::max(1L, std::lround(std::floor(length[d] / a0)));
  auto sites = [&] { return 4 * cells[0] * cells[1] * cells[2]; };
  while (sites() < static_cast<long>(count)) {
    int widest = 0;
    for (int d = 1; d < 3; ++d) {
      if (length[d] / static_cast<double>(cells[static_cast<std::size_t>(d)]) >
          length[widest] / static_cast<double>(cells[static_cast<std::size_t>(widest)]))
        widest = d;
    }
    ++cells[static_cast<std::size_t>(widest)];
  }
  const Vec3 a(length[0] / static_cast<double>(cells[0]), length[1] / static_cast<double>(cells[1]),
               length[2] / static_cast<double>(cells[2]));
  // Nearest neighbours sit half a face diagonal apart.
  const double nearest = 0.5 * std::min({std::hypot(a[0], a[1]), std::hypot(a[0], a[2]), std::hypot(a[1], a[2])});
  if (nearest < diameter * (1.0 + 1e-9)) {
    const double densest = static_cast<double>(count) * M_PI / 6.0 * diameter * diameter * diameter / length.prod() *
                           std::pow(nearest / diameter, 3);
    std::ostringstream msg;
    msg << "lattice insertion: " << count << " spheres of diameter " << diameter
        << " m do not fit on an fcc lattice in a " << length[0] << " x " << length[1] << " x " << length[2]
        << " m box (neighbours " << nearest << " m apart); the densest such lattice has solid fraction about "
        << densest;
    throw Error(msg.str());
  }
  const std::array<Vec3, 4> basis = {Vec3(0, 0, 0), Vec3(0.5, 0.5, 0), Vec3(0.5, 0, 0.5), Vec3(0, 0.5, 0.5)};
  std::vector<Vec3> out;
  out.reserve(static_cast<std::size_t>(sites()));
  for (long i = 0; i < cells[0]; ++i) {
    for (long j = 0; j < cells[1]; ++j) {
      for (long k = 0; k < cells[2]; ++k) {
        for (const auto& b : basis) {
          // A quarter cell in from the faces: no sphere centre on a periodic boundary.
          const Vec3 unit =
              Vec3(static_cast<double>(i), static_cast<double>(j), static_cast<double>(k)) + b + Vec3::Constant(0.25);
          out.push_back(lo + unit.cwiseProduct(a));
        }
      }
    }
  }
  std::shuffle(out.begin(), out.end(), rng);
  out.resize(count);
  return out;
}

}  // namespace grainbridge::dem
