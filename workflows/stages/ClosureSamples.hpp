#pragma once
// Closure samples of a continuum run on DEM closure tables (issue 31): besides the nominal run,
// runs on realisations of the tables drawn within their standard errors (core/ClosureTableDraw),
// so that a comparing stage can say how much the DEM's statistical error moves the answer.
//
// `closure_samples` N asks for N joint samples (every table drawn) and
// `closure_samples_per_quantity` M for M one-at-a-time samples of each table quantity (that
// quantity drawn, the others nominal), which say which quantity the spread comes from. The
// planner makes each sample a replica of the instance (StageType::replicas) with its own key.
//
// Which sample a run is has one representation, ClosureDraw (issue 57). The planner writes it
// once, as the replica's overlay `closure_draw` in the sample's params: so it enters the sample's
// key and reaches its run on whatever rank runs it. The run draws its tables from it and records
// it as its products, the summary values closure_sample and closure_perturbed, which a comparing
// stage reads by name (UpstreamInstance::summaryValue) and finds declared in the sample's
// PlannedOutput. The sample's sweep point is its nominal run's: a comparing stage matches a
// sample to its nominal run by stage and sweep point, with no label to strip. Sample k's tables
// are drawn from the stream seeded by (sample_seed, k), so a sample is reproducible from its seed
// and independent of the others. The nominal run's key is that of the run without samples: the
// three parameters do not affect its results.
#include <cstdint>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "core/LoadedClosureTable.hpp"
#include "workflows/params/ParamSchema.hpp"
#include "workflows/stages/PlannedOutput.hpp"
#include "workflows/stages/StageType.hpp"

namespace grainbridge::workflows::stages {

// The summary values a closure sample records (and declares in its PlannedOutput): the sample
// number k, and "all" or the one quantity drawn. A nominal run records neither.
inline constexpr const char* kClosureSampleKey = "closure_sample";
inline constexpr const char* kClosurePerturbedKey = "closure_perturbed";

// Which closure sample a run is. Its JSON form ({"sample", "seed", "quantities", "perturbed"})
// is the overlay `closure_draw` and enters the sample's key: changing it reruns cached samples.
struct ClosureDraw {
  int sample = 0;                       // k = 1, 2, ... among the instance's samples
  std::int64_t seed = 1;                // sample_seed
  std::vector<std::string> quantities;  // the table quantities drawn; the others stay nominal
  std::string perturbed = "all";        // "all" (a joint sample) or the one quantity drawn

  // The seed of core::drawClosureTable: sample_seed in the upper 32 bits, k in the lower.
  [[nodiscard]] std::uint64_t stream() const;
  [[nodiscard]] bool draws(const std::string& quantity) const;
  // The run's summary values that say which sample it is (kClosureSampleKey, kClosurePerturbedKey).
  [[nodiscard]] nlohmann::json summary() const;

  friend bool operator==(const ClosureDraw&, const ClosureDraw&) = default;
};

void to_json(nlohmann::json& j, const ClosureDraw& draw);
void from_json(const nlohmann::json& j, ClosureDraw& draw);

// closure_samples, closure_samples_per_quantity, sample_seed.
void addClosureSampleParams(params::ParamSchema& schema);

// The nominal run and its samples; the nominal run alone without samples.
// `tableQuantities`: the quantities of the tables the run reads (p_theta, eta_theta, j_theta).
[[nodiscard]] std::vector<Replica> closureSampleReplicas(const nlohmann::json& resolved,
                                                         const std::vector<std::string>& tableQuantities);

// Whether the resolved params ask for samples (either count above zero).
[[nodiscard]] bool asksForClosureSamples(const nlohmann::json& resolved);

// The draw of a sample's resolved params (its `closure_draw`); nullopt for the nominal run.
[[nodiscard]] std::optional<ClosureDraw> closureDrawOf(const nlohmann::json& resolved);

// The tables a run reads: `nominal` with the tables of its draw's quantities drawn, or `nominal`
// itself for the nominal run. Throws grainbridge::Error when a drawn table has no standard errors.
[[nodiscard]] std::vector<core::LoadedClosureTable> sampleClosureTables(
    const nlohmann::json& resolved, const std::vector<core::LoadedClosureTable>& nominal);

// A sample's summary values (ClosureDraw::summary); nothing for the nominal run, whose summary
// stays that of a run without samples.
void addClosureSampleSummary(const nlohmann::json& resolved, nlohmann::json& summary);
// The same keys declared in a sample's planned output, so a downstream stage's checkAgainstUpstream
// sees which upstream plans are samples; nothing for the nominal run.
void addClosureSamplePlannedOutput(const nlohmann::json& resolved, PlannedOutput& out);

}  // namespace grainbridge::workflows::stages
