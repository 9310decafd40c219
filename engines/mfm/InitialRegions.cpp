#include "engines/mfm/InitialRegions.hpp"

#include <optional>
#include <random>
#include <string>

#include "core/json/Vec3Json.hpp"
#include "core/text/NumberText.hpp"
#include "engines/fluid/BedMeasures.hpp"

namespace grainbridge::mfm {

void applyRegions(fluid::FlowState& st, const InitialState& init) {
  const auto& grid = st.grid();
  const std::size_t M = st.phases.size();
  std::mt19937_64 rng(init.seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int k = 0; k < grid.cells(2); ++k) {
    for (int j = 0; j < grid.cells(1); ++j) {
      for (int i = 0; i < grid.cells(0); ++i) {
        const std::size_t c = grid.index(i, j, k);
        const Vec3 x = grid.cellCentre(i, j, k);
        const InitialRegion* region = nullptr;
        for (const auto& r : init.regions) {
          bool inside = true;
          for (int a = 0; a < grid.dimensions(); ++a) inside = inside && x[a] >= r.lo[a] && x[a] < r.hi[a];
          if (inside) region = &r;
        }
        const double noise = unit(rng);  // drawn for every cell: the sequence is the grid's
        double solids = 0.0;
        for (std::size_t m = 1; m < M; ++m) {
          double eps = region != nullptr ? region->solidsFractions[m - 1] : 0.0;
          eps *= 1.0 - init.perturbation * noise;
          st.phases[m].fraction[c] = eps;
          st.phases[m].granularTemperature[c] = region != nullptr ? region->granularTemperature : 0.0;
          solids += eps;
        }
        st.phases[0].fraction[c] = 1.0 - solids;
        for (std::size_t m = 0; m < M; ++m) {
          const Vec3 v = region != nullptr ? region->velocities[m] : Vec3::Zero();
          // The faces of the cell's high sides; a face shared with the next cell takes the last
          // written, so regions set velocities face-exactly where they meet.
          for (int a = 0; a < grid.dimensions(); ++a) {
            st.phases[m].velocity[static_cast<std::size_t>(a)][c] = v[a];
            if (grid.coordinates(c)[static_cast<std::size_t>(a)] == 0)
              st.phases[m].velocity[static_cast<std::size_t>(a)][grid.neighbour(c, a, -1)] = v[a];
          }
        }
      }
    }
  }
}

void initialise(MultiFluidEngine& engine, const InitialState& init) {
  applyRegions(engine.state(), init);
  auto& st = engine.state();
  const auto& grid = engine.grid();
  const std::size_t M = st.phases.size();
  // The gas pressure: each cell carries the weight of the mixture above it, starting from the
  // reference at the top.
  const fluid::VerticalAxis v = fluid::verticalAxis(engine.settings().gravity);
  const double g = engine.settings().gravity.norm();
  const double h = grid.spacing(v.axis);
  const int n = grid.cells(v.axis);
  const auto& model = engine.model().params();
  for (int k = 0; k < grid.cells(2); ++k) {
    for (int j = 0; j < grid.cells(1); ++j) {
      for (int i = 0; i < grid.cells(0); ++i) {
        std::array<int, 3> at{i, j, k};
        if (at[static_cast<std::size_t>(v.axis)] != 0) continue;
        // From the top face (the reference) down: half of each cell's weight lies above its
        // centre, so consecutive centres differ by the mean of their two cells' weights.
        double p = init.referencePressure, weightAbove = 0.0;
        for (int b = n - 1; b >= 0; --b) {  // b counts rows from the bottom
          at[static_cast<std::size_t>(v.axis)] = v.up > 0.0 ? b : n - 1 - b;
          const std::size_t c = grid.index(at[0], at[1], at[2]);
          double density = st.phases[0].fraction[c] * model.gas.densityAt(p);
          for (std::size_t m = 1; m < M; ++m) density += st.phases[m].fraction[c] * model.solids[m - 1].density;
          const double weight = density * g * h;
          p += 0.5 * (weightAbove + weight);
          st.pressure[c] = p;
          weightAbove = weight;
        }
      }
    }
  }
}

namespace {

// Why region `r` (at pointer `at`) sets no cell, or nothing: applyRegions sets the cells whose
// centres lie in [lo, hi) along every axis the grid resolves, so lo above hi, lo = hi, or a box
// between two centres leaves the region empty without a word. A 2D grid does not test z (its
// depth), where only a reversed box is refused.
std::optional<core::engine::SetupProblem> emptyRegionProblem(const InitialRegion& r, const std::string& at,
                                                             const core::data::GridGeometry& domain) {
  const bool twoD = domain.cells[2] == 1;
  for (int a = 0; a < 3; ++a) {
    const bool resolved = !(twoD && a == 2);
    const std::string axis(1, "xyz"[a]);
    const std::string lo = core::humanNumber(r.lo[a]), hi = core::humanNumber(r.hi[a]);
    if (r.lo[a] > r.hi[a]) {
      return core::engine::SetupProblem{at + "/lo", "lo along " + axis + " is " + lo + " m, above hi " + hi + " m" +
                                                        (resolved ? ": the region holds no cell" : "") +
                                                        "; give the lower corner in lo"};
    }
    if (!resolved) continue;
    if (r.lo[a] == r.hi[a]) {
      return core::engine::SetupProblem{
          at + "/hi", "lo and hi along " + axis + " are both " + lo +
                          " m: the region holds no cell (a cell is in it when its centre is in [lo, hi))"};
    }
    bool centre = false;
    for (int i = 0; i < domain.cells[static_cast<std::size_t>(a)] && !centre; ++i) {
      const double x = domain.origin[a] + (i + 0.5) * domain.spacing[a];  // StaggeredGrid::cellCentre
      centre = x >= r.lo[a] && x < r.hi[a];
    }
    if (!centre) {
      return core::engine::SetupProblem{
          at + "/hi", "[" + lo + ", " + hi + ") m along " + axis +
                          " holds no cell centre (cells of " + core::humanNumber(domain.spacing[a]) +
                          " m): the region holds no cell; widen it over the centres of the cells it means"};
    }
  }
  return std::nullopt;
}

}  // namespace

std::vector<core::engine::SetupProblem> InitialState::problems(const core::data::GridGeometry& domain,
                                                               std::size_t solidsPhases,
                                                               const fluid::FluidSetup::PackedFraction& packedFraction) const {
  std::vector<core::engine::SetupProblem> out;
  for (std::size_t k = 0; k < regions.size(); ++k) {
    const InitialRegion& r = regions[k];
    const std::string at = "/regions/" + std::to_string(k);
    if (r.solidsFractions.size() != solidsPhases) {
      out.push_back({at + "/solids_fractions", "gives " + std::to_string(r.solidsFractions.size()) + " fractions for " +
                                                   std::to_string(solidsPhases) + " solids phases"});
    } else {
      double solids = 0.0;
      for (const double f : r.solidsFractions) solids += f;
      if (const double packed = packedFraction(r.solidsFractions); solids > packed + 1e-12) {
        out.push_back({at + "/solids_fractions",
                       "the solids fractions add up to " + core::humanNumber(solids) +
                           ", above the packed solids fraction of this composition eps_s,max = " +
                           core::humanNumber(packed)});
      }
    }
    // Inside the domain along every axis, to round-off: a box past a side would start the run
    // with fewer grains than the config describes, silently.
    for (int a = 0; a < 3; ++a) {
      const double low = domain.origin[a];
      const double high = low + domain.cells[static_cast<std::size_t>(a)] * domain.spacing[a];
      const double slack = 1e-9 * (high - low);
      const std::string along = std::string(" along ") + "xyz"[a] + " is ";
      const std::string domainText =
          " m, outside the domain (" + core::humanNumber(low) + " to " + core::humanNumber(high) + " m)";
      if (r.lo[a] < low - slack) out.push_back({at + "/lo", "lo" + along + core::humanNumber(r.lo[a]) + domainText});
      if (r.hi[a] > high + slack) out.push_back({at + "/hi", "hi" + along + core::humanNumber(r.hi[a]) + domainText});
    }
    if (auto empty = emptyRegionProblem(r, at, domain)) out.push_back(std::move(*empty));
  }
  return out;
}

void to_json(nlohmann::json& j, const InitialRegion& r) {
  j = {{"lo", core::json::vec3Json(r.lo)},
       {"hi", core::json::vec3Json(r.hi)},
       {"solids_fractions", r.solidsFractions},
       {"gas_velocity", core::json::vec3Json(r.velocities.empty() ? Vec3::Zero() : r.velocities[0])},
       {"solids_velocity", core::json::vec3Json(r.velocities.size() < 2 ? Vec3::Zero() : r.velocities[1])},
       {"granular_temperature", r.granularTemperature}};
}

void from_json(const nlohmann::json& j, InitialRegion& r) {
  r.lo = core::json::vec3FromJson(j.at("lo"));
  r.hi = core::json::vec3FromJson(j.at("hi"));
  r.solidsFractions = j.at("solids_fractions").get<std::vector<double>>();
  r.granularTemperature = j.at("granular_temperature");
  r.velocities.assign(1 + r.solidsFractions.size(), core::json::vec3FromJson(j.at("solids_velocity")));
  r.velocities[0] = core::json::vec3FromJson(j.at("gas_velocity"));
}

void to_json(nlohmann::json& j, const InitialState& s) {
  j = {{"regions", s.regions},
       {"reference_pressure", s.referencePressure},
       {"perturbation", s.perturbation},
       {"seed", s.seed}};
}

void from_json(const nlohmann::json& j, InitialState& s) {
  s.regions = j.contains("regions") ? j.at("regions").get<std::vector<InitialRegion>>() : std::vector<InitialRegion>{};
  s.referencePressure = j.at("reference_pressure");
  s.perturbation = j.at("perturbation");
  s.seed = j.at("seed").get<std::uint64_t>();
}

}  // namespace grainbridge::mfm
