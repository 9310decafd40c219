// Contact part of Eq. 2.3 for a uniformly compressed simple-cubic lattice (spacing a) whose
// contacts along axis alpha all carry the same force G_alpha on i (normal compression plus a
// tangential part): the applied stress is sigma = sum_alpha (-a e_alpha) G_alpha^T / a^3. It
// must come out to round-off over the whole domain, and in every interior cell with bins and with
// smooth kernels (cells two lattice spacings wide; lattice offset from the cell faces).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdio>

#include "extract/coarse/CoarseGrain.hpp"
#include "extract/coarse/DomainAverages.hpp"
#include "tests/extract/coarse/CoarseTestFrames.hpp"
#include "tests/support/ValidationNote.hpp"
#include "tests/support/ValidationRecord.hpp"

using namespace grainbridge;
using namespace grainbridge::extract::coarse;
using namespace grainbridge::extract::coarse::testing;

namespace {
constexpr double kA = 1.0;  // lattice spacing
const std::array<Vec3, 3> kForce{Vec3(-3.0, 0.4, 0.0), Vec3(0.0, -2.0, 0.0), Vec3(0.1, 0.0, -1.5)};

Mat3 appliedStress() {
  Mat3 s = Mat3::Zero();
  for (int a = 0; a < 3; ++a) s += (-kA * Vec3::Unit(a)) * kForce[static_cast<std::size_t>(a)].transpose();
  return s / (kA * kA * kA);
}

// n^3 particles at (i + 0.3) a; each has a contact with its +alpha neighbour on each axis
// (branch r_i - r_j = -a e_alpha), wrapping when periodic.
core::data::ParticleFrame lattice(int n, bool periodic) {
  core::data::ParticleFrame f;
  f.domain.lo = Vec3::Zero();
  f.domain.hi = Vec3::Constant(n * kA);
  f.domain.periodic = {periodic, periodic, periodic};
  const auto id = [n](int i, int j, int k) { return static_cast<std::int64_t>((k * n + j) * n + i); };
  for (int k = 0; k < n; ++k) {
    for (int j = 0; j < n; ++j) {
      for (int i = 0; i < n; ++i) {
        addParticle(f, id(i, j, k), 0, 0.5 * kA, 1.0, kA * Vec3(i + 0.3, j + 0.3, k + 0.3), Vec3::Zero());
      }
    }
  }
  for (int k = 0; k < n; ++k) {
    for (int j = 0; j < n; ++j) {
      for (int i = 0; i < n; ++i) {
        const std::array<int, 3> p{i, j, k};
        for (int a = 0; a < 3; ++a) {
          std::array<int, 3> q = p;
          q[static_cast<std::size_t>(a)] += 1;
          if (q[static_cast<std::size_t>(a)] == n) {
            if (!periodic) continue;
            q[static_cast<std::size_t>(a)] = 0;
          }
          addContact(f, id(i, j, k), id(q[0], q[1], q[2]), -kA * Vec3::Unit(a), kForce[static_cast<std::size_t>(a)]);
        }
      }
    }
  }
  return f;
}

double worst = 0.0;            // largest relative error seen, printed per test
Mat3 worstGot = Mat3::Zero();  // the stress with that error, and whether every one passed: for the record
bool allPassed = true;

void expectStress(const Mat3& got, const Mat3& want, const std::string& where) {
  const double relative = (got - want).norm() / want.norm();
  if (relative >= worst) worstGot = got;
  worst = std::max(worst, relative);
  allPassed = allPassed && relative < 1e-12;
  EXPECT_LT(relative, 1e-12) << where << "\n" << got << "\nexpected\n" << want;
}

// Records the checks since the last record (the mean normal stress of the worst one against the
// applied stress's) and starts over.
void recordLattice(const std::string& id, const std::string& check, const std::string& note) {
  const Mat3 applied = appliedStress();
  grainbridge::testing::recordValidation(
      {id, "Extraction (Section 2.3, Sections 6.3.2-6.3.3)", check, "Eq. 2.3", applied.trace() / 3.0,
       worstGot.trace() / 3.0, "round-off (1e-12)", allPassed,
       grainbridge::testing::formatNote("mean normal stress tr(sigma)/3 shown; the whole tensor (normal and "
                                        "tangential contact forces) is compared, largest relative Frobenius error "
                                        "%.1e; ",
                                        worst) +
           note});
  worstGot = Mat3::Zero();
  allPassed = true;
}
}  // namespace

