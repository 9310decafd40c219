#include "engines/dem/Simulation.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>
#include <unordered_map>

#include "core/Error.hpp"
#include "engines/dem/LeesEdwardsImage.hpp"

namespace grainbridge::dem {

namespace {
std::string vecText(const Vec3& v) {
  return "(" + std::to_string(v[0]) + ", " + std::to_string(v[1]) + ", " + std::to_string(v[2]) + ")";
}
}  // namespace

Simulation::Simulation(SimulationSetup setup, Particles particles)
    : setup_(std::move(setup)), p_(std::move(particles)) {
  validateSetup();
  if (setup_.planarAxis >= 0) {
    for (std::size_t i = 0; i < p_.nOwned; ++i) {
      p_.v[i][setup_.planarAxis] = 0.0;
      const double spin = p_.omega[i][setup_.planarAxis];
      p_.omega[i].setZero();
      p_.omega[i][setup_.planarAxis] = spin;
    }
  }
  wallHistory_.assign(p_.nOwned * setup_.walls.size(), Vec3::Zero());
  rebuild(false);
  computeForces(Evaluation::Setup);  // the initial frame gets its contacts too
}

Simulation::Simulation(SimulationSetup setup, EngineState state)
    : setup_(std::move(setup)), p_(std::move(state.particles)) {
  validateSetup();
  GB_ASSERT(state.buildPositions.size() == p_.nOwned, "state without build positions");
  GB_ASSERT(state.wallHistory.size() == p_.nOwned * setup_.walls.size(), "state with wrong wall history size");
  time_ = state.time;
  step_ = state.step;
  rebuildsSinceSort_ = state.rebuildsSinceSort;
  if (setup_.boxMovesAlongY()) {
    setup_.hi[1] = state.boxHighY;
    shearOffsetBase_ = state.shearOffsetBase;
    shearOffsetTime_ = state.shearOffsetTime;
    normalStressSum_ = state.normalStressSum;
    normalStressSamples_ = state.normalStressSamples;
  }
  wallHistory_ = std::move(state.wallHistory);
  // Rebuild the list exactly as it was built: from the positions of that moment, so the same
  // pairs (and ghosts) come in the same order.
  const std::vector<Vec3> current = p_.x;
  p_.x = state.buildPositions;
  buildTime_ = state.buildTime;
  buildGhosts(shearOffset(buildTime_));
  list_.build(p_, setup_.lo, setup_.hi, cutoff_, setup_.skin, &state.pairHistory);
  selectWallCandidates(/*clearOthers=*/false);
  for (std::size_t i = 0; i < p_.nOwned; ++i) p_.x[i] = current[i];
  p_.refreshGhosts(shearDrift(buildTime_));
  // The inner list from the current positions: which pairs it holds changes no result.
  buildInner();
}

EngineState Simulation::captureState() const {
  EngineState s;
  s.time = time_;
  s.step = step_;
  s.rebuildsSinceSort = rebuildsSinceSort_;
  s.particles = p_;
  s.particles.clearGhosts();
  s.buildPositions = list_.referencePositions();
  s.buildTime = buildTime_;
  s.pairHistory = list_.exportHistory();
  s.wallHistory = wallHistory_;
  s.boxHighY = setup_.hi[1];
  s.shearOffsetBase = shearOffsetBase_;
  s.shearOffsetTime = shearOffsetTime_;
  s.normalStressSum = normalStressSum_;
  s.normalStressSamples = normalStressSamples_;
  return s;
}

void Simulation::validateSetup() {
  GB_ASSERT(p_.size() == p_.nOwned, "the engine creates ghosts itself");
  double maxRadius = 0.0;
  for (std::size_t i = 0; i < p_.nOwned; ++i) maxRadius = std::max(maxRadius, p_.radius[i]);
  // The same rules the dem stage reports at load (with the particles' own largest diameter
  // here: a state read from a file may hold grains the config did not declare).
  const auto problems = setup_.problems(2.0 * maxRadius);
  if (!problems.empty()) {
    std::string message = "DEM setup";
    for (const auto& p : problems) message += (&p == &problems.front() ? ": " : "; ") + p.pointer + ": " + p.message;
    throw Error(message);
  }
  law_ = *contact::findContactLaw(setup_.contact);  // registered: problems() says so
  cutoff_ = interactionRange(2.0 * maxRadius, setup_.skin);
  // A quarter of the skin. In the dense benchmark bed (skin 0.3 d, as LAMMPS settled it) the
  // Verlet list holds 5.17 pairs per particle, the inner list 3.47, and 2.07 touch; an eighth of
  // the skin ran no faster.
  innerSkin_ = 0.25 * setup_.skin;
  frictionless_ = std::all_of(setup_.pairMaterial.begin(), setup_.pairMaterial.end(),
                              [](const PairMaterial& m) { return m.mu == 0.0; });
  wallForce_.assign(setup_.walls.size(), Vec3::Zero());
  if (setup_.compression.active()) {
    // The schedule runs from the configured box (a resumed run restores its current box after
    // this) to the length along y at which the particles fill the target fraction.
    double volume = 0.0;
    for (std::size_t i = 0; i < p_.nOwned; ++i) volume += 4.0 / 3.0 * M_PI * std::pow(p_.radius[i], 3);
    const Vec3 length = setup_.hi - setup_.lo;
    compressionStartLength_ = length[1];
    compressionTargetLength_ = volume / (length[0] * length[2] * setup_.compression.solidFraction);
    if (!(compressionTargetLength_ < compressionStartLength_)) {
      throw Error("DEM: compression to solid fraction " + std::to_string(setup_.compression.solidFraction) +
                  ": the particles already fill " + std::to_string(volume / length.prod()) +
                  " of the box as configured, and compression only shrinks it (a larger box_hi along y)");
    }
  }
}

double Simulation::shearOffset(double t) const {
  const double lx = setup_.hi[0] - setup_.lo[0];
  const double offset =
      std::fmod(shearOffsetBase_ + setup_.shearRate * (setup_.hi[1] - setup_.lo[1]) * (t - shearOffsetTime_), lx);
  return offset < 0 ? offset + lx : offset;
}

double Simulation::shearDrift(double since) const {
  return setup_.shearRate * (setup_.hi[1] - setup_.lo[1]) * (time_ - since);
}

void Simulation::setFrozen(std::int64_t id, bool frozen) {
  const auto i = indexOf(id);
  if (!i) throw Error("DEM: no particle with id " + std::to_string(id));
  const double m = p_.mass[*i];
  const double a = p_.radius[*i];
  p_.invMass[*i] = frozen ? 0.0 : 1.0 / m;
  p_.invInertia[*i] = frozen ? 0.0 : 1.0 / (0.4 * m * a * a);
  if (frozen) {
    p_.v[*i].setZero();
    p_.omega[*i].setZero();
    p_.force[*i].setZero();
    p_.torque[*i].setZero();
  }
  // Ghost copies and the frozen-pair exclusion of the list follow at the rebuild.
  rebuild(false);
  contactsCurrent_ = false;
}

void Simulation::setWallVibration(std::size_t wall, const Vibration& vibration) {
  GB_ASSERT(wall < setup_.walls.size(), "no such wall");
  setup_.walls[wall].vibration = vibration;
  contactsCurrent_ = false;
}

void Simulation::restartClock() {
  time_ = 0.0;
  step_ = 0;
}

Simulation::Overlap Simulation::largestOverlap() const {
  Overlap worst;
  for (std::size_t i = 0; i < p_.nOwned; ++i) {
    for (std::size_t s = list_.begin(i); s < list_.end(i); ++s) {
      const std::size_t j = list_.partner(s);
      const double gap = (p_.x[i] - p_.x[j]).norm() - (p_.radius[i] + p_.radius[j]);
      const double relative = -gap / (2.0 * std::min(p_.radius[i], p_.radius[j]));
      if (relative > worst.relative) worst = {relative, p_.id[i], p_.id[j]};
    }
  }
  return worst;
}

std::optional<std::size_t> Simulation::indexOf(std::int64_t id) const {
  for (std::size_t i = 0; i < p_.nOwned; ++i) {
    if (p_.id[i] == id) return i;
  }
  return std::nullopt;
}

Energies Simulation::energies() const {
  Energies e;
  const double offset = setup_.shearRate != 0.0 ? shearOffset(time_) : 0.0;
  for (std::size_t i = 0; i < p_.nOwned; ++i) {
    if (p_.isFrozen(i)) continue;
    Vec3 v = p_.v[i];
    if (setup_.shearRate != 0.0) {
      Vec3 x = p_.x[i];
      toPrimaryImage(x, v, setup_.lo, setup_.hi, offset, setup_.shearRate);  // the frame's image
    }
    e.translational += 0.5 * p_.mass[i] * v.squaredNorm();
    e.rotational += 0.5 / p_.invInertia[i] * p_.omega[i].squaredNorm();
  }
  return e;
}

std::int64_t Simulation::mobileCount() const {
  std::int64_t n = 0;
  for (std::size_t i = 0; i < p_.nOwned; ++i) n += p_.isFrozen(i) ? 0 : 1;
  return n;
}

Vec3 Simulation::momentum() const {
  Vec3 m = Vec3::Zero();
  for (std::size_t i = 0; i < p_.nOwned; ++i) {
    if (!p_.isFrozen(i)) m += p_.mass[i] * p_.v[i];
  }
  return m;
}

void Simulation::run(std::int64_t steps) {
  for (std::int64_t s = 0; s < steps; ++s) step(false);
}

void Simulation::step(bool recordContacts) {
  const double dt = setup_.dt;
  const double half = 0.5 * dt;
  // Velocity Verlet: half kick, drift, forces at the new positions, half kick. The first loop
  // also clears the forces it has used and checks each displacement against the rebuild
  // reach: one pass over the particle arrays instead of three, which counts on beds larger than
  // the cache.
  time_ += dt;
  ++step_;
  ++stepsTaken_;
  const double reach = rebuildReach(setup_.skin, buildTime_);
  const double reach2 = reach * reach;
  const double innerReach = rebuildReach(innerSkin_, innerBuildTime_);  // the same rule
  const double innerReach2 = innerReach * innerReach;
  // The shear strain since each list's build (0 without shear: the plain displacement, bit for
  // bit) and the height of zero streaming velocity (rebuildReach).
  const double strain = setup_.shearRate * (time_ - buildTime_);
  const double innerStrain = setup_.shearRate * (time_ - innerBuildTime_);
  const double midY = 0.5 * (setup_.lo[1] + setup_.hi[1]);
  const auto& x0 = list_.referencePositions();
  bool movedTooFar = reach <= 0.0;
  bool innerMovedTooFar = innerReach <= 0.0;
  // The arrays as local pointers: read through the members, GCC reloaded each array's address
  // for every particle (callgrind: 23 % fewer instructions in this function with them local).
  Vec3* const x = p_.x.data();
  Vec3* const v = p_.v.data();
  Vec3* const omega = p_.omega.data();
  Vec3* const force = p_.force.data();
  Vec3* const torque = p_.torque.data();
  const double* const invMass = p_.invMass.data();
  const double* const invInertia = p_.invInertia.data();
  const Vec3* const start = x0.data();
  const Vec3* const innerStart = list_.innerReferencePositions().data();
  const std::size_t n = p_.nOwned;
  for (std::size_t i = 0; i < n; ++i) {
    v[i] += (half * invMass[i]) * force[i];
    omega[i] += (half * invInertia[i]) * torque[i];
    x[i] += dt * v[i];
    force[i].setZero();
    torque[i].setZero();
    movedTooFar |= squaredPeculiarDisplacement(x[i], start[i], strain, midY) > reach2;
    innerMovedTooFar |= squaredPeculiarDisplacement(x[i], innerStart[i], innerStrain, midY) > innerReach2;
  }
  if (movedTooFar) {
    rebuild(setup_.sortEveryRebuilds > 0 && rebuildsSinceSort_ >= setup_.sortEveryRebuilds);
  } else {
    p_.refreshGhosts(shearDrift(buildTime_));
    if (innerMovedTooFar) buildInner();
  }
  contactForces(recordContacts ? Evaluation::StepRecorded : Evaluation::Step, /*ownedCleared=*/true);
  if (setup_.pressureControl.active()) {
    // Eq. 2.3's contact part of p_yy, sum over pairs of r_y F_y, as sum_k y_k F_y,k over owned
    // particles and ghosts before the ghosts' forces go to their owners (LAMMPS's fdotr virial):
    // an O(N) pass for the controlled box only, nothing in the pair loop.
    double virial = 0.0;
    for (std::size_t k = 0; k < p_.size(); ++k) virial += p_.x[k][1] * p_.force[k][1];
    contactVirialYY_ = virial;
  }
  // The closing half kick in the body forces' pass. The addresses are taken here: a rebuild
  // above may have re-sorted the arrays.
  Vec3* const vNow = p_.v.data();
  Vec3* const omegaNow = p_.omega.data();
  const Vec3* const forceNow = p_.force.data();
  const Vec3* const torqueNow = p_.torque.data();
  const double* const invMassNow = p_.invMass.data();
  const double* const invInertiaNow = p_.invInertia.data();
  finishForces([&](std::size_t i) {
    vNow[i] += (half * invMassNow[i]) * forceNow[i];
    omegaNow[i] += (half * invInertiaNow[i]) * torqueNow[i];
  });
  if (setup_.pressureControl.active()) controlPressure();
  if (setup_.compression.active()) compress();
}

void Simulation::controlPressure() {
  // p_yy of Eq. 2.3 over the whole box: (sum m v_y v_y + sum_contacts r_y F_y) / V. The
  // streaming velocity of Lees-Edwards shear is along x, so v_y is already the fluctuation.
  double kinetic = 0.0;
  for (std::size_t i = 0; i < p_.nOwned; ++i) kinetic += p_.mass[i] * p_.v[i][1] * p_.v[i][1];
  const Vec3 length = setup_.hi - setup_.lo;
  normalStressYY_ = (kinetic + contactVirialYY_) / (length[0] * length[1] * length[2]);
  normalStressSum_ += normalStressYY_;
  ++normalStressSamples_;
  const auto& control = setup_.pressureControl;
  if (step_ % control.interval != 0) return;
  const double mean = normalStressSum_ / static_cast<double>(normalStressSamples_);
  normalStressSum_ = 0.0;
  normalStressSamples_ = 0;
  const double error = std::clamp((mean - control.stress) / control.stress, -1.0, 1.0);
  const double scale = 1.0 + control.interval * setup_.dt / control.relaxationTime * error;
  resizeAlongY(scale, length[1] * scale,
               "pressure control: the target stress packs these particles into a slab too thin for this box; use "
               "more particles, a larger box in x and z, or a lower stress");
}

void Simulation::compress() {
  const auto& c = setup_.compression;
  // Held: the last change set hi = lo + the target length, the same sum to the bit.
  if (step_ % c.interval != 0 || setup_.hi[1] == setup_.lo[1] + compressionTargetLength_) return;
  // Linear in time; the last change lands on the target exactly (a fixed-volume box from then on).
  const double s = std::min(1.0, time_ / c.duration);
  const double length = s < 1.0 ? compressionStartLength_ + s * (compressionTargetLength_ - compressionStartLength_)
                                : compressionTargetLength_;
  resizeAlongY(length / (setup_.hi[1] - setup_.lo[1]), length,
               "compression: its solid fraction packs these particles into a slab too thin for this box; use more "
               "particles or a box_hi longer along x and z");
}

void Simulation::resizeAlongY(double scale, double length, const char* why) {
  // The offset so far, then the new box: positions scaled affinely about its lower face,
  // velocities kept (as LAMMPS's fix deform with remap x). The forces of this step stay those of
  // the positions they were computed at; the list is rebuilt for the new box.
  shearOffsetBase_ = shearOffset(time_);
  shearOffsetTime_ = time_;
  const double low = setup_.lo[1];
  for (std::size_t i = 0; i < p_.nOwned; ++i) p_.x[i][1] = low + (p_.x[i][1] - low) * scale;
  setup_.hi[1] = low + length;
  if (length < 2.0 * cutoff_) {
    // Ghosts need a periodic length of at least twice the interaction range (problems()).
    throw Error("DEM: the box along y shrank to " + std::to_string(length) + " m at step " + std::to_string(step_) +
                ", below twice the interaction range (" + std::to_string(2.0 * cutoff_) + " m); " + why);
  }
  rebuild(setup_.sortEveryRebuilds > 0 && rebuildsSinceSort_ >= setup_.sortEveryRebuilds);
}

void Simulation::refreshContacts() {
  if (contactsCurrent_) return;
  // Contacts only: the body forces (and what they recorded) belong to the last step.
  const std::vector<Vec3> force = p_.force;
  const std::vector<Vec3> torque = p_.torque;
  const std::vector<Vec3> wallForce = wallForce_;
  contactForces(Evaluation::Setup);
  p_.force = force;
  p_.torque = torque;
  wallForce_ = wallForce;
}

void Simulation::forceRebuild(bool sort) {
  // Forces are not recomputed: an evaluation advances the tangential history (Eq. 6.4), so a
  // second one in the same step would change the trajectory. The stored forces travel with
  // their particles through the re-sort.
  rebuild(sort);
}

void Simulation::buildInner() {
  list_.buildInner(p_, innerSkin_);
  innerBuildTime_ = time_;
}

double Simulation::rebuildReach(double skin, double builtAt) const {
  // The list holds every pair of images within R_ij + skin at the build (R_ij = a_i + a_j).
  // Without shear two particles close that gap by at most |dx_i| + |dx_j| <= 2 max|dx|: the
  // half-skin rule. Under Lees-Edwards shear every image of a particle (its ghosts across the
  // shearing boundary included: their offset drift is the streaming field's jump over L_y) moves
  // as the affine shear F = I + s e_x e_y^T, s the strain since the build, plus its particle's
  // peculiar displacement p = dx - s (y_0 - y_mid) e_x (squaredPeculiarDisplacement). A pair's separation
  // is then r = F r_0 + p_i - p_j, so |r| >= sigma_min(F) |r_0| - 2 max|p|, with
  // sigma_min = sqrt(1 + s^2/4) - |s|/2 the smallest stretch of F. An unlisted pair
  // (|r_0| >= R_ij + skin) stays apart while 2 max|p| <= skin - (1 - sigma_min)(R_max + skin),
  // R_max + skin being the interaction range. This replaces a rule on the whole displacement
  // (streaming motion and offset drift included), which in the closure loop's dilute boxes
  // rebuilt the list every 15-30 steps although neighbours stream together (issue 59); the
  // peculiar motion and the shear's slow distortion of the neighbourhood are what can close a gap.
  const double s = std::abs(setup_.shearRate * (time_ - builtAt));
  const double shrink = 1.0 - 1.0 / (std::sqrt(1.0 + 0.25 * s * s) + 0.5 * s);  // 1 - sigma_min, no cancellation
  return 0.5 * (skin - shrink * (cutoff_ - setup_.skin + skin));
}

void Simulation::wrapAndCheck() {
  const Vec3 length = setup_.hi - setup_.lo;
  for (std::size_t i = 0; i < p_.nOwned; ++i) {
    Vec3& x = p_.x[i];
    if (!x.allFinite() || !p_.v[i].allFinite()) {
      throw Error("DEM: particle " + std::to_string(p_.id[i]) + " has a non-finite position or velocity at step " +
                  std::to_string(step_) + " (time step too large, or overlapping initial particles?)");
    }
    if (setup_.shearRate != 0.0) {
      // Crossing the shearing boundary: the particle re-enters as its image, displaced by the
      // offset and with the image's streaming velocity.
      const double ly = length[1];
      const double offset = shearOffset(time_);
      if (x[1] >= setup_.hi[1]) {
        x[1] -= ly;
        x[0] -= offset;
        p_.v[i][0] -= setup_.shearRate * ly;
      } else if (x[1] < setup_.lo[1]) {
        x[1] += ly;
        x[0] += offset;
        p_.v[i][0] += setup_.shearRate * ly;
      }
    }
    for (int a = 0; a < 3; ++a) {
      if (setup_.periodic[static_cast<std::size_t>(a)]) {
        x[a] -= length[a] * std::floor((x[a] - setup_.lo[a]) / length[a]);
        if (x[a] >= setup_.hi[a]) x[a] = setup_.lo[a];  // floor round-off at the upper edge
      } else if (x[a] < setup_.lo[a] - cutoff_ || x[a] > setup_.hi[a] + cutoff_) {
        throw Error("DEM: particle " + std::to_string(p_.id[i]) + " left the domain at step " + std::to_string(step_) +
                    ": position " + vecText(x) + " outside " + vecText(setup_.lo) + " - " + vecText(setup_.hi));
      }
    }
  }
}

void Simulation::buildGhosts(double shearOffsetNow) {
  p_.clearGhosts();
  const Vec3 length = setup_.hi - setup_.lo;
  const bool sheared = setup_.shearRate != 0.0;
  // Axis by axis, including ghosts made for earlier axes, so edges and corners get images. With
  // Lees-Edwards the gradient axis y goes first: its images are displaced in x, and the x pass
  // then images them across x as well.
  const std::array<int, 3> order = sheared ? std::array<int, 3>{1, 0, 2} : std::array<int, 3>{0, 1, 2};
  for (int a : order) {
    if (!setup_.periodic[static_cast<std::size_t>(a)]) continue;
    const std::size_t existing = p_.size();
    for (std::size_t k = 0; k < existing; ++k) {
      const bool ghost = k >= p_.nOwned;
      const std::size_t owner = ghost ? p_.ghostOwner[k - p_.nOwned] : k;
      const Vec3 baseShift = ghost ? p_.ghostShift[k - p_.nOwned] : Vec3::Zero();
      const Vec3 baseVel = ghost ? p_.ghostVelocityShift[k - p_.nOwned] : Vec3::Zero();
      const std::int8_t baseCrossings = ghost ? p_.ghostShearCrossings[k - p_.nOwned] : std::int8_t{0};
      const Vec3 xk = p_.x[k];
      for (int side : {+1, -1}) {
        // side +1: a particle near the lower face gets an image above; -1: near the upper face.
        const bool near = side > 0 ? xk[a] < setup_.lo[a] + cutoff_ : xk[a] >= setup_.hi[a] - cutoff_;
        if (!near) continue;
        Vec3 shift = baseShift;
        Vec3 vel = baseVel;
        shift[a] += side * length[a];
        std::int8_t crossings = baseCrossings;
        if (sheared && a == 1) {
          shift[0] += side * shearOffsetNow;
          // keep the image's x inside the box; the x pass adds its x images
          const double xImage = xk[0] + side * shearOffsetNow;
          if (xImage >= setup_.hi[0]) shift[0] -= length[0];
          if (xImage < setup_.lo[0]) shift[0] += length[0];
          vel[0] += side * setup_.shearRate * length[1];
          crossings = static_cast<std::int8_t>(crossings + side);
        }
        p_.addGhost(owner, shift, vel, crossings);
      }
    }
  }
}

void Simulation::sortByCell() {
  // Particles close in space close in memory: the pair loop then touches fewer cache lines.
  const double cell = cutoff_;
  const Vec3 extent = setup_.hi - setup_.lo;
  Vec3i cells;
  for (int a = 0; a < 3; ++a) cells[a] = std::max(1, static_cast<int>(extent[a] / cell));
  std::vector<std::size_t> key(p_.nOwned);
  for (std::size_t i = 0; i < p_.nOwned; ++i) {
    Vec3i c;
    for (int a = 0; a < 3; ++a) {
      c[a] = std::clamp(static_cast<int>((p_.x[i][a] - setup_.lo[a]) / extent[a] * cells[a]), 0, cells[a] - 1);
    }
    key[i] = (static_cast<std::size_t>(c[2]) * cells[1] + c[1]) * cells[0] + c[0];
  }
  std::vector<std::size_t> order(p_.nOwned);
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return key[a] < key[b]; });
  p_.permuteOwned(order);
  const std::size_t nw = setup_.walls.size();
  if (nw > 0) {
    std::vector<Vec3> moved(wallHistory_.size());
    for (std::size_t k = 0; k < order.size(); ++k) {
      for (std::size_t w = 0; w < nw; ++w) moved[k * nw + w] = wallHistory_[order[k] * nw + w];
    }
    wallHistory_.swap(moved);
  }
}

