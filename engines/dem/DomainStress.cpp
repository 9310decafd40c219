#include "engines/dem/DomainStress.hpp"

#include "core/data/WholeDomainStress.hpp"

namespace grainbridge::dem {

Mat3 wholeDomainStress(const core::data::ParticleFrame& frame, double volume) {
  const auto sums = core::data::wholeDomainStressSums(frame);
  return (sums.kinetic + sums.contact) / volume;
}

}  // namespace grainbridge::dem
