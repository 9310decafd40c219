#include "workflows/stages/DemSeriesColumns.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/Error.hpp"
#include "engines/dem/DomainStress.hpp"

namespace grainbridge::workflows::stages {

using driver::SeriesColumns;
using driver::SeriesRow;

namespace {

class EnergyColumns final : public SeriesColumns {
 public:
  explicit EnergyColumns(dem::ParticleEngine& engine) : engine_(engine) {}
  [[nodiscard]] std::vector<std::string> names() const override { return {"ke_translational", "ke_rotational"}; }
  void sample(SeriesRow& row) override {
    const auto e = engine_.energies();
    row.add(e.translational).add(e.rotational);
  }

 private:
  dem::ParticleEngine& engine_;
};

// Coordination counts the mobile grains only: a frozen rough base is not part of the packing.
// Counted in the state sampled, so it holds for states read from files (whose species declare no
// counts) and after a preparation has released the grains it held.
class ContactColumns final : public SeriesColumns {
 public:
  explicit ContactColumns(dem::ParticleEngine& engine) : engine_(engine) {}
  [[nodiscard]] std::vector<std::string> names() const override { return {"contacts", "coordination"}; }
  void sample(SeriesRow& row) override {
    const auto contacts = engine_.frame().contacts.size();
    const auto mobile = engine_.mobileCount();
    row.add(contacts).add(mobile > 0 ? 2.0 * static_cast<double>(contacts) / static_cast<double>(mobile) : 0.0);
  }

 private:
  dem::ParticleEngine& engine_;
};

// Eq. 2.3 over the whole box, as it is now (pressure control moves it).
class StressColumns final : public SeriesColumns {
 public:
  explicit StressColumns(dem::ParticleEngine& engine) : engine_(engine) {}
  [[nodiscard]] std::vector<std::string> names() const override {
    return {"stress_xx", "stress_yy", "stress_zz", "stress_xy", "stress_xz", "stress_yz"};
  }
  void sample(SeriesRow& row) override {
    const auto& frame = engine_.frame();
    const Mat3 sigma = dem::wholeDomainStress(frame, (frame.domain.hi - frame.domain.lo).prod());
    for (auto [a, b] : {std::pair{0, 0}, {1, 1}, {2, 2}, {0, 1}, {0, 2}, {1, 2}}) row.add(sigma(a, b));
  }

 private:
  dem::ParticleEngine& engine_;
};

// A box moving along y (pressure control or compression): its length along the gradient and the
// solid fraction in it; under pressure control also the p_yy the control saw at the step (the
// stress_yy column is Eq. 2.3 of the frame, the same state).
class MovingBoxColumns final : public SeriesColumns {
 public:
  MovingBoxColumns(const dem::DemEngine& engine, bool controlled) : engine_(engine), controlled_(controlled) {}
  [[nodiscard]] std::vector<std::string> names() const override {
    if (!controlled_) return {"box_length_y", "solid_fraction"};
    return {"box_length_y", "solid_fraction", "controlled_stress_yy"};
  }
  void sample(SeriesRow& row) override {
    const auto& sim = engine_.simulation();
    const Vec3 length = sim.boxHigh() - sim.boxLow();
    const auto& p = sim.particles();
    double volume = 0.0;
    for (std::size_t i = 0; i < p.nOwned; ++i) volume += 4.0 / 3.0 * M_PI * std::pow(p.radius[i], 3);
    row.add(length[1]).add(volume / length.prod());
    if (controlled_) row.add(sim.normalStressYY());
  }

 private:
  const dem::DemEngine& engine_;
  bool controlled_;
};

class WallForceColumns final : public SeriesColumns {
 public:
  WallForceColumns(dem::ParticleEngine& engine, std::size_t walls) : engine_(engine), walls_(walls) {}
  [[nodiscard]] std::vector<std::string> names() const override {
    std::vector<std::string> out;
    for (std::size_t w = 0; w < walls_; ++w) {
      for (const char* c : {"x", "y", "z"}) out.push_back("wall" + std::to_string(w) + "_f" + c);
    }
    return out;
  }
  void sample(SeriesRow& row) override {
    for (const auto& f : engine_.wallForces()) row.add(f[0]).add(f[1]).add(f[2]);
  }