void Simulation::rebuild(bool sort) {
  p_.clearGhosts();
  wrapAndCheck();
  if (sort) {
    sortByCell();
    rebuildsSinceSort_ = 0;
  } else {
    ++rebuildsSinceSort_;
  }
  buildTime_ = time_;
  buildGhosts(shearOffset(time_));
  list_.build(p_, setup_.lo, setup_.hi, cutoff_, setup_.skin);
  buildInner();
  selectWallCandidates(/*clearOthers=*/true);
}

void Simulation::selectWallCandidates(bool clearOthers) {
  const std::size_t nw = setup_.walls.size();
  wallCandidates_.resize(nw);
  for (std::size_t w = 0; w < nw; ++w) {
    const Wall& wall = setup_.walls[w];
    auto& candidates = wallCandidates_[w];
    candidates.clear();
    const Vec3 origin = wall.positionAt(buildTime_);
    const Vec3 k = wall.direction;
    // Under shear the rebuild rule bounds only the displacement less the streaming motion along
    // x (rebuildReach): a gap that the streaming motion changes (a plane not parallel to x, a
    // cylinder not along x) is not bounded by it, so such a wall keeps every particle.
    const bool streamingMovesGap =
        setup_.shearRate != 0.0 && (wall.kind == Wall::Kind::Plane ? k[0] != 0.0 : (k[1] != 0.0 || k[2] != 0.0));
    const bool fixed = wall.vibration.amplitude == 0.0 && !streamingMovesGap;
    for (std::size_t i = 0; i < p_.nOwned; ++i) {
      if (p_.isFrozen(i)) continue;
      const Vec3 rel = p_.x[i] - origin;
      const double gap = wall.kind == Wall::Kind::Plane ? rel.dot(k) : wall.radius - (rel - rel.dot(k) * k).norm();
      // A whole skin of margin where half would do: the gap moves by at most a particle's
      // displacement, which stays below half the skin until the next build.
      if (!fixed || gap < p_.radius[i] + setup_.skin) {
        candidates.push_back(i);
      } else if (clearOthers) {
        wallHistory_[i * nw + w].setZero();
      }
    }
  }
}

