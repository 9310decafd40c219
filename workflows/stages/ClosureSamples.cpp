#include "workflows/stages/ClosureSamples.hpp"

#include <algorithm>
#include <cstdint>

#include "core/ClosureTableDraw.hpp"
#include "core/Error.hpp"

namespace grainbridge::workflows::stages {

using nlohmann::json;
using params::ParamSpec;

void addClosureSampleParams(params::ParamSchema& schema) {
  schema
      .add(ParamSpec::integer("closure_samples")
               .defaultValue(0)
               .min(0)
               .doesNotAffectResults()
               .doc("closure \"table\": runs on N joint realisations of the tables within their standard errors, "
                    "besides the nominal run (each a keyed instance; bed_compare gives the spread)"))
      .add(ParamSpec::integer("closure_samples_per_quantity")
               .defaultValue(0)
               .min(0)
               .doesNotAffectResults()
               .doc("closure \"table\": runs on M realisations of each table quantity alone, the others nominal "
                    "(which quantity the spread comes from)"))
      .add(ParamSpec::integer("sample_seed")
               .defaultValue(1)
               .min(0)
               .max(2147483647)  // the stream's upper 32 bits; the sample number is the lower
               .doesNotAffectResults()
               .doc("seed of the closure samples' draws (sample k draws from the stream of (sample_seed, k))"));
}

bool asksForClosureSamples(const json& p) {
  return p.value("closure_samples", 0) > 0 || p.value("closure_samples_per_quantity", 0) > 0;
}

std::vector<Replica> closureSampleReplicas(const json& p, const std::vector<std::string>& quantities) {
  std::vector<Replica> replicas{Replica{}};
  const int joint = p.value("closure_samples", 0);
  const int each = p.value("closure_samples_per_quantity", 0);
  const std::int64_t seed = p.value("sample_seed", std::int64_t{1});
  int k = 0;
  const auto add = [&](const json& drawn, const std::string& perturbed) {
    ++k;
    Replica r;
    r.overlay["closure_draw"] = {
        {"sample", k}, {"seed", seed}, {"quantities", drawn}, {"perturbed", perturbed.empty() ? "all" : perturbed}};
    r.label["closure_sample"] = k;
    if (!perturbed.empty()) r.label["closure_perturbed"] = perturbed;
    replicas.push_back(std::move(r));
  };
  for (int s = 0; s < joint; ++s) add(quantities, "");
  for (const auto& q : quantities) {
    for (int s = 0; s < each; ++s) add(json::array({q}), q);
  }
  return replicas;
}

std::vector<core::LoadedClosureTable> sampleClosureTables(const json& p,
                                                          const std::vector<core::LoadedClosureTable>& nominal) {
  if (!p.contains("closure_draw")) return nominal;
  const json& draw = p.at("closure_draw");
  // Sample k of seed s draws from the stream of (s, k); core::drawClosureTable adds the quantity.
  const std::uint64_t stream = (static_cast<std::uint64_t>(draw.at("seed").get<std::int64_t>()) << 32) |
                               static_cast<std::uint64_t>(draw.at("sample").get<std::int64_t>());
  const auto& quantities = draw.at("quantities");
  std::vector<core::LoadedClosureTable> drawn = nominal;
  for (auto& loaded : drawn) {
    if (std::find(quantities.begin(), quantities.end(), loaded.quantity()) == quantities.end()) continue;
    if (loaded.uncertainties.empty()) {
      throw Error("closure table \"" + loaded.name + "\" (" + loaded.quantity() +
                  ") has no standard errors to draw closure sample " + std::to_string(draw.at("sample").get<int>()) +
                  " within");
    }
    loaded.table = core::drawClosureTable(loaded.table, loaded.uncertainties, stream);
  }
  return drawn;
}

void addClosureSampleSummary(const json& p, json& summary) {
  if (!p.contains("closure_draw")) return;
  const json& draw = p.at("closure_draw");
  summary["closure_sample"] = draw.at("sample");
  summary["closure_perturbed"] = draw.at("perturbed");
}

}  // namespace grainbridge::workflows::stages
