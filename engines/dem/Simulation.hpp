#pragma once
// The soft-sphere DEM engine (Chapter 6 of the reference, Eqs. 6.1-6.10): velocity Verlet for
// translation and rotation, contact forces from a composed contact law (contact/), body forces
// from a list (BodyForces.hpp: gravity, background damping of Eq. 6.7, TF-DEM coupling), torques
// with the lever arm to the contact point (Eq. 6.8 generalised to unequal radii), periodic images
// as ghosts, rigid and vibrating walls.
#include <array>
#include <cstdint>
#include <optional>
#include <vector>

#include "core/Types.hpp"
#include "core/data/ParticleFrame.hpp"
#include "engines/dem/BodyForces.hpp"
#include "engines/dem/Energies.hpp"
#include "engines/dem/NeighborList.hpp"
#include "engines/dem/Particles.hpp"
#include "engines/dem/SimulationSetup.hpp"

namespace grainbridge::dem {

// Everything a checkpoint needs to continue a run bit for bit on the same binary: the owned
// particles in their current order (with the forces of the last evaluation, which the next
// half kick uses), the positions at the last neighbour-list build (the list is rebuilt from them,
// so the same pairs come in the same order and the next rebuild happens at the same step), and
// the contact histories keyed by particle ids.
struct EngineState {
  double time = 0.0;
  std::int64_t step = 0;
  std::int64_t rebuildsSinceSort = 0;
  Particles particles;               // owned only
  std::vector<Vec3> buildPositions;  // owned positions at the last list build
  double buildTime = 0.0;            // time of the last list build (Lees-Edwards offset then)
  std::vector<PairHistory> pairHistory;
  std::vector<Vec3> wallHistory;  // per (particle, wall), particle-major
  // Pressure control (SimulationSetup::PressureControl): the box's upper y as it now is, the
  // Lees-Edwards offset at the last box change and its time, and the p_yy samples summed since.
  double boxHighY = 0.0;
  double shearOffsetBase = 0.0;
  double shearOffsetTime = 0.0;
  double normalStressSum = 0.0;
  std::int64_t normalStressSamples = 0;
};

class Simulation {
 public:
  // Throws grainbridge::Error for an unusable setup (naming what is wrong).
  Simulation(SimulationSetup setup, Particles particles);
  // Continues from a captured state (restart); the setup must be the one that produced it.
  Simulation(SimulationSetup setup, EngineState state);
  [[nodiscard]] EngineState captureState() const;

  // One velocity-Verlet step. With recordContacts, the contacts of this step's force
  // evaluation are kept for frame() (recording changes nothing in the trajectory).
  void step(bool recordContacts = false);
  void run(std::int64_t steps);

  [[nodiscard]] double time() const { return time_; }
  [[nodiscard]] std::int64_t stepCount() const { return step_; }
  // Steps this object has taken (a preparation's included, a resumed run's earlier ones not): the
  // window rebuilds() counts its list builds over.
  [[nodiscard]] std::int64_t stepsTaken() const { return stepsTaken_; }
  [[nodiscard]] const Particles& particles() const { return p_; }
  Particles& mutableParticles() { return p_; }
  [[nodiscard]] const SimulationSetup& setup() const { return setup_; }
  [[nodiscard]] Energies energies() const;
  // Owned particles that move (not frozen): what coordination numbers count.
  [[nodiscard]] std::int64_t mobileCount() const;
  [[nodiscard]] Vec3 momentum() const;
  [[nodiscard]] std::int64_t rebuilds() const { return list_.builds(); }
  [[nodiscard]] std::int64_t innerRebuilds() const { return list_.innerBuilds(); }  // NeighborList::buildInner
  // Lees-Edwards offset of the image above at time t, in [0, L_x).
  [[nodiscard]] double shearOffset(double t) const;
  [[nodiscard]] std::size_t contactCount() const { return contactCount_; }
  // Power dissipated by the dashpots (-F_n,diss . v_n - F_t,diss . v_t summed over contacts) at
  // the last force evaluation that recorded contacts; Coulomb sliding losses are not included.
  [[nodiscard]] double dashpotDissipation() const { return dissipation_; }
  // The box as it now is (pressure control moves its upper y) and the whole-domain normal stress
  // p_yy of Eq. 2.3 at the last step (kinetic + contact part; computed under pressure control).
  [[nodiscard]] Vec3 boxLow() const { return setup_.lo; }
  [[nodiscard]] Vec3 boxHigh() const { return setup_.hi; }
  [[nodiscard]] double normalStressYY() const { return normalStressYY_; }
  // Total force each wall received from the particles at the last force evaluation.
  [[nodiscard]] const std::vector<Vec3>& wallForces() const { return wallForce_; }
  // The body forces the step applies; each can record what it applied (BodyForces.hpp).
  BodyForces& bodyForces() { return bodyForces_; }
  [[nodiscard]] const BodyForces& bodyForces() const { return bodyForces_; }