void Simulation::contactForces(Evaluation evaluation, bool ownedCleared) {
  const bool record = evaluation != Evaluation::Step;
  const std::size_t n = p_.size();
  for (std::size_t i = ownedCleared ? p_.nOwned : 0; i < n; ++i) {
    p_.force[i].setZero();
    p_.torque[i].setZero();
  }
  contactsCurrent_ = record;
  if (record) {
    recordedContacts_ = {};
    recordedWallContacts_ = {};
    dissipation_ = 0.0;
  }
  contactCount_ = 0;
  // The run's composition is chosen here, once per evaluation; the loops are compiled for it.
  std::visit([&](auto law) { contactLoops<decltype(law)>(evaluation); }, law_);
}

void Simulation::computeForces(Evaluation evaluation, bool ownedCleared) {
  contactForces(evaluation, ownedCleared);
  finishForces([](std::size_t /*i*/) {});
}

template <class Then>
void Simulation::finishForces(Then&& then) {
  // Forces on ghosts belong to their owners (the reverse communication of a parallel run).
  for (std::size_t k = 0; k < p_.ghostOwner.size(); ++k) {
    const std::size_t o = p_.ghostOwner[k];
    p_.force[o] += p_.force[p_.nOwned + k];
    p_.torque[o] += p_.torque[p_.nOwned + k];
  }
  // Gravity, background damping (Eq. 6.7), TF-DEM coupling (frozen: zero), a 2-D bed held in its
  // plane, then `then`, particle by particle.
  const int planar = setup_.planarAxis;
  bodyForces_.apply(p_, setup_, [&](std::size_t i) {
    if (planar >= 0) constrainToPlane(i, planar);
    then(i);
  });
}

