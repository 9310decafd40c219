// Stage keys (DESIGN.md): hash of type, impl_version, canonical resolved params and upstream
// keys. Equal content gives equal keys however it is written; any physics change, or an
// upstream change, gives a new key downstream.
#include <gtest/gtest.h>

#include <set>

#include "core/Error.hpp"
#include "core/json/StrictParse.hpp"
#include "tests/support/Cli.hpp"
#include "workflows/plan/Plan.hpp"
#include "workflows/stages/ClosureSamples.hpp"
#include "workflows/stages/MfmStage.hpp"
#include "workflows/stages/StageRegistry.hpp"

using namespace grainbridge::workflows;
using nlohmann::json;

namespace {
plan::Plan planOf(const std::string& text) {
  grainbridge::core::json::Diagnostics d;
  auto doc = grainbridge::core::json::parseStrict(text, d);
  EXPECT_TRUE(doc.has_value()) << d.format("t");
  return plan::makePlan(config::parseWorkflow(*doc, "t", stages::StageRegistry::builtin()));
}

const plan::StageInstance& only(const plan::Plan& p, const std::string& stage, std::size_t i = 0) {
  return p.instances.at(p.byStage.at(stage).at(i));
}

const char* kBase = R"({"name": "w", "stages": {
  "gas": {"type": "particle_gas", "params": {"n_particles": 100, "solid_fraction": 0.1, "diameter": "1 mm"}},
  "rep": {"type": "report", "from": "gas"}}})";
}  // namespace

TEST(Plan, SweepIsCartesianProductInGivenOrder) {
  auto p = planOf(R"({"name": "w", "stages": {
    "gas": {"type": "particle_gas", "params": {"n_particles": 10},
            "sweep": {"solid_fraction": [0.1, 0.2, 0.3], "seed": [1, 2]}},
    "rep": {"type": "report", "from": "gas"}}})");
  ASSERT_EQ(p.byStage.at("gas").size(), 6u);
  ASSERT_EQ(p.byStage.at("rep").size(), 1u);
  EXPECT_EQ(only(p, "rep").upstream.size(), 6u);
  std::set<std::string> keys;
  for (auto i : p.byStage.at("gas")) keys.insert(p.instances[i].key);
  EXPECT_EQ(keys.size(), 6u);
  EXPECT_EQ(only(p, "gas", 0).label(), "gas[seed=1, solid_fraction=0.1]");
}

// Logs and status name an instance by its sweep point as the config wrote it: a length in
// millimetres reads "1.3 mm", not its metres with binary noise (0.0013000000000000002).
TEST(Plan, LabelShowsTheSweepAsWritten) {
  auto p = planOf(R"({"name": "w", "stages": {
    "gas": {"type": "particle_gas", "params": {"n_particles": 10, "solid_fraction": 0.1},
            "sweep": {"diameter": ["1.3 mm", 0.0021]}}}})");
  ASSERT_EQ(p.byStage.at("gas").size(), 2u);
  EXPECT_EQ(only(p, "gas", 0).sweepPoint["diameter"].get<double>(), 1.3 * 1e-3);
  EXPECT_EQ(only(p, "gas", 0).label(), "gas[diameter=1.3 mm]");
  EXPECT_EQ(only(p, "gas", 1).label(), "gas[diameter=0.0021]");
}

TEST(Plan, KeyIgnoresKeyOrderUnitSpellingAndNonResultParams) {
  const auto a = planOf(kBase);
  const auto b = planOf(R"({"stages": {
    "rep": {"from": ["gas"], "type": "report", "params": {"title": "x"}},
    "gas": {"params": {"diameter": 0.001, "solid_fraction": 0.1, "progress": false, "n_particles": 100, "seed": 1},
            "type": "particle_gas"}}, "name": "w"})");
  EXPECT_EQ(only(a, "gas").key, only(b, "gas").key);
  EXPECT_EQ(only(a, "rep").key, only(b, "rep").key);
}

TEST(Plan, PhysicsChangeChangesKeyAndEveryDownstreamKey) {
  const auto a = planOf(kBase);
  std::string changed = kBase;
  changed.replace(changed.find("0.1"), 3, "0.2");
  const auto b = planOf(changed);
  EXPECT_NE(only(a, "gas").key, only(b, "gas").key);
  EXPECT_NE(only(a, "rep").key, only(b, "rep").key);
}

