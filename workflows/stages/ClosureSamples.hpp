#pragma once
// Closure samples of a continuum run on DEM closure tables (issue 31): besides the nominal run,
// runs on realisations of the tables drawn within their standard errors (core/ClosureTableDraw),
// so that a comparing stage can say how much the DEM's statistical error moves the answer.
//
// `closure_samples` N asks for N joint samples (every table drawn) and
// `closure_samples_per_quantity` M for M one-at-a-time samples of each table quantity (that
// quantity drawn, the others nominal), which say which quantity the spread comes from. The
// planner makes each sample a replica of the instance (StageType::replicas) with its own key:
// the overlay `closure_draw` {"sample": k, "seed": sample_seed, "quantities": [...], "perturbed":
// "all" or the quantity} and the
// label {"closure_sample": k} (and "closure_perturbed": quantity, one at a time). Sample k's
// tables are drawn from the stream seeded by (sample_seed, k), so a sample is reproducible from
// its seed and independent of the others. The nominal run's key is that of the run without
// samples: the three parameters do not affect its results.
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "core/LoadedClosureTable.hpp"
#include "core/json/Diagnostics.hpp"
#include "workflows/params/ParamSchema.hpp"
#include "workflows/stages/StageType.hpp"

namespace grainbridge::workflows::stages {

// closure_samples, closure_samples_per_quantity, sample_seed.
void addClosureSampleParams(params::ParamSchema& schema);

// The nominal run and its samples; the nominal run alone without samples.
// `tableQuantities`: the quantities of the tables the run reads (p_theta, eta_theta, j_theta).
[[nodiscard]] std::vector<Replica> closureSampleReplicas(const nlohmann::json& resolved,
                                                         const std::vector<std::string>& tableQuantities);

// Whether the resolved params ask for samples (either count above zero).
[[nodiscard]] bool asksForClosureSamples(const nlohmann::json& resolved);

// The tables a sample runs on: `nominal` with the tables of its `closure_draw` quantities drawn;
// `nominal` itself for the nominal run. Throws grainbridge::Error when a drawn table has no
// standard errors.
[[nodiscard]] std::vector<core::LoadedClosureTable> sampleClosureTables(
    const nlohmann::json& resolved, const std::vector<core::LoadedClosureTable>& nominal);

// A sample's summary values: closure_sample (k) and closure_perturbed ("all" or the quantity);
// nothing for the nominal run, whose summary stays that of a run without samples.
void addClosureSampleSummary(const nlohmann::json& resolved, nlohmann::json& summary);

}  // namespace grainbridge::workflows::stages