template <class Law>
void Simulation::contactLoops(Evaluation evaluation) {
  using contact::History;
  switch (evaluation) {
    case Evaluation::Step:
      contactsOf<Law, false, History::Advance>();
      break;
    case Evaluation::StepRecorded:
      contactsOf<Law, true, History::Advance>();
      break;
    case Evaluation::Setup:
      contactsOf<Law, true, History::Keep>();
      break;
  }
}

template <class Law, bool Record, contact::History H>
void Simulation::contactsOf() {
  if (frictionless_) {
    pairForces<Law, Record, H, true>();
  } else {
    pairForces<Law, Record, H, false>();
  }
  wallForces<Law, Record, H>();
}

void Simulation::constrainToPlane(std::size_t i, int a) {
  // 2-D beds: the layer stays in its plane and spins only about the plane's normal.
  p_.force[i][a] = 0.0;
  const double spin = p_.torque[i][a];
  p_.torque[i].setZero();
  p_.torque[i][a] = spin;
}

template <class Law, bool Record, contact::History H, bool Frictionless>
void Simulation::pairForces() {
  const double dt = setup_.dt;
  const int ns = setup_.species;
  // Local pointers to the arrays, as in step().
  const Vec3* const x = p_.x.data();
  const Vec3* const v = p_.v.data();
  const Vec3* const omega = p_.omega.data();
  const double* const radius = p_.radius.data();
  const double* const invMass = p_.invMass.data();
  const auto* const species = p_.species.data();
  Vec3* const force = p_.force.data();
  Vec3* const torque = p_.torque.data();
  const PairMaterial* const materials = setup_.pairMaterial.data();
  const NeighborList::InnerView inner = list_.innerView();
  const std::size_t nOwned = p_.nOwned;
  std::size_t contacts = 0;  // a local: the member's every increment went through memory
  for (std::size_t i = 0; i < nOwned; ++i) {
    const std::size_t first = inner.offset[i];
    const std::size_t last = inner.offset[i + 1];
    // Nothing to add: most particles of a dilute box list no pair of their own, and reading their
    // state and adding a zero to their force and torque was a fifth of such a box's time.
    if (first == last) continue;
    const Vec3 xi = x[i];
    const Vec3 vi = v[i];
    const Vec3 wi = omega[i];
    const double ai = radius[i];
    const double invMi = invMass[i];
    const int si = species[i];
    Vec3 fi = Vec3::Zero();
    Vec3 ti = Vec3::Zero();
    // The inner list: the pairs it leaves out are apart (NeighborList::buildInner).
    for (std::size_t k = first; k < last; ++k) {
      const std::size_t j = inner.partner[k];
      const Vec3 r = xi - x[j];
      const double sumRadii = ai + radius[j];
      const double r2 = r.squaredNorm();
      if (r2 >= sumRadii * sumRadii) {
        // Not touching: the history ends with the contact. Most listed pairs are apart and
        // already zero; testing first spares the cache line a write every step. A frictionless
        // run's history is never set.
        if constexpr (!Frictionless) {
          Vec3& ut = inner.history[inner.slot[k]];
          if (!ut.isZero(0.0)) ut.setZero();
        }
        continue;
      }
      // 1 / r^2 beside |r|: nothing waits for a division after the square root
      // (ContactKinematics::branch).
      const double rlen = std::sqrt(r2);
      contact::ContactKinematics c;
      c.setBranch(r, rlen, 1.0 / r2);
      c.delta = sumRadii - rlen;  // Eq. 6.1
      c.d = sumRadii;
      const double aj = radius[j];
      const Vec3 vij = vi - v[j];
      c.vn = c.alongNormal(vij);  // Eq. 6.2
      c.meff = 1.0 / (invMi + invMass[j]);
      const PairMaterial& material = materials[static_cast<std::size_t>(si * ns + species[j])];
      contact::ContactForce f;
      if constexpr (Frictionless) {
        f = Law::evaluateNormal(c, material);
        const Vec3 fn = f.normal();
        fi += fn;
        force[j] -= fn;
      } else {
        c.vt = vij - c.vn - (ai * wi + aj * omega[j]).cross(c.n);  // Eq. 6.3
        f = Law::evaluate(c, material, dt, inner.history[inner.slot[k]], H);
        const Vec3 fn = f.normal();
        const Vec3 ft = f.tangential();
        const Vec3 total = fn + ft;
        fi += total;
        force[j] -= total;
        // Torque with the lever arm to the contact point, a_i n from each centre (consistent with
        // Eq. 6.3; Eq. 6.8's -1/2 r_ij x F_t is its equal-size form).
        const Vec3 nxft = c.n.cross(ft);
        ti -= ai * nxft;
        torque[j] -= aj * nxft;
      }
      ++contacts;
      if constexpr (Record) {
        auto& rc = recordedContacts_;
        rc.i.push_back(p_.id[i]);
        rc.j.push_back(p_.id[j]);
        rc.branch.push_back(r);
        rc.contactPoint.push_back(xi - ai * c.n);
        rc.forceNormal.push_back(f.normal());
        rc.forceTangential.push_back(f.tangential());
        rc.forceNormalElastic.push_back(f.normalElastic);
        rc.forceNormalDissipative.push_back(f.normalDissipative);
        rc.forceTangentialElastic.push_back(f.tangentialElastic);
        rc.forceTangentialDissipative.push_back(f.tangentialDissipative);
        if constexpr (Frictionless) {
          dissipation_ -= f.normalDissipative.dot(c.vn);  // c.vt is not computed
        } else {
          dissipation_ -= f.normalDissipative.dot(c.vn) + f.tangentialDissipative.dot(c.vt);
        }
      }
    }
    force[i] += fi;
    if constexpr (!Frictionless) torque[i] += ti;
  }
  contactCount_ += contacts;
}

