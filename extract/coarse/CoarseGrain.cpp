#include "extract/coarse/CoarseGrain.hpp"

#include <cmath>
#include <sstream>

#include "core/Error.hpp"
#include "core/grid/CellShare.hpp"
#include "core/grid/KernelCellShares.hpp"
#include "core/grid/SegmentCellShares.hpp"
#include "core/grid/SphereCellOverlap.hpp"
#include "extract/coarse/FrameSpecies.hpp"
#include "extract/coarse/ParticleContacts.hpp"
#include "extract/coarse/StreamingProfile.hpp"
#include "extract/coarse/StressMeasures.hpp"

namespace grainbridge::extract::coarse {

namespace {

using core::grid::CellGrid;
using core::grid::CellShares;

// A periodic grid axis folds images by its own length, so it must be the domain's periodic box.
CellGrid gridForFrame(const CellGrid& grid, const core::data::Domain& domain) {
  const char* names[3] = {"x", "y", "z"};
  for (int a = 0; a < 3; ++a) {
    const auto s = static_cast<std::size_t>(a);
    if (!grid.periodic()[s]) continue;
    const double tol = 1e-12 * (domain.hi[a] - domain.lo[a]);
    if (!domain.periodic[s] || std::abs(grid.lo()[a] - domain.lo[a]) > tol ||
        std::abs(grid.hi()[a] - domain.hi[a]) > tol) {
      std::ostringstream msg;
      msg << "coarse graining: the grid is periodic in " << names[a] << " over [" << grid.lo()[a] << ", "
          << grid.hi()[a] << "] but the domain is " << (domain.periodic[s] ? "periodic" : "not periodic")
          << " there over [" << domain.lo[a] << ", " << domain.hi[a]
          << "]; make the grid span the periodic domain, or not periodic";
      throw Error(msg.str());
    }
  }
  if (grid.periodic()[1] && domain.leesEdwardsOffset != 0.0)
    return grid.withLeesEdwardsOffset(domain.leesEdwardsOffset);
  return grid;
}

struct Moments {
  std::vector<double> volume, mass;
  std::vector<Vec3> momentum, peculiarMomentum;
  explicit Moments(std::size_t cells)
      : volume(cells, 0.0), mass(cells, 0.0), momentum(cells, Vec3::Zero()), peculiarMomentum(cells, Vec3::Zero()) {}
};

}  // namespace

CoarseFields coarseGrain(const core::data::ParticleFrame& frame, const CellGrid& userGrid,
                         const CoarseGrainingKernel& kernel) {
  frame.validate();
  const CellGrid grid = gridForFrame(userGrid, frame.domain);
  const auto smooth = kernel.smoothingKernel();
  if (smooth) core::grid::checkKernelResolvesGrid(grid, *smooth);
  const auto index = indexById(frame);
  const ParticleContacts contacts = particleContacts(frame, index);
  const FrameSpecies species = frameSpecies(frame);
  const std::size_t n = frame.size();
  const std::size_t cells = grid.cellCount();
  const std::size_t nSpecies = species.ids.size();
  const double cellVolume = grid.cellVolume();

  // Shares of every particle, kept for the second pass (fluctuations about the local mean).
  std::vector<std::size_t> offset(n + 1, 0);
  CellShares shares, one;
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3& x = frame.position[i];
    switch (kernel.kind) {
      case KernelKind::Bin:
        // Eq. 7.35: the whole particle in the cell holding its centre.
        one.clear();
        if (const auto cell = grid.cellOf(x)) one.push_back({grid.flatIndex(*cell), 1.0});
        break;
      case KernelKind::Overlap:
        core::grid::sphereCellShares(grid, x, frame.radius[i], one);
        break;
      case KernelKind::Gaussian:
      case KernelKind::Lucy:
        core::grid::kernelPointShares(grid, *smooth, x, one);
        break;
    }
    shares.insert(shares.end(), one.begin(), one.end());
    offset[i + 1] = shares.size();
  }

