#pragma once
// The mu(I) rheology a continuum run reads from the workflow database (a tabulate stage's
// `rheology` rows of relation mu_of_I, one per restitution): the measured points and, where the
// points determined it, the fit mu_s + (mu_2 - mu_s) / (1 + I_0 / I), with the grains they were
// measured on and where they came from. db::ClosureStore loads it; it reaches the stage as it is
// and becomes JSON only to cross to a worker rank, as LoadedClosureTable does.
#include <nlohmann/json_fwd.hpp>
#include <optional>
#include <string>
#include <vector>

namespace grainbridge::core {

// The form of the mu(I) rows a continuum engine loads (Jop, Forterre and Pouliquen's): a rheology
// table also holds the power-law form's rows (issue 61), which `plastic: mu_i` does not use.
inline constexpr const char* kMuOfIJopForm = "mu_s + (mu_2 - mu_s) / (1 + I_0 / I)";

// The quantity a stage's closure-table reference names for a tabulate stage's mu(I) rows.
inline constexpr const char* kRheologyQuantity = "mu_of_I";

struct LoadedRheology {
  struct Fit {
    double staticRatio = 0.0, limitRatio = 0.0, inertialNumberScale = 0.0;  // mu_s, mu_2, I_0
  };
  struct Row {
    std::optional<double> restitution;  // the DEM's e (none when its points did not say)
    std::vector<double> inertialNumbers, stressRatios;  // in increasing I
    std::optional<Fit> fit;
  };
  std::string name;    // the tabulate stage's `table`
  std::string runKey;  // the run that made it
  std::string sha256;  // over the content alone
  double diameter = 0.0, density = 0.0;  // the grains [m], [kg/m^3]
  std::vector<Row> rows;

  // The row of restitution e (core::sameValue), or nullptr.
  [[nodiscard]] const Row* atRestitution(double e) const;
};

// The sha256 of the content (grains and rows): equal rheologies hash equal whatever their run.
[[nodiscard]] std::string contentSha256(const LoadedRheology& rheology);

void to_json(nlohmann::json& j, const LoadedRheology& r);
// Throws grainbridge::Error naming what is missing.
[[nodiscard]] LoadedRheology loadedRheologyFromJson(const nlohmann::json& j);

}  // namespace grainbridge::core