template <class Law, bool Record, contact::History H>
void Simulation::wallForces() {
  const std::size_t nw = setup_.walls.size();
  for (auto& wf : wallForce_) wf.setZero();
  if (nw == 0) return;
  const double dt = setup_.dt;
  for (std::size_t w = 0; w < nw; ++w) {
    const Wall& wall = setup_.walls[w];
    const Vec3 origin = wall.positionAt(time_);
    const Vec3 wallVelocity = wall.velocityAt(time_);
    const Vec3 k = wall.direction;
    for (const std::size_t i : wallCandidates_[w]) {
      const double ai = p_.radius[i];
      const Vec3 rel = p_.x[i] - origin;
      Vec3 n;  // from the wall towards the particle centre
      double gap;
      if (wall.kind == Wall::Kind::Plane) {
        gap = rel.dot(k);
        n = k;
      } else {
        const Vec3 radial = rel - rel.dot(k) * k;
        const double rho = radial.norm();
        gap = wall.radius - rho;
        if (rho <= 0.0) continue;
        n = -radial / rho;
      }
      Vec3& ut = wallHistory_[i * nw + w];
      if (gap >= ai) {
        ut.setZero();
        continue;
      }
      contact::ContactKinematics c;
      c.setUnitNormal(n);
      c.delta = ai - gap;
      c.d = 2.0 * ai;  // Hertz against a wall: d = 2 a_i
      const Vec3 vij = p_.v[i] - wallVelocity;
      c.vn = vij.dot(n) * n;
      c.vt = vij - c.vn - (ai * p_.omega[i]).cross(n);  // the wall does not rotate
      c.meff = p_.mass[i];                              // infinite wall mass
      const auto f = Law::evaluate(c, wall.material[static_cast<std::size_t>(p_.species[i])], dt, ut, H);
      const Vec3 fn = f.normal();
      const Vec3 ft = f.tangential();
      p_.force[i] += fn + ft;
      p_.torque[i] -= ai * n.cross(ft);
      wallForce_[w] -= fn + ft;
      if constexpr (Record) {
        auto& rw = recordedWallContacts_;
        rw.particle.push_back(p_.id[i]);
        rw.wall.push_back(static_cast<std::int32_t>(w));
        rw.point.push_back(p_.x[i] - ai * n);
        rw.forceNormal.push_back(fn);
        rw.forceTangential.push_back(ft);
        dissipation_ -= f.normalDissipative.dot(c.vn) + f.tangentialDissipative.dot(c.vt);
      }
    }
  }
}

