#include "core/ClosureTableDraw.hpp"

#include <cmath>
#include <random>
#include <sstream>
#include <vector>

#include "core/Error.hpp"

namespace grainbridge::core {

namespace {

// FNV-1a of the quantity's name: the second word of the stream's seed.
std::uint64_t nameHash(const std::string& name) {
  std::uint64_t h = 1469598103934665603ULL;
  for (const unsigned char c : name) {
    h ^= c;
    h *= 1099511628211ULL;
  }
  return h;
}

}  // namespace

ClosureTable drawClosureTable(const ClosureTable& nominal, std::span<const double> standardErrors,
                              std::uint64_t seed) {
  const std::vector<double>& values = nominal.values();
  if (standardErrors.size() != values.size()) {
    std::ostringstream msg;
    msg << "closure table " << nominal.quantity() << ": " << standardErrors.size() << " standard errors for "
        << values.size() << " values";
    throw Error(msg.str());
  }
  for (std::size_t k = 0; k < standardErrors.size(); ++k) {
    if (!(standardErrors[k] >= 0.0) || !std::isfinite(standardErrors[k])) {
      std::ostringstream msg;
      msg << "closure table " << nominal.quantity() << ": node " << k << " has standard error " << standardErrors[k]
          << "; it must be finite and >= 0";
      throw Error(msg.str());
    }
  }
  const std::uint64_t words = nameHash(nominal.quantity());
  std::seed_seq seq{static_cast<std::uint32_t>(seed), static_cast<std::uint32_t>(seed >> 32),
                    static_cast<std::uint32_t>(words), static_cast<std::uint32_t>(words >> 32)};
  std::mt19937_64 rng(seq);
  std::normal_distribution<double> normal;
  std::vector<double> drawn(values.size());
  for (std::size_t k = 0; k < values.size(); ++k) {
    // Every node takes at least one number from the stream, so node k's draw does not depend on
    // whether an earlier node had an error.
    double value = values[k] + standardErrors[k] * normal(rng);
    for (int again = 0; values[k] > 0.0 && value <= 0.0; ++again) {
      if (again == 1000) throw Error("closure table " + nominal.quantity() + ": no positive draw at node " +
                                     std::to_string(k) + " in 1000 tries (its error dwarfs its value)");
      value = values[k] + standardErrors[k] * normal(rng);
    }
    drawn[k] = standardErrors[k] == 0.0 ? values[k] : value;
  }
  if (nominal.twoDimensional()) {
    return ClosureTable(nominal.quantity(), nominal.solidFractions(), nominal.secondVariable(), nominal.seconds(),
                        std::move(drawn));
  }
  return ClosureTable(nominal.quantity(), nominal.solidFractions(), std::move(drawn));
}

}  // namespace grainbridge::core
