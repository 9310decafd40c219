#include "workflows/stages/ClosureSamples.hpp"

#include <algorithm>

#include "core/ClosureTableDraw.hpp"
#include "core/Error.hpp"

namespace grainbridge::workflows::stages {

using nlohmann::json;
using params::ParamSpec;

namespace {

constexpr const char* kOverlayKey = "closure_draw";

}  // namespace

std::uint64_t ClosureDraw::stream() const {
  return (static_cast<std::uint64_t>(seed) << 32) | static_cast<std::uint64_t>(sample);
}

bool ClosureDraw::draws(const std::string& quantity) const {
  return std::find(quantities.begin(), quantities.end(), quantity) != quantities.end();
}

json ClosureDraw::summary() const { return {{kClosureSampleKey, sample}, {kClosurePerturbedKey, perturbed}}; }

void to_json(json& j, const ClosureDraw& d) {
  j = {{"sample", d.sample}, {"seed", d.seed}, {"quantities", d.quantities}, {"perturbed", d.perturbed}};
}

void from_json(const json& j, ClosureDraw& d) {
  d.sample = j.at("sample").get<int>();
  d.seed = j.at("seed").get<std::int64_t>();
  d.quantities = j.at("quantities").get<std::vector<std::string>>();
  d.perturbed = j.at("perturbed").get<std::string>();
}

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
  const auto add = [&](std::vector<std::string> drawn, const std::string& perturbed) {
    const ClosureDraw draw{static_cast<int>(replicas.size()), seed, std::move(drawn), perturbed};
    Replica r;
    r.overlay[kOverlayKey] = draw;
    // For logs and status only ("bed[closure_sample=3]"); a joint sample's "all" goes unsaid.
    r.shown[kClosureSampleKey] = draw.sample;
    if (draw.perturbed != "all") r.shown[kClosurePerturbedKey] = draw.perturbed;
    replicas.push_back(std::move(r));
  };
  for (int s = 0; s < joint; ++s) add(quantities, "all");
  for (const auto& q : quantities) {
    for (int s = 0; s < each; ++s) add({q}, q);
  }
  return replicas;
}

std::optional<ClosureDraw> closureDrawOf(const json& p) {
  const auto it = p.find(kOverlayKey);
  if (it == p.end()) return std::nullopt;
  return it->get<ClosureDraw>();
}

std::vector<core::LoadedClosureTable> sampleClosureTables(const json& p,
                                                          const std::vector<core::LoadedClosureTable>& nominal) {
  const auto draw = closureDrawOf(p);
  if (!draw) return nominal;
  std::vector<core::LoadedClosureTable> drawn = nominal;
  std::vector<core::LoadedClosureTable*> toDraw;
  std::vector<core::TableToDraw> tables;
  for (auto& loaded : drawn) {
    if (!draw->draws(loaded.quantity())) continue;
    if (loaded.uncertainties.empty()) {
      throw Error("closure table \"" + loaded.name + "\" (" + loaded.quantity() +
                  ") has no standard errors to draw closure sample " + std::to_string(draw->sample) + " within");
    }
    toDraw.push_back(&loaded);
  }
  for (const auto* loaded : toDraw) tables.push_back({&loaded->table, loaded->uncertainties, &loaded->correlations});
  // A joint sample draws a node's quantities together, correlated as their closure point's were;
  // without recorded correlations each table has its own stream (seed, quantity), as before.
  auto realised = core::drawClosureTablesJointly(tables, draw->stream());
  for (std::size_t i = 0; i < toDraw.size(); ++i) toDraw[i]->table = std::move(realised[i]);
  return drawn;
}

void addClosureSampleSummary(const json& p, json& summary) {
  if (const auto draw = closureDrawOf(p)) summary.update(draw->summary());
}

void addClosureSamplePlannedOutput(const json& p, PlannedOutput& out) {
  if (!closureDrawOf(p)) return;
  out.summaryKeys.emplace_back(kClosureSampleKey);
  out.summaryKeys.emplace_back(kClosurePerturbedKey);
}

}  // namespace grainbridge::workflows::stages