TEST(Plan, KeyMaterialHasNoPathsHostsOrVersions) {
  const auto p = planOf(kBase);
  const auto& gas = only(p, "gas");
  const json m = plan::keyMaterial(*gas.type, gas.params, {});
  EXPECT_EQ(m.size(), 4u);
  for (const char* k : {"type", "impl_version", "params", "upstream"}) EXPECT_TRUE(m.contains(k)) << k;
  EXPECT_EQ(plan::stageKey(m), gas.key);
  EXPECT_EQ(gas.key.size(), 64u);
}

TEST(Plan, SweepIntoNestedParametersByPath) {
  // Wall friction of the Brazil-nut container is a field of one wall: swept as "walls/0/mu".
  auto p = planOf(R"({"name": "w", "stages": {"bed": {"type": "dem", "params": {
    "box_lo": [0, 0, 0], "box_hi": [0.02, 0.02, 0.02], "dt": 1e-6, "duration": 1e-5,
    "species": [{"name": "s", "diameter": 0.001, "density": 2500, "count": 5}],
    "contact": {"kn": 2000, "restitution": 0.9},
    "walls": [{"kind": "plane", "point": [0, 0, 0], "direction": [0, 0, 1], "kn": 2000, "restitution": 0.9}]},
    "sweep": {"walls/0/mu": [0, 0.5]}}}})");
  ASSERT_EQ(p.byStage.at("bed").size(), 2u);
  EXPECT_EQ(only(p, "bed", 0).params["walls"][0]["mu"].get<double>(), 0.0);
  EXPECT_EQ(only(p, "bed", 1).params["walls"][0]["mu"].get<double>(), 0.5);
  EXPECT_NE(only(p, "bed", 0).key, only(p, "bed", 1).key);
  EXPECT_EQ(only(p, "bed", 1).label(), "bed[walls/0/mu=0.5]");
}

namespace {

// The grain-fluidization smoke bed on a closure table "t" the database holds (`hasErrors`: with
// each node's standard error), asking for closure samples.
// `inflows`: swept over the first boundary's gas inflow (as written) when not empty.
json sampledBedStage(int samples, int perQuantity, int seed, const std::string& closure = "table",
                     const std::vector<std::string>& inflows = {}) {
  json wf = json::parse(
      grainbridge::testing::readText(grainbridge::testing::sourceDir() / "configs/grain-fluidization-smoke.json"));
  json bed = wf["stages"]["bed"];
  bed.erase("sweep");
  if (!inflows.empty()) bed["sweep"] = {{"boundaries/0/gas_inflow", inflows}};
  auto& p = bed["params"];
  p.erase("kinetic_model");
  p.erase("granular_energy");
  p["boundaries"][0]["gas_inflow"] = "0.5 m/s";
  p["closure"] = closure;
  p["closure_table"] = "t";
  p["out_of_range"] = "kinetic_theory";
  p["table_quantities"] = {"pressure", "dissipation"};
  if (samples >= 0) p["closure_samples"] = samples;
  if (perQuantity >= 0) p["closure_samples_per_quantity"] = perQuantity;
  if (seed >= 0) p["sample_seed"] = seed;
  return bed;
}

plan::Plan planWithTables(const json& stagesObject, bool hasErrors) {
  const json doc = {{"name", "w"}, {"stages", stagesObject}};
  const auto config = config::parseWorkflow(doc, "t.json", stages::StageRegistry::builtin());
  return plan::makePlan(config, [hasErrors](const std::string&, const std::string& quantity) {
    return plan::TableFound{"sha-of-" + quantity, std::nullopt, hasErrors};
  });
}

plan::Plan sampledBedPlan(int samples, int perQuantity, int seed, bool hasErrors,
                          const std::string& closure = "table") {
  return planWithTables({{"bed", sampledBedStage(samples, perQuantity, seed, closure)}}, hasErrors);
}

// Records the upstream plans the config loader hands to checkAgainstUpstream.
class UpstreamProbe final : public stages::StageType {
 public:
  explicit UpstreamProbe(std::vector<stages::UpstreamPlan>& seen) : seen_(seen) {}
  [[nodiscard]] std::string name() const override { return "probe"; }
  [[nodiscard]] int implVersion() const override { return 1; }
  [[nodiscard]] std::string summary() const override { return "test-only"; }
  [[nodiscard]] const params::ParamSchema& params() const override { return schema_; }
  [[nodiscard]] stages::InputMode inputMode() const override { return stages::InputMode::Gather; }
  void checkAgainstUpstream(const json& /*resolved*/, const std::string& /*pointer*/,
                            const std::vector<stages::UpstreamPlan>& upstream,
                            grainbridge::core::json::Diagnostics& /*diagnostics*/) const override {
    seen_ = upstream;
  }
  void run(stages::StageContext& /*ctx*/) const override {}

