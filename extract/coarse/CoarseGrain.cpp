#include "extract/coarse/CoarseGrain.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <sstream>
#include <type_traits>

#include "core/Error.hpp"
#include "core/grid/CellShare.hpp"
#include "core/grid/KernelCellShares.hpp"
#include "core/grid/SegmentCellShares.hpp"
#include "core/grid/SphereCellOverlap.hpp"
#include "extract/coarse/ParticleContacts.hpp"
#include "core/data/StreamingProfile.hpp"
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

constexpr std::size_t npos = static_cast<std::size_t>(-1);

// The cells [begin, end) that deposits reached (flat indices: a layer of particles on the floor
// of a box is one contiguous range).
struct CellRange {
  std::size_t begin = npos, end = 0;
  void add(std::size_t c) {
    begin = std::min(begin, c);
    end = std::max(end, c + 1);
  }
  [[nodiscard]] bool empty() const { return begin >= end; }
};

template <class T>
T zeroOf() {
  if constexpr (std::is_arithmetic_v<T>) {
    return T(0);
  } else {
    return T::Zero();
  }
}

}  // namespace

CoarseFields& CoarseGrainer::prepare(const CellGrid& grid, const CoarseGrainingKernel& kernel, const Layout& layout) {
  if (!fields_) fields_.emplace(grid, kernel);
  CoarseFields& out = *fields_;
  out.grid = grid;
  out.kernel = kernel;
  const std::size_t cells = layout.cells;
  const bool oneSpecies = layout.species == 1;
  // A new layout starts from fresh arrays, to be finalised everywhere; otherwise only the cells
  // the last frame reached hold anything to clear.
  const bool fresh = !(layout_ == layout);
  if (fresh) {
    dirtyBegin_ = 0;
    dirtyEnd_ = cells;
  }
  const auto clear = [&](auto& v) {
    using T = typename std::decay_t<decltype(v)>::value_type;
    const T zero = zeroOf<T>();
    if (fresh) {
      v.assign(cells, zero);
    } else {
      std::fill(v.begin() + static_cast<std::ptrdiff_t>(dirtyBegin_),
                v.begin() + static_cast<std::ptrdiff_t>(dirtyEnd_), zero);
    }
  };
  // Accumulated by the passes over particles and contacts (the solid fraction, density,
  // velocity, coordination and multi-contact arrays hold volume, mass, momentum and counts
  // until finalised); the rest is only written.
  clear(out.solidFraction);
  clear(out.density);
  clear(out.velocity);
  clear(out.kineticStress);
  clear(out.contactStress);
  clear(out.particleCount);
  clear(out.coordinationNumber);
  clear(out.multiContactRatio);
  out.granularTemperature.resize(cells);
  out.stress.resize(cells);
  out.pressure.resize(cells);
  out.shearStress.resize(cells);
  out.deviatoricStress.resize(cells);
  out.contactForce.resize(cells);
  out.dragForce.resize(cells);
  out.contactToDragRatio.resize(cells);
  out.species.resize(layout.species);
  for (SpeciesCellFields& sf : out.species) {
    clear(sf.granularTemperature);
    // A single species' moments are the totals: copied at the end rather than summed twice.
    if (oneSpecies) continue;
    clear(sf.solidFraction);
    clear(sf.density);
    clear(sf.velocity);
  }
  if (layout.sheared) {
    clear(meanPeculiar_);
    speciesMeanPeculiar_.resize(oneSpecies ? 0 : layout.species);
    for (auto& u : speciesMeanPeculiar_) clear(u);
  }
  clear(inContact_);
  clear(contactForce_);
  if (layout.drag) clear(drag_);
  return out;
}

CoarseFields CoarseGrainer::release() {
  CoarseFields out = std::move(fields_.value());
  fields_.reset();
  layout_.reset();
  return out;
}

