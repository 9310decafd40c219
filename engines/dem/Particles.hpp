#pragma once
// Particle state as per-property arrays (structure of arrays): the pair loop streams through
// positions and velocities without pulling in unrelated fields. Indices [0, nOwned) are the
// particles this process integrates; [nOwned, size()) are ghosts: periodic and Lees-Edwards
// images now, other ranks' particles once the engine is domain-decomposed. Every particle has
// a global id, and contact history is keyed by ids, never by indices, so neither a re-sort nor
// a rebuild nor (later) a migration to another rank loses it.
#include <cstdint>
#include <vector>

#include "core/Types.hpp"

namespace grainbridge::dem {

struct Particles {
  // Per particle (owned and ghost).
  std::vector<std::int64_t> id;
  std::vector<std::int32_t> species;
  std::vector<double> radius;
  std::vector<double> mass;
  std::vector<double> invMass;     // 0 for frozen particles: infinite mass, m_eff = partner's mass
  std::vector<double> invInertia;  // 1 / (2/5 m a^2); 0 when frozen
  std::vector<Vec3> x;
  std::vector<Vec3> v;
  std::vector<Vec3> omega;
  std::vector<Vec3> force;
  std::vector<Vec3> torque;
  // Owned only: TF-DEM's drag a_p + B_p (u_p - v_p), filled once per fluid step and evaluated
  // every DEM step with the current velocity, and its pressure-gradient force (BodyForces.hpp).
  std::vector<Vec3> couplingA;
  std::vector<double> couplingB;
  std::vector<Vec3> couplingU;
  std::vector<Vec3> couplingPressure;

  // Ghost bookkeeping: ghost g = nOwned + k is an image of owned particle ghostOwner[k],
  // displaced by ghostShift[k] and moving with the extra velocity ghostVelocityShift[k]
  // (Lees-Edwards images move with the shearing boundary).
  std::size_t nOwned = 0;
  std::vector<std::size_t> ghostOwner;
  std::vector<Vec3> ghostShift;
  std::vector<Vec3> ghostVelocityShift;
  // Net number of Lees-Edwards boundary crossings of a ghost (+1: image above, -1: below). Its
  // x shift follows the growing offset: + crossings * (offset drift since the list was built).
  std::vector<std::int8_t> ghostShearCrossings;

  // Every per-particle array, declared here once: the ghost, re-sort and checkpoint code visit
  // these lists, so a new field (drag, void fraction) is one member plus one line below.
  // f(name, array): `name` is its dataset in checkpoints.
  // Arrays of owned and ghost particles; a ghost copies its owner's values (then the position and
  // velocity get the image's shift, force and torque start at zero).
  template <class Self, class F>
  static void forEachParticleArray(Self& p, F&& f) {
    f("id", p.id);
    f("species", p.species);
    f("radius", p.radius);
    f("mass", p.mass);
    f("inv_mass", p.invMass);
    f("inv_inertia", p.invInertia);
    f("position", p.x);
    f("velocity", p.v);
    f("angular_velocity", p.omega);
    f("force", p.force);
    f("torque", p.torque);
  }
  // Arrays of owned particles only (ghosts never read them).
  template <class Self, class F>
  static void forEachOwnedArray(Self& p, F&& f) {
    f("coupling_a", p.couplingA);
    f("coupling_b", p.couplingB);
    f("coupling_u", p.couplingU);
    f("coupling_pressure", p.couplingPressure);
  }

  [[nodiscard]] std::size_t size() const { return id.size(); }
  [[nodiscard]] bool isFrozen(std::size_t i) const { return invMass[i] == 0.0; }

  // Appends an owned particle (only while there are no ghosts).
  void addOwned(std::int64_t globalId, std::int32_t speciesIndex, double a, double m, const Vec3& position,
                const Vec3& velocity, const Vec3& angularVelocity, bool frozen);
  void clearGhosts();
  void addGhost(std::size_t owner, const Vec3& shift, const Vec3& velocityShift, std::int8_t shearCrossings = 0);
  // Copies owners' current state into their ghosts (every step between rebuilds);
  // `shearDrift` is the growth of the Lees-Edwards offset since the ghosts were built.
  void refreshGhosts(double shearDrift = 0.0);
  // Reorders owned particles by `order` (order[k] = old index of the new k-th particle);
  // requires no ghosts.
  void permuteOwned(const std::vector<std::size_t>& order);
};

}  // namespace grainbridge::dem