core::data::ParticleFrame Simulation::frame() const {
  core::data::ParticleFrame f;
  f.time = time_;
  f.step = step_;
  f.units = "SI";
  f.domain.lo = setup_.lo;
  f.domain.hi = setup_.hi;
  f.domain.periodic = setup_.periodic;
  f.domain.leesEdwardsOffset = shearOffset(time_);
  f.domain.leesEdwardsShearRate = setup_.shearRate;
  for (const auto& w : setup_.walls) {
    f.domain.walls.push_back({w.kind == Wall::Kind::Plane ? "plane" : "cylinder", w.positionAt(time_), w.direction,
                              w.radius, w.velocityAt(time_)});
  }
  const std::size_t n = p_.nOwned;
  f.id.assign(p_.id.begin(), p_.id.begin() + static_cast<std::ptrdiff_t>(n));
  f.species.assign(p_.species.begin(), p_.species.begin() + static_cast<std::ptrdiff_t>(n));
  f.radius.assign(p_.radius.begin(), p_.radius.begin() + static_cast<std::ptrdiff_t>(n));
  f.mass.assign(p_.mass.begin(), p_.mass.begin() + static_cast<std::ptrdiff_t>(n));
  f.position.assign(p_.x.begin(), p_.x.begin() + static_cast<std::ptrdiff_t>(n));
  f.velocity.assign(p_.v.begin(), p_.v.begin() + static_cast<std::ptrdiff_t>(n));
  f.angularVelocity.assign(p_.omega.begin(), p_.omega.begin() + static_cast<std::ptrdiff_t>(n));
  f.contacts = recordedContacts_;
  f.wallContacts = recordedWallContacts_;
  if (setup_.shearRate != 0.0) {
    // Each particle as its primary image; the contact points it recorded (x_i - a_i n, at its
    // position as the engine holds it) move with it, so that extract's r_i - c stays a lever arm.
    std::unordered_map<std::int64_t, Vec3> moved;  // id -> shift, for the particles shown as another image
    for (std::size_t i = 0; i < n; ++i) {
      const Vec3 held = f.position[i];
      toPrimaryImage(f.position[i], f.velocity[i], setup_.lo, setup_.hi, f.domain.leesEdwardsOffset, setup_.shearRate);
      if (f.position[i] != held) moved.emplace(f.id[i], f.position[i] - held);
    }
    if (!moved.empty()) {
      for (std::size_t k = 0; k < f.contacts.size(); ++k) {
        if (const auto it = moved.find(f.contacts.i[k]); it != moved.end()) f.contacts.contactPoint[k] += it->second;
      }
      for (std::size_t k = 0; k < f.wallContacts.size(); ++k) {
        if (const auto it = moved.find(f.wallContacts.particle[k]); it != moved.end())
          f.wallContacts.point[k] += it->second;
      }
    }
  }
  return f;
}

}  // namespace grainbridge::dem