  // Rebuilds the neighbour list now (optionally re-sorting particles by cell first); contact
  // history is carried over by particle ids, so trajectories do not depend on when this happens.
  void forceRebuild(bool sort);

  // The current state as a frame of the data model; contacts as recorded by the last step
  // (call refreshContacts() first when that step did not record them).
  [[nodiscard]] core::data::ParticleFrame frame() const;
  // Records the contacts of the current state when the last force evaluation did not (after
  // unrecorded steps, a preparation or a restart): the contact part of a set-up evaluation,
  // history kept and the forces the next half kick uses put back, so neither the trajectory nor
  // the body forces' records depend on it.
  void refreshContacts();

  // Preparation protocols (Section 6.2's two-step preparation): hold particles in place with
  // infinite mass, change a wall's vibration between phases, start the clock of a new phase.
  void setFrozen(std::int64_t id, bool frozen);
  void setWallVibration(std::size_t wall, const Vibration& vibration);
  void restartClock();

  // The largest overlap between two particles, relative to the smaller diameter, with the ids
  // of that pair (a check of initial states read from files).
  struct Overlap {
    double relative = 0.0;
    std::int64_t i = -1;
    std::int64_t j = -1;
  };
  [[nodiscard]] Overlap largestOverlap() const;

  // Index of the owned particle with this global id (linear search; for tests and setup).
  [[nodiscard]] std::optional<std::size_t> indexOf(std::int64_t id) const;

