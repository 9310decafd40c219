#pragma once
// Body forces: what acts on a particle besides its contacts, as a list the step applies in order
// (gravity, the background damping of Eq. 6.7, and TF-DEM's two forces from the gas the fluid
// step sets: the drag a_p + B_p (u_p - v_p) and the pressure-gradient force, kept apart so the
// drag alone can be recorded, Fig. 7.7's f'). Each is a small struct; adding one is the struct plus one line in
// `BodyForceList` below. Any of them can record what it applied to each owned particle at the
// last force evaluation: TF-DEM hands the gas exactly the force the particles received.
// Frozen particles receive none (their force and torque are held at zero).
#include <tuple>
#include <vector>

#include "core/Types.hpp"
#include "engines/dem/Particles.hpp"
#include "engines/dem/SimulationSetup.hpp"

namespace grainbridge::dem {

struct Gravity {
  static constexpr const char* name = "gravity";
  static bool active(const SimulationSetup& s) { return !s.gravity.isZero(0.0); }
  static Vec3 on(const Particles& p, const SimulationSetup& s, std::size_t i) { return p.mass[i] * s.gravity; }
};

// Eq. 6.7: -b v, with the half-step velocity (as the coupling force).
struct BackgroundDamping {
  static constexpr const char* name = "background_damping";
  static bool active(const SimulationSetup& s) { return s.backgroundDamping != 0.0; }
  static Vec3 on(const Particles& p, const SimulationSetup& s, std::size_t i) { return -s.backgroundDamping * p.v[i]; }
};

// TF-DEM's drag on a particle (Chapter 7, eps_g f_d of Eq. 7.28), a_p + B_p (u_p - v_p), from
// the owned arrays couplingA, couplingB, couplingU the fluid step fills once per fluid step:
// a_p a drag held over the fluid step (Eq. 7.33's cell mean), B_p (u_p - v_p) one evaluated every
// DEM step with the particle's current velocity (Eq. 7.29), so it follows the particle between
// fluid steps.
struct FluidCoupling {
  static constexpr const char* name = "fluid_coupling";
  static bool active(const SimulationSetup& s) { return s.fluidCoupled; }
  static Vec3 on(const Particles& p, const SimulationSetup& /*s*/, std::size_t i) {
    return p.couplingA[i] + p.couplingB[i] * (p.couplingU[i] - p.v[i]);
  }
};

// TF-DEM's pressure-gradient force on a particle, -V_p grad P_g (Eq. 7.28), from the owned array
// couplingPressure the fluid step fills; held over the fluid step. Both act only in a
// fluid-coupled run: in a plain DEM run their arrays are zero, and reading them cost the dense
// bed 3 % of its time for nothing.
struct FluidPressure {
  static constexpr const char* name = "fluid_pressure";
  static bool active(const SimulationSetup& s) { return s.fluidCoupled; }
  static Vec3 on(const Particles& p, const SimulationSetup& /*s*/, std::size_t i) { return p.couplingPressure[i]; }
};

// One body force with its optional record (per owned particle, in the current particle order;
// Particles::id names them).
template <class Force>
struct RecordedBodyForce {
  bool record = false;
  std::vector<Vec3> applied;
};

template <class... Forces>
class BodyForceSet {
 public:
  // Adds every active force to the owned particles' force, in the list's order, summed first so
  // the total is the same to the last bit whichever are recorded. A frozen particle's force and
  // torque are set to zero instead. Then `finish(i)`, while the particle is still in cache: the
  // step's closing half kick rides on this pass instead of making its own.
  template <class Finish>
  void apply(Particles& p, const SimulationSetup& s, Finish&& finish) {
    const bool active[] = {Forces::active(s)...};
    std::apply([&](auto&... r) { (prepare(r, p.nOwned), ...); }, records_);
    Vec3* const force = p.force.data();  // a local pointer: see Simulation::step
    const std::size_t n = p.nOwned;
    for (std::size_t i = 0; i < n; ++i) {
      if (p.isFrozen(i)) {
        force[i].setZero();
        p.torque[i].setZero();
      } else {
        Vec3 total = Vec3::Zero();
        std::size_t k = 0;
        std::apply([&](auto&... r) { (add<Forces>(r, active[k++], p, s, i, total), ...); }, records_);
        force[i] += total;
      }
      finish(i);
    }
  }

  // Keep (or stop keeping) what Force applied, from the next force evaluation on.
  template <class Force>
  void setRecording(bool on) {
    std::get<RecordedBodyForce<Force>>(records_).record = on;
  }
  // What Force applied to each owned particle at the last evaluation (empty unless it recorded).
  template <class Force>
  [[nodiscard]] const std::vector<Vec3>& applied() const {
    return std::get<RecordedBodyForce<Force>>(records_).applied;
  }

 private:
  template <class Force>
  static void prepare(RecordedBodyForce<Force>& r, std::size_t n) {
    // A record belongs to the evaluation that made it: one that does not record drops it.
    if (r.record) {
      r.applied.assign(n, Vec3::Zero());
    } else if (!r.applied.empty()) {
      r.applied.clear();
    }
  }
  template <class Force>
  static void add(RecordedBodyForce<Force>& r, bool active, const Particles& p, const SimulationSetup& s, std::size_t i,
                  Vec3& total) {
    if (!active) return;
    const Vec3 f = Force::on(p, s, i);
    total += f;
    if (r.record) r.applied[i] = f;
  }

  std::tuple<RecordedBodyForce<Forces>...> records_;
};

// ---- the list: one line per body force, applied in this order -------------------------------
using BodyForces = BodyForceSet<Gravity,            //
                                BackgroundDamping,  //
                                FluidCoupling,      //
                                FluidPressure>;

}  // namespace grainbridge::dem
