#include "core/ClosureTableDraw.hpp"

#include <Eigen/Cholesky>
#include <Eigen/Core>
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

void checkErrors(const ClosureTable& nominal, std::span<const double> standardErrors) {
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
}

ClosureTable withValues(const ClosureTable& nominal, std::vector<double> values) {
  if (nominal.twoDimensional()) {
    return ClosureTable(nominal.quantity(), nominal.solidFractions(), nominal.secondVariable(), nominal.seconds(),
                        nominal.thirdVariable(), nominal.thirds(), std::move(values));
  }
  return ClosureTable(nominal.quantity(), nominal.solidFractions(), std::move(values));
}

bool sameLayout(const ClosureTable& a, const ClosureTable& b) {
  return a.solidFractions() == b.solidFractions() && a.seconds() == b.seconds() && a.thirds() == b.thirds();
}

}  // namespace

ClosureTable drawClosureTable(const ClosureTable& nominal, std::span<const double> standardErrors, std::uint64_t seed) {
  checkErrors(nominal, standardErrors);
  const std::vector<double>& values = nominal.values();
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
  return withValues(nominal, std::move(drawn));
}

std::vector<ClosureTable> drawClosureTablesJointly(std::span<const TableToDraw> tables, std::uint64_t seed) {
  const std::size_t q = tables.size();
  bool joint = q > 1;
  for (const auto& t : tables) {
    checkErrors(*t.nominal, t.standardErrors);
    joint = joint && sameLayout(*t.nominal, *tables.front().nominal);
  }
  // The correlation matrix of every node; none given means drawing table by table.
  const std::size_t nodes = tables.front().nominal->values().size();
  std::vector<Eigen::MatrixXd> matrices(
      nodes, Eigen::MatrixXd::Identity(static_cast<Eigen::Index>(q), static_cast<Eigen::Index>(q)));
  bool anyCorrelation = false;
  for (std::size_t i = 0; joint && i < q; ++i) {
    if (tables[i].correlations == nullptr) continue;
    for (const auto& [other, coefficients] : *tables[i].correlations) {
      std::size_t j = 0;
      while (j < q && tables[j].nominal->quantity() != other) ++j;
      if (j == q || j == i) continue;
      if (coefficients.size() != nodes) {
        throw Error("closure table " + tables[i].nominal->quantity() + ": " + std::to_string(coefficients.size()) +
                    " correlations with " + other + " for " + std::to_string(nodes) + " nodes");
      }
      for (std::size_t k = 0; k < nodes; ++k) {
        const double r = coefficients[k];
        if (!(std::abs(r) <= 1.0)) {
          throw Error("closure table " + tables[i].nominal->quantity() + ": node " + std::to_string(k) +
                      " has correlation " + std::to_string(r) + " with " + other + "; it must be in [-1, 1]");
        }
        auto& m = matrices[k];
        const auto a = static_cast<Eigen::Index>(std::min(i, j)), b = static_cast<Eigen::Index>(std::max(i, j));
        if (m(a, b) == 0.0 && r != 0.0) {  // the first table that has the pair gives it
          m(a, b) = m(b, a) = r;
          anyCorrelation = true;
        }
      }
    }
  }
  if (!joint || !anyCorrelation) {
    std::vector<ClosureTable> out;
    for (const auto& t : tables) out.push_back(drawClosureTable(*t.nominal, t.standardErrors, seed));
    return out;
  }
  std::string names = "joint";
  for (const auto& t : tables) names += ":" + t.nominal->quantity();
  const std::uint64_t words = nameHash(names);
  std::seed_seq seq{static_cast<std::uint32_t>(seed), static_cast<std::uint32_t>(seed >> 32),
                    static_cast<std::uint32_t>(words), static_cast<std::uint32_t>(words >> 32)};
  std::mt19937_64 rng(seq);
  std::normal_distribution<double> normal;
  std::vector<std::vector<double>> drawn(q, std::vector<double>(nodes));
  Eigen::VectorXd u(static_cast<Eigen::Index>(q));
  for (std::size_t k = 0; k < nodes; ++k) {
    Eigen::MatrixXd m = matrices[k];
    Eigen::LLT<Eigen::MatrixXd> cholesky(m);
    for (int shrink = 0; cholesky.info() != Eigen::Success; ++shrink) {
      // Estimated coefficients need not form a valid matrix: shrink them towards independence.
      if (shrink == 100)
        throw Error("closure tables: no positive definite correlation matrix at node " + std::to_string(k));
      m = 0.95 * m;
      m.diagonal().setOnes();
      cholesky.compute(m);
    }
    const Eigen::MatrixXd lower = cholesky.matrixL();
    for (int again = 0;; ++again) {
      // Every node takes q numbers per try from the stream; a positive value drawn at or below
      // zero draws the node's vector again (the joint normal truncated to positive values).
      for (std::size_t i = 0; i < q; ++i) u(static_cast<Eigen::Index>(i)) = normal(rng);
      const Eigen::VectorXd z = lower * u;
      bool positive = true;
      for (std::size_t i = 0; i < q; ++i) {
        const double value = tables[i].nominal->values()[k];
        const double error = tables[i].standardErrors[k];
        drawn[i][k] = error == 0.0 ? value : value + error * z(static_cast<Eigen::Index>(i));
        positive = positive && !(value > 0.0 && drawn[i][k] <= 0.0);
      }
      if (positive) break;
      if (again == 1000) {
        throw Error("closure tables: no positive joint draw at node " + std::to_string(k) +
                    " in 1000 tries (an error dwarfs its value)");
      }
    }
  }
  std::vector<ClosureTable> out;
  for (std::size_t i = 0; i < q; ++i) out.push_back(withValues(*tables[i].nominal, std::move(drawn[i])));
  return out;
}

}  // namespace grainbridge::core