 private:
  void validateSetup();
  void rebuild(bool sort);
  // At a list build, per wall, the owned particles that can touch it before the next build (the
  // same rule as the list's pairs: a particle moves less than half the skin between builds, less
  // the streaming motion under shear); the others' wall history is zeroed, as the contact loop
  // would zero it at every step until then. A vibrating wall keeps every particle, and so does,
  // under shear, a wall whose gap the streaming motion along x changes. `clearOthers` is false when a restored state's
  // histories are already what the run had.
  void selectWallCandidates(bool clearOthers);
  // How far one particle may move from its position at a list's last build before that list must
  // be rebuilt (<= 0: rebuild now): the Verlet list with setup_.skin since buildTime_, the inner
  // list with innerSkin_ since innerBuildTime_.
  [[nodiscard]] double rebuildReach(double skin, double builtAt) const;
  // What rebuildReach bounds, squared: a particle's displacement from its position at a list
  // build, less the streaming field's affine part, strain (y_0 - y_mid) along x. In scalars, summed
  // in the order of Eigen's squaredNorm (so a run without shear decides as before, to the bit): a
  // Vec3 with one component set apart went through the stack, and its packed reload waited on
  // store forwarding (the step ran 2.2 times slower).
  [[nodiscard]] static double squaredPeculiarDisplacement(const Vec3& x, const Vec3& atBuild, double strain,
                                                          double midY) {
    const double dx = (x[0] - atBuild[0]) - strain * (atBuild[1] - midY);
    const double dy = x[1] - atBuild[1];
    const double dz = x[2] - atBuild[2];
    return (dx * dx + dy * dy) + dz * dz;
  }
  void buildInner();
  void wrapAndCheck();
  void buildGhosts(double shearOffsetNow);
  [[nodiscard]] double shearDrift(double since) const;  // offset growth since `since` (a build)
  // A step's force evaluation, the same with its contacts recorded for frame(), or the set-up
  // evaluation of a run (recorded, contact history kept as it is).
  enum class Evaluation { Step, StepRecorded, Setup };
  // ownedCleared: the owned particles' forces and torques are zero already (step clears them)
  void computeForces(Evaluation evaluation, bool ownedCleared = false);
  // The contact part of computeForces: forces cleared, contacts evaluated (and recorded).
  void contactForces(Evaluation evaluation, bool ownedCleared = false);
  template <class Law>
  void contactLoops(Evaluation evaluation);
  // One evaluation's pair and wall loops, the pair loop's frictionless form when every mu is 0.
  template <class Law, bool Record, contact::History H>
  void contactsOf();
  // After the contacts: ghost forces to their owners, body forces, the plane of a 2-D bed, then
  // then(i) for each owned particle in the same pass.
  template <class Then>
  void finishForces(Then&& then);
  void constrainToPlane(std::size_t i, int axis);
  // Frictionless: every pair's mu is 0 (frictionless_), so the Coulomb cap leaves no tangential
  // force and the pairs' tangential step and torques are skipped (ContactLaw::evaluateNormal).
  template <class Law, bool Record, contact::History H, bool Frictionless>
  void pairForces();
  template <class Law, bool Record, contact::History H>
  void wallForces();
  void sortByCell();
  // Pressure control: p_yy of this step into the running mean, and every interval steps the box
  // scaled along y (SimulationSetup::PressureControl).
  void controlPressure();
  // Compression: every interval steps the box's length along y set by its schedule
  // (SimulationSetup::Compression), until it holds the target.
  void compress();
  // The box's length along y changed to `length` (= scale times the old one; both given so
  // pressure control's box stays bit for bit as it was): the Lees-Edwards offset so far kept,
  // positions scaled affinely about the lower face, the neighbour list rebuilt. `why` names the
  // cause in the error of a box too thin for its ghosts.
  void resizeAlongY(double scale, double length, const char* why);

  SimulationSetup setup_;
  contact::AnyContactLaw law_;  // the composition setup_.contact names
  BodyForces bodyForces_;
  Particles p_;
  NeighborList list_;
  double contactVirialYY_ = 0.0;  // sum over touching pairs of r_y F_y at the last evaluation
  double normalStressYY_ = 0.0;
  double normalStressSum_ = 0.0;
  std::int64_t normalStressSamples_ = 0;
  // The Lees-Edwards offset is shearOffsetBase_ + gammadot L_y (t - shearOffsetTime_): L_y is
  // constant between box changes (both 0 without pressure control: the plain formula).
  double shearOffsetBase_ = 0.0;
  double shearOffsetTime_ = 0.0;
  // Compression: the box's length along y as configured (the schedule's start) and as it is to end.
  double compressionStartLength_ = 0.0;
  double compressionTargetLength_ = 0.0;
  double cutoff_ = 0.0;
  double time_ = 0.0;
  double buildTime_ = 0.0;
  double innerSkin_ = 0.0;  // the inner list's skin (NeighborList::buildInner)
  double innerBuildTime_ = 0.0;
  bool frictionless_ = false;  // every pair material's mu is 0 (pairForces' Frictionless)
  std::int64_t step_ = 0;
  std::int64_t stepsTaken_ = 0;
  std::int64_t rebuildsSinceSort_ = 0;
  std::size_t contactCount_ = 0;
  double dissipation_ = 0.0;
  // Wall contact history u_t per (owned particle, wall), carried with the particle on re-sort.
  std::vector<Vec3> wallHistory_;
  std::vector<Vec3> wallForce_;
  std::vector<std::vector<std::size_t>> wallCandidates_;  // per wall, increasing particle index
  bool contactsCurrent_ = false;                          // recordedContacts_ belong to the current state
  core::data::ContactList recordedContacts_;
  core::data::WallContactList recordedWallContacts_;
};

}  // namespace grainbridge::dem