  std::vector<Vec3> peculiar(n);
  for (std::size_t i = 0; i < n; ++i)
    peculiar[i] = frame.velocity[i] - streamingVelocity(frame.domain, frame.position[i]);

  // First pass: volume, mass and momentum per cell, in total and per species.
  Moments total(cells);
  std::vector<Moments> bySpecies(nSpecies, Moments(cells));
  for (std::size_t i = 0; i < n; ++i) {
    const double r = frame.radius[i];
    const double vp = 4.0 / 3.0 * M_PI * r * r * r;
    const double m = frame.mass[i];
    Moments& sp = bySpecies[species.slot[i]];
    for (std::size_t s = offset[i]; s < offset[i + 1]; ++s) {
      const std::size_t c = shares[s].cell;
      const double f = shares[s].fraction;
      for (Moments* mom : {&total, &sp}) {
        mom->volume[c] += vp * f;
        mom->mass[c] += m * f;
        mom->momentum[c] += m * f * frame.velocity[i];
        mom->peculiarMomentum[c] += m * f * peculiar[i];
      }
    }
  }
  const auto meanOf = [](const std::vector<Vec3>& p, const std::vector<double>& m) {
    std::vector<Vec3> u(p.size(), Vec3::Zero());
    for (std::size_t c = 0; c < p.size(); ++c) {
      if (m[c] > 0.0) u[c] = p[c] / m[c];
    }
    return u;
  };
  const std::vector<Vec3> meanPeculiar = meanOf(total.peculiarMomentum, total.mass);
  std::vector<std::vector<Vec3>> speciesMeanPeculiar(nSpecies);
  for (std::size_t k = 0; k < nSpecies; ++k) {
    speciesMeanPeculiar[k] = meanOf(bySpecies[k].peculiarMomentum, bySpecies[k].mass);
  }

  // Second pass: fluctuations C = v' - u'(cell), summed as m C C phi (two passes rather than
  // sum m v v - rho u u, which cancels badly when the mean flow dominates).
  std::vector<Mat3> kinetic(cells, Mat3::Zero());
  std::vector<std::vector<double>> speciesC2(nSpecies, std::vector<double>(cells, 0.0));
  for (std::size_t i = 0; i < n; ++i) {
    const double m = frame.mass[i];
    const std::size_t k = species.slot[i];
    for (std::size_t s = offset[i]; s < offset[i + 1]; ++s) {
      const std::size_t c = shares[s].cell;
      const double f = shares[s].fraction;
      const Vec3 C = peculiar[i] - meanPeculiar[c];
      kinetic[c] += m * f * C * C.transpose();
      speciesC2[k][c] += m * f * (peculiar[i] - speciesMeanPeculiar[k][c]).squaredNorm();
    }
  }

  // Contact part of Eq. 2.3: full r_ij F_ij of each contact along its contact line.
  std::vector<Mat3> contact(cells, Mat3::Zero());
  const auto spread = [&](const Vec3& start, const Vec3& branch, const Vec3& force) {
    const Vec3 end = start - branch;
    if (smooth) {
      core::grid::kernelSegmentShares(grid, *smooth, start, end, one);
    } else {
      core::grid::segmentCellShares(grid, start, end, one);
    }
    const Mat3 product = branch * force.transpose();
    for (const auto& s : one) contact[s.cell] += s.fraction * product;
  };
  const auto& pc = frame.contacts;
  for (std::size_t k = 0; k < pc.size(); ++k) {
    const Vec3& ri = frame.position[index.at(pc.i[k])];
    spread(ri, pc.branch[k], pc.forceNormal[k] + pc.forceTangential[k]);
  }
  const auto& wc = frame.wallContacts;
  for (std::size_t k = 0; k < wc.size(); ++k) {
    const Vec3& ri = frame.position[index.at(wc.particle[k])];
    spread(ri, ri - wc.point[k], wc.forceNormal[k] + wc.forceTangential[k]);
  }