 private:
  params::ParamSchema schema_;
  std::vector<stages::UpstreamPlan>& seen_;
};

}  // namespace

// Issue 31: closure samples are replicas of the instance with their own keys; the nominal run
// keeps the key it has without samples, and the seed enters only the samples' keys.
TEST(Plan, ClosureSamplesAreKeyedReplicasAndTheNominalRunKeepsItsKey) {
  const auto without = sampledBedPlan(-1, -1, -1, true);
  ASSERT_EQ(without.instances.size(), 1u);
  const auto sampled = sampledBedPlan(3, 2, 5, true);
  // 1 nominal + 3 joint + 2 for each of the two table quantities.
  ASSERT_EQ(sampled.instances.size(), 8u);
  EXPECT_EQ(sampled.instances[0].key, without.instances[0].key);
  EXPECT_EQ(sampled.instances[0].label(), "bed");
  std::set<std::string> keys;
  std::map<std::string, int> perturbed;
  for (std::size_t i = 0; i < sampled.instances.size(); ++i) {
    const auto& inst = sampled.instances[i];
    keys.insert(inst.key);
    if (i == 0) continue;
    const json& draw = inst.params.at("closure_draw");
    EXPECT_EQ(draw.at("sample"), static_cast<int>(i));
    EXPECT_EQ(draw.at("seed"), 5);
    perturbed[draw.at("perturbed").get<std::string>()]++;
    if (draw.at("perturbed") == "all") {
      EXPECT_EQ(draw.at("quantities"), json::array({"p_theta", "j_theta"}));
      EXPECT_EQ(inst.label(), "bed[closure_sample=" + std::to_string(i) + "]");
    } else {
      EXPECT_EQ(draw.at("quantities"), json::array({draw.at("perturbed")}));
      EXPECT_EQ(inst.label(), "bed[closure_perturbed=" + draw.at("perturbed").get<std::string>() +
                                  ", closure_sample=" + std::to_string(i) + "]");
    }
  }
  EXPECT_EQ(keys.size(), 8u);
  EXPECT_EQ(perturbed, (std::map<std::string, int>{{"all", 3}, {"p_theta", 2}, {"j_theta", 2}}));
  // Another seed: the same nominal key, other sample keys.
  const auto reseeded = sampledBedPlan(3, 2, 6, true);
  EXPECT_EQ(reseeded.instances[0].key, without.instances[0].key);
  EXPECT_NE(reseeded.instances[1].key, sampled.instances[1].key);
}