const CoarseFields& CoarseGrainer::operator()(const core::data::ParticleFrame& frame, const CellGrid& userGrid,
                                              const CoarseGrainingKernel& kernel) {
  frame.validate();
  const CellGrid grid = gridForFrame(userGrid, frame.domain);
  const auto smooth = kernel.smoothingKernel();
  if (smooth) core::grid::checkKernelResolvesGrid(grid, *smooth);
  index_.assign(frame);
  particleContacts(frame, index_, contacts_);
  const ParticleContacts& contacts = contacts_;
  frameSpecies(frame, species_);
  const FrameSpecies& species = species_;
  const std::size_t n = frame.size();
  const std::size_t nSpecies = species.ids.size();
  const bool oneSpecies = nSpecies == 1;
  const double cellVolume = grid.cellVolume();
  // Without shear the peculiar velocity is the velocity, so its cell means are the mean
  // velocities and need no arrays of their own.
  const bool sheared = frame.domain.leesEdwardsShearRate != 0.0;
  const bool hasDrag = !frame.externalForce.empty();
  const Layout layout{grid.cellCount(), nSpecies, sheared, hasDrag};
  CoarseFields& out = prepare(grid, kernel, layout);
  // Should anything below throw, the next call starts afresh.
  layout_.reset();
  CellRange reached;

  // The cell holding each centre: the bin kernel's share (Eq. 7.35: the whole particle there)
  // and the cell of the contact statistics.
  centreCell_.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const auto cell = grid.cellOf(frame.position[i]);
    centreCell_[i] = cell ? grid.flatIndex(*cell) : npos;
    if (cell) reached.add(centreCell_[i]);
  }
  // Shares of every particle under the other kernels, kept for the second pass.
  const bool bin = kernel.kind == KernelKind::Bin;
  if (!bin) {
    offset_.assign(n + 1, 0);
    shares_.clear();
    for (std::size_t i = 0; i < n; ++i) {
      const Vec3& x = frame.position[i];
      if (kernel.kind == KernelKind::Overlap) {
        core::grid::sphereCellShares(grid, x, frame.radius[i], one_);
      } else {
        core::grid::kernelPointShares(grid, *smooth, x, one_);
      }
      for (const auto& share : one_) reached.add(share.cell);
      shares_.insert(shares_.end(), one_.begin(), one_.end());
      offset_[i + 1] = shares_.size();
    }
  }
  const auto forEachShare = [&](std::size_t i, auto&& visit) {
    if (bin) {
      if (centreCell_[i] != npos) visit(centreCell_[i], 1.0);
      return;
    }
    for (std::size_t s = offset_[i]; s < offset_[i + 1]; ++s) visit(shares_[s].cell, shares_[s].fraction);
  };
  const auto peculiar = [&](std::size_t i) {
    return Vec3(frame.velocity[i] - streamingVelocity(frame.domain, frame.position[i]));
  };

  // First pass: volume, mass and momentum per cell, in total and per species, summed into the
  // solid fraction, density and velocity arrays (finalised below).
  for (std::size_t i = 0; i < n; ++i) {
    const double r = frame.radius[i];
    const double vp = 4.0 / 3.0 * M_PI * r * r * r;
    const double m = frame.mass[i];
    const Vec3& v = frame.velocity[i];
    const Vec3 vPeculiar = peculiar(i);
    const std::size_t k = species.slot[i];
    SpeciesCellFields& sp = out.species[k];
    forEachShare(i, [&](std::size_t c, double f) {
      out.solidFraction[c] += vp * f;
      out.density[c] += m * f;
      out.velocity[c] += m * f * v;
      if (sheared) meanPeculiar_[c] += m * f * vPeculiar;
      if (oneSpecies) return;
      sp.solidFraction[c] += vp * f;
      sp.density[c] += m * f;
      sp.velocity[c] += m * f * v;
      if (sheared) speciesMeanPeculiar_[k][c] += m * f * vPeculiar;
    });
  }
  // Momenta to mean velocities (the density arrays still hold the masses). Cells no particle
  // reached have neither and stay zero.
  const auto toMean = [&](std::vector<Vec3>& momentum, const std::vector<double>& mass) {
    for (std::size_t c = reached.begin; c < reached.end; ++c) {
      if (mass[c] > 0.0) {
        momentum[c] = momentum[c] / mass[c];
      } else {
        momentum[c] = Vec3::Zero();
      }
    }
  };
  toMean(out.velocity, out.density);
  if (sheared) toMean(meanPeculiar_, out.density);
  if (!oneSpecies) {
    for (std::size_t k = 0; k < nSpecies; ++k) {
      toMean(out.species[k].velocity, out.species[k].density);
      if (sheared) toMean(speciesMeanPeculiar_[k], out.species[k].density);
    }
  }
  const std::vector<Vec3>& meanPeculiar = sheared ? meanPeculiar_ : out.velocity;
  const auto speciesMeanPeculiar = [&](std::size_t k) -> const std::vector<Vec3>& {
    if (oneSpecies) return meanPeculiar;
    return sheared ? speciesMeanPeculiar_[k] : out.species[k].velocity;
  };

  // Second pass: fluctuations C = v' - u'(cell), summed as m C C phi (two passes rather than
  // sum m v v - rho u u, which cancels badly when the mean flow dominates); each species' sum of
  // m C^2 phi about its own mean goes into its temperature array (finalised below).
  for (std::size_t i = 0; i < n; ++i) {
    const double m = frame.mass[i];
    const std::size_t k = species.slot[i];
    const Vec3 vPeculiar = peculiar(i);
    const std::vector<Vec3>& speciesMean = speciesMeanPeculiar(k);
    std::vector<double>& speciesC2 = out.species[k].granularTemperature;
    forEachShare(i, [&](std::size_t c, double f) {
      const Vec3 C = vPeculiar - meanPeculiar[c];
      out.kineticStress[c] += m * f * C * C.transpose();
      speciesC2[c] += m * f * (vPeculiar - speciesMean[c]).squaredNorm();
    });
  }

  // Contact part of Eq. 2.3: full r_ij F_ij of each contact along its contact line.
  const auto spread = [&](const Vec3& start, const Vec3& branch, const Vec3& force) {
    const Vec3 end = start - branch;
    const Mat3 product = branch * force.transpose();
    const auto deposit = [&](std::size_t c, double f) {
      out.contactStress[c] += f * product;
      reached.add(c);
    };
    if (smooth) {
      core::grid::kernelSegmentShares(grid, *smooth, start, end, one_);
      for (const auto& s : one_) deposit(s.cell, s.fraction);
    } else {
      core::grid::forEachSegmentCell(grid, start, end, deposit);
    }
  };
  const auto& pc = frame.contacts;
  for (std::size_t k = 0; k < pc.size(); ++k) {
    spread(frame.position[contacts.first[k]], pc.branch[k], pc.forceNormal[k] + pc.forceTangential[k]);
  }
  const auto& wc = frame.wallContacts;
  for (std::size_t k = 0; k < wc.size(); ++k) {
    const Vec3& ri = frame.position[contacts.wallParticle[k]];
    spread(ri, ri - wc.point[k], wc.forceNormal[k] + wc.forceTangential[k]);
  }

  // Contact statistics by particle centre (Figs. 7.5-7.7, 7.11): the coordination and
  // multi-contact arrays hold the sums of N_c and the particles with N_c >= 2 until finalised.
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t c = centreCell_[i];
    if (c == npos) continue;
    out.particleCount[c] += 1.0;
    out.coordinationNumber[c] += contacts.count[i];
    if (contacts.count[i] >= 1) inContact_[c] += 1.0;
    if (contacts.count[i] >= 2) out.multiContactRatio[c] += 1.0;
    contactForce_[c] += contacts.totalForce[i];
    if (hasDrag) drag_[c] += frame.externalForce[i];
  }

  // Finalise the cells this frame reached and those the last one did (cleared above); every
  // other cell already holds an empty cell's values. Species first, while the density arrays
  // still hold the masses.
  const std::size_t first = std::min(reached.begin, dirtyBegin_);
  const std::size_t last = std::max(reached.end, dirtyEnd_);
  for (std::size_t k = 0; k < nSpecies; ++k) {
    SpeciesCellFields& sf = out.species[k];
    sf.species = species.ids[k];
    const std::vector<double>& mass = oneSpecies ? out.density : sf.density;
    for (std::size_t c = first; c < last; ++c) {
      // Eq. 3.38 for the species about its own mean: T = sum m C^2 phi / (3 sum m phi).
      const double m = mass[c];
      sf.granularTemperature[c] = m > 0.0 ? sf.granularTemperature[c] / (3.0 * m) : 0.0;
      if (oneSpecies) continue;
      sf.solidFraction[c] /= cellVolume;
      sf.density[c] = m / cellVolume;
    }
  }
  for (std::size_t c = first; c < last; ++c) {
    const double mass = out.density[c];
    out.solidFraction[c] /= cellVolume;
    out.density[c] = mass / cellVolume;
    // Eq. 3.38, mass-weighted: T = sum m C^2 phi / (3 sum m phi).
    out.granularTemperature[c] = mass > 0.0 ? out.kineticStress[c].trace() / (3.0 * mass) : 0.0;
    out.kineticStress[c] /= cellVolume;
    out.contactStress[c] /= cellVolume;
    out.stress[c] = out.kineticStress[c] + out.contactStress[c];
    out.pressure[c] = pressure(out.stress[c]);
    out.shearStress[c] = shearStress(out.stress[c]);
    out.deviatoricStress[c] = deviatoricNorm(out.stress[c]);

    const double count = out.particleCount[c];
    out.coordinationNumber[c] = count > 0.0 ? out.coordinationNumber[c] / count : 0.0;
    out.multiContactRatio[c] = inContact_[c] > 0.0 ? out.multiContactRatio[c] / inContact_[c] : 0.0;
    out.contactForce[c] = contactForce_[c].norm();
    out.dragForce[c] = hasDrag ? drag_[c].norm() : 0.0;
    out.contactToDragRatio[c] = out.dragForce[c] > 0.0 ? out.contactForce[c] / out.dragForce[c] : -1.0;
  }
  if (oneSpecies) {
    SpeciesCellFields& sf = out.species[0];
    const auto copy = [&](const auto& from, auto& to) {
      // A new layout finalises every cell (and the copies are not allocated yet).
      if (first == 0 && last == layout.cells) {
        to = from;
      } else {
        std::copy(from.begin() + static_cast<std::ptrdiff_t>(first), from.begin() + static_cast<std::ptrdiff_t>(last),
                  to.begin() + static_cast<std::ptrdiff_t>(first));
      }
    };
    copy(out.solidFraction, sf.solidFraction);
    copy(out.density, sf.density);
    copy(out.velocity, sf.velocity);
  }
  dirtyBegin_ = reached.empty() ? 0 : reached.begin;
  dirtyEnd_ = reached.empty() ? 0 : reached.end;
  layout_ = layout;
  return out;
}

CoarseFields coarseGrain(const core::data::ParticleFrame& frame, const CellGrid& grid,
                         const CoarseGrainingKernel& kernel) {
  CoarseGrainer grainer;
  grainer(frame, grid, kernel);
  return grainer.release();
}

}  // namespace grainbridge::extract::coarse