 private:
  dem::ParticleEngine& engine_;
  std::size_t walls_;
};

// Per species: the centre of mass height, then the highest top (z + a), the free surface.
class SpeciesHeightColumns final : public SeriesColumns {
 public:
  SpeciesHeightColumns(dem::ParticleEngine& engine, std::vector<std::string> species)
      : engine_(engine), species_(std::move(species)) {}
  [[nodiscard]] std::vector<std::string> names() const override {
    std::vector<std::string> out;
    for (const auto& s : species_) out.push_back("com_z_" + s);
    for (const auto& s : species_) out.push_back("top_z_" + s);
    return out;
  }
  void sample(SeriesRow& row) override {
    const auto& f = engine_.frame();
    std::vector<double> z(species_.size(), 0.0);
    std::vector<double> m(species_.size(), 0.0);
    std::vector<double> top(species_.size(), -std::numeric_limits<double>::infinity());
    for (std::size_t i = 0; i < f.size(); ++i) {
      const auto s = static_cast<std::size_t>(f.species[i]);
      z[s] += f.mass[i] * f.position[i][2];
      m[s] += f.mass[i];
      top[s] = std::max(top[s], f.position[i][2] + f.radius[i]);
    }
    for (std::size_t s = 0; s < z.size(); ++s) row.add(m[s] > 0 ? z[s] / m[s] : 0.0);
    for (double t : top) row.add(t);
  }

 private:
  dem::ParticleEngine& engine_;
  std::vector<std::string> species_;
};

class TrackedHeightColumns final : public SeriesColumns {
 public:
  TrackedHeightColumns(dem::ParticleEngine& engine, std::vector<std::int64_t> ids) : engine_(engine), ids_(std::move(ids)) {}
  [[nodiscard]] std::vector<std::string> names() const override {
    std::vector<std::string> out;
    for (const auto id : ids_) out.push_back("z_id" + std::to_string(id));
    return out;
  }
  void sample(SeriesRow& row) override {
    const auto& f = engine_.frame();
    for (const auto id : ids_) {
      const auto it = std::find(f.id.begin(), f.id.end(), id);
      GB_ASSERT(it != f.id.end(), "tracked particle " + std::to_string(id) + " is checked at the start of the run");
      row.add(f.position[static_cast<std::size_t>(it - f.id.begin())][2]);
    }
  }

 private:
  dem::ParticleEngine& engine_;
  std::vector<std::int64_t> ids_;
};

}  // namespace

std::vector<std::unique_ptr<SeriesColumns>> demSeriesColumns(dem::ParticleEngine& engine, const DemSetup& setup) {
  std::vector<std::string> species;
  for (const auto& s : setup.species) species.push_back(s.name);
  std::vector<std::unique_ptr<SeriesColumns>> out;
  out.push_back(std::make_unique<EnergyColumns>(engine));
  out.push_back(std::make_unique<ContactColumns>(engine));
  out.push_back(std::make_unique<StressColumns>(engine));
  if (setup.engine.boxMovesAlongY()) {
    // Pressure control and compression are grainbridge's own (refused on engine lammps at check).
    auto* own = dynamic_cast<dem::DemEngine*>(&engine);
    GB_ASSERT(own != nullptr, "a box moving along y runs on grainbridge's engine only");
    out.push_back(std::make_unique<MovingBoxColumns>(*own, setup.engine.pressureControl.active()));
  }
  out.push_back(std::make_unique<WallForceColumns>(engine, setup.engine.walls.size()));
  out.push_back(std::make_unique<SpeciesHeightColumns>(engine, std::move(species)));
  out.push_back(std::make_unique<TrackedHeightColumns>(engine, setup.trackedIds));
  return out;
}

}  // namespace grainbridge::workflows::stages