TEST(LatticeContactStress, WholeDomainEqualsTheAppliedStress) {
  const auto f = lattice(6, true);
  const auto avg = averageWholeDomain(f);
  expectStress(avg.contactStress, appliedStress(), "whole domain");
  recordLattice("extract.contact_stress.lattice.whole_domain",
                "contact part of Eq. 2.3 for a uniformly compressed periodic simple-cubic lattice, whole domain, "
                "against the applied stress",
                "6^3 particles");
  worst = 0.0;
  EXPECT_TRUE(avg.kineticStress.isZero());
  EXPECT_NEAR(avg.coordinationNumber, 6.0, 1e-15);
  EXPECT_NEAR(avg.multiContactRatio, 1.0, 1e-15);
}

TEST(LatticeContactStress, EveryCellOfAPeriodicLatticeWithEachKernel) {
  const auto f = lattice(8, true);
  const core::grid::CellGrid grid(f.domain.lo, f.domain.hi, {4, 4, 4}, {true, true, true});
  for (const auto& kernel : {CoarseGrainingKernel::bin(), CoarseGrainingKernel::overlap(),
                             CoarseGrainingKernel::gaussian(0.7 * kA), CoarseGrainingKernel::lucy(0.6 * kA)}) {
    const auto cg = coarseGrain(f, grid, kernel);
    for (std::size_t c = 0; c < grid.cellCount(); ++c) {
      expectStress(cg.contactStress[c], appliedStress(), kernel.name() + " cell " + std::to_string(c));
    }
    std::printf("  %s periodic cells: worst relative error %.1e\n", kernel.name().c_str(), worst);
    recordLattice("extract.contact_stress.lattice.periodic_cells." + kernel.name(),
                  "contact part of Eq. 2.3 for a uniformly compressed periodic simple-cubic lattice, every cell with "
                  "the " +
                      kernel.name() + " kernel, against the applied stress",
                  "8^3 particles, 4^3 cells two lattice spacings wide, lattice offset from the cell faces");
    worst = 0.0;
  }
}

TEST(LatticeContactStress, InteriorCellsOfAFiniteLatticeWithBinsAndLucy) {
  // 12^3 particles in a non-periodic box of 6^3 cells: cells 1..4 on every axis see every
  // contact their kernel reaches (Lucy cutoff 2 sqrt(3) 0.6 a = 2.08 a from the cell centre).
  const int n = 12;
  const auto f = lattice(n, false);
  const core::grid::CellGrid grid(f.domain.lo, f.domain.hi, {6, 6, 6});
  for (const auto& kernel : {CoarseGrainingKernel::bin(), CoarseGrainingKernel::lucy(0.6 * kA)}) {
    const auto cg = coarseGrain(f, grid, kernel);
    int interior = 0;
    for (int k = 1; k <= 4; ++k) {
      for (int j = 1; j <= 4; ++j) {
        for (int i = 1; i <= 4; ++i) {
          const std::size_t c = grid.flatIndex({i, j, k});
          expectStress(cg.contactStress[c], appliedStress(), kernel.name() + " cell " + std::to_string(c));
          ++interior;
        }
      }
    }
    EXPECT_EQ(interior, 64);
    std::printf("  %s interior cells: worst relative error %.1e\n", kernel.name().c_str(), worst);
    recordLattice("extract.contact_stress.lattice.finite_interior." + kernel.name(),
                  "contact part of Eq. 2.3 for a uniformly compressed finite simple-cubic lattice, the 64 interior "
                  "cells with the " +
                      kernel.name() + " kernel, against the applied stress",
                  "12^3 particles in a non-periodic box of 6^3 cells");
    worst = 0.0;
    // A boundary cell misses the contacts beyond the lattice.
    EXPECT_LT(cg.contactStress[grid.flatIndex({0, 2, 2})](0, 0), 0.9 * appliedStress()(0, 0));
  }
}