// Issue 57: which sample a run is is written once, as the typed draw in its params (the key's
// material); the summary values a comparing stage reads by name are declared in the sample's
// planned output, which the config check hands on; and a sample's sweep point is its nominal
// run's, so nothing downstream strips a label off it to find that run.
TEST(Plan, AClosureSampleIsOneDrawInItsParamsDeclaredAsProductsAndKeepsItsNominalSweepPoint) {
  const std::vector<std::string> inflows{"20.7 cm/s", "41.4 cm/s"};
  const auto p = planWithTables({{"bed", sampledBedStage(2, 1, 5, "table", inflows)}}, true);
  // Per inflow: the nominal run, 2 joint samples, 1 per quantity (p_theta, j_theta).
  ASSERT_EQ(p.instances.size(), 2u * 5u);
  const plan::StageInstance* nominal = nullptr;
  int samplesSeen = 0;
  for (const auto& inst : p.instances) {
    const auto draw = stages::closureDrawOf(inst.params);
    const auto planned = inst.type->plannedOutput(inst.params);
    ASSERT_TRUE(planned.has_value());
    const stages::UpstreamPlan asUpstream{inst.stage, inst.sweepPoint, inst.sweepWritten, *planned};
    if (!draw) {
      nominal = &inst;
      EXPECT_FALSE(asUpstream.records(stages::kClosureSampleKey)) << inst.label();
      EXPECT_FALSE(asUpstream.records(stages::kClosurePerturbedKey)) << inst.label();
      continue;
    }
    ++samplesSeen;
    ASSERT_NE(nominal, nullptr) << "a sample before its nominal run: " << inst.label();
    EXPECT_EQ(inst.sweepPoint, nominal->sweepPoint) << inst.label();
    EXPECT_EQ(inst.sweepWritten, nominal->sweepWritten) << inst.label();
    EXPECT_FALSE(inst.sweepPoint.contains(stages::kClosureSampleKey)) << inst.label();
    // The draw round-trips through its JSON form, the one the key hashes.
    EXPECT_EQ(json(*draw), inst.params.at("closure_draw"));
    EXPECT_EQ(inst.params.at("closure_draw").get<stages::ClosureDraw>(), *draw);
    EXPECT_EQ(draw->seed, 5);
    EXPECT_TRUE(asUpstream.records(stages::kClosureSampleKey)) << inst.label();
    EXPECT_TRUE(asUpstream.records(stages::kClosurePerturbedKey)) << inst.label();
    // What the run records is the draw, read back by name.
    json summary = json::object();
    stages::addClosureSampleSummary(inst.params, summary);
    EXPECT_EQ(summary.at(stages::kClosureSampleKey), draw->sample);
    EXPECT_EQ(summary.at(stages::kClosurePerturbedKey), draw->perturbed);
    EXPECT_EQ(draw->quantities.size(), draw->perturbed == "all" ? 2u : 1u);
  }
  EXPECT_EQ(samplesSeen, 8);

  // The config check hands a downstream stage every planned instance, samples included, each
  // with its declared products and its nominal run's sweep point.
  std::vector<stages::UpstreamPlan> seen;
  std::vector<std::unique_ptr<stages::StageType>> types;
  types.push_back(std::make_unique<stages::MfmStage>());
  types.push_back(std::make_unique<UpstreamProbe>(seen));
  const stages::StageRegistry registry(std::move(types));
  const json doc = {
      {"name", "w"},
      {"stages",
       {{"bed", sampledBedStage(2, 1, 5, "table", inflows)}, {"probe", {{"type", "probe"}, {"from", "bed"}}}}}};
  (void)config::parseWorkflow(doc, "t.json", registry);
  ASSERT_EQ(seen.size(), p.instances.size());
  std::map<std::string, int> samplesAt;
  for (const auto& up : seen) {
    if (up.records(stages::kClosureSampleKey)) ++samplesAt[up.sweepPoint.dump()];
  }
  ASSERT_EQ(samplesAt.size(), 2u);
  for (const auto& [point, n] : samplesAt) EXPECT_EQ(n, 4) << point;
}

TEST(Plan, ClosureSamplesNeedATableClosureWithErrorsAndSayWhereAtCheck) {
  const auto messageOf = [](const std::function<void()>& plan) -> std::string {
    try {
      plan();
    } catch (const grainbridge::Error& e) {
      return e.what();
    }
    return "accepted";
  };
  const std::string noErrors = messageOf([] { sampledBedPlan(2, 0, 1, false); });
  EXPECT_NE(noErrors.find("/stages/bed/params/closure_samples"), std::string::npos) << noErrors;
  EXPECT_NE(noErrors.find("no standard errors"), std::string::npos) << noErrors;
  const std::string perQuantity = messageOf([] { sampledBedPlan(0, 2, 1, false); });
  EXPECT_NE(perQuantity.find("/stages/bed/params/closure_samples_per_quantity"), std::string::npos) << perQuantity;
  // A table without errors is fine for a run that draws nothing.
  EXPECT_EQ(messageOf([] { sampledBedPlan(0, 0, 1, false); }), "accepted");
  const std::string single = messageOf([] { sampledBedPlan(1, 1, 1, true); });
  EXPECT_NE(single.find("/stages/bed/params/closure_samples"), std::string::npos) << single;
  EXPECT_NE(single.find("one closure sample gives no spread"), std::string::npos) << single;
  EXPECT_EQ(messageOf([] { sampledBedPlan(1, 2, 1, true); }), "accepted");
  const std::string kinetic = messageOf([] { sampledBedPlan(2, 0, 1, true, "ktgf"); });
  EXPECT_NE(kinetic.find("/stages/bed/params/closure_samples"), std::string::npos) << kinetic;
  EXPECT_NE(kinetic.find("closure \"table\""), std::string::npos) << kinetic;
}