  CoarseFields out(grid, kernel);
  out.solidFraction.resize(cells);
  out.density.resize(cells);
  out.velocity = meanOf(total.momentum, total.mass);
  out.granularTemperature.assign(cells, 0.0);
  out.kineticStress.resize(cells);
  out.contactStress.resize(cells);
  out.stress.resize(cells);
  out.pressure.resize(cells);
  out.shearStress.resize(cells);
  out.deviatoricStress.resize(cells);
  for (std::size_t c = 0; c < cells; ++c) {
    out.solidFraction[c] = total.volume[c] / cellVolume;
    out.density[c] = total.mass[c] / cellVolume;
    out.kineticStress[c] = kinetic[c] / cellVolume;
    out.contactStress[c] = contact[c] / cellVolume;
    out.stress[c] = out.kineticStress[c] + out.contactStress[c];
    // Eq. 3.38, mass-weighted: T = sum m C^2 phi / (3 sum m phi).
    if (total.mass[c] > 0.0) out.granularTemperature[c] = kinetic[c].trace() / (3.0 * total.mass[c]);
    out.pressure[c] = pressure(out.stress[c]);
    out.shearStress[c] = shearStress(out.stress[c]);
    out.deviatoricStress[c] = deviatoricNorm(out.stress[c]);
  }
  out.species.resize(nSpecies);
  for (std::size_t k = 0; k < nSpecies; ++k) {
    SpeciesCellFields& sf = out.species[k];
    const Moments& mom = bySpecies[k];
    sf.species = species.ids[k];
    sf.solidFraction.resize(cells);
    sf.density.resize(cells);
    sf.velocity = meanOf(mom.momentum, mom.mass);
    sf.granularTemperature.assign(cells, 0.0);
    for (std::size_t c = 0; c < cells; ++c) {
      sf.solidFraction[c] = mom.volume[c] / cellVolume;
      sf.density[c] = mom.mass[c] / cellVolume;
      if (mom.mass[c] > 0.0) sf.granularTemperature[c] = speciesC2[k][c] / (3.0 * mom.mass[c]);
    }
  }

  // Contact statistics by particle centre (Figs. 7.5-7.7, 7.11).
  std::vector<double> inContact(cells, 0.0), multi(cells, 0.0), contactSum(cells, 0.0);
  std::vector<Vec3> contactForce(cells, Vec3::Zero()), drag(cells, Vec3::Zero());
  out.particleCount.assign(cells, 0.0);
  for (std::size_t i = 0; i < n; ++i) {
    const auto cell = grid.cellOf(frame.position[i]);
    if (!cell) continue;
    const std::size_t c = grid.flatIndex(*cell);
    out.particleCount[c] += 1.0;
    contactSum[c] += contacts.count[i];
    if (contacts.count[i] >= 1) inContact[c] += 1.0;
    if (contacts.count[i] >= 2) multi[c] += 1.0;
    contactForce[c] += contacts.totalForce[i];
    if (!frame.externalForce.empty()) drag[c] += frame.externalForce[i];
  }
  out.coordinationNumber.assign(cells, 0.0);
  out.multiContactRatio.assign(cells, 0.0);
  out.contactForce.resize(cells);
  out.dragForce.resize(cells);
  out.contactToDragRatio.resize(cells);
  for (std::size_t c = 0; c < cells; ++c) {
    if (out.particleCount[c] > 0.0) out.coordinationNumber[c] = contactSum[c] / out.particleCount[c];
    if (inContact[c] > 0.0) out.multiContactRatio[c] = multi[c] / inContact[c];
    out.contactForce[c] = contactForce[c].norm();
    out.dragForce[c] = drag[c].norm();
    out.contactToDragRatio[c] = out.dragForce[c] > 0.0 ? out.contactForce[c] / out.dragForce[c] : -1.0;
  }
  return out;
}

}  // namespace grainbridge::extract::coarse
