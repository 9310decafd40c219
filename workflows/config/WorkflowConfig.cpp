#include "workflows/config/WorkflowConfig.hpp"

#include <algorithm>
#include <functional>
#include <map>
#include <regex>
#include <set>

#include "core/json/StrictParse.hpp"
#include "core/units/Quantity.hpp"
#include "workflows/config/WrittenValue.hpp"

namespace grainbridge::workflows::config {

using nlohmann::json;
namespace cj = core::json;

const StageConfig* WorkflowConfig::findStage(const std::string& stageName) const {
  for (const auto& s : stages) {
    if (s.name == stageName) return &s;
  }
  return nullptr;
}

namespace {

std::vector<json> cartesianPoints(const std::vector<SweepAxis>& axes, std::vector<json> SweepAxis::*values) {
  std::vector<json> points{json::object()};
  for (const auto& axis : axes) {
    std::vector<json> next;
    for (const auto& p : points) {
      for (const auto& v : axis.*values) {
        json q = p;
        q[axis.param] = v;
        next.push_back(std::move(q));
      }
    }
    points = std::move(next);
  }
  return points;
}

}  // namespace

std::vector<json> sweepPoints(const std::vector<SweepAxis>& axes) { return cartesianPoints(axes, &SweepAxis::values); }

std::vector<json> sweepPointsAsWritten(const std::vector<SweepAxis>& axes) {
  return cartesianPoints(axes, &SweepAxis::written);
}

json withSweepPoint(json params, const json& point) {
  for (const auto& [k, v] : point.items()) params[json::json_pointer("/" + k)] = v;
  return params;
}

namespace {

std::string found(const json& v) { return cj::describeFound(v.dump(), v.type_name()); }

// Names become folder names (results/<workflow>/<stage>/...): keep them portable.
bool isSafeName(const std::string& s) {
  static const std::regex pattern("[A-Za-z0-9][A-Za-z0-9_.-]*");
  return s.size() <= 100 && std::regex_match(s, pattern);
}

void rejectUnknownKeys(const json& obj, const std::vector<std::string>& allowed, const std::string& pointer,
                       const std::string& what, cj::Diagnostics& d) {
  for (const auto& [key, value] : obj.items()) {
    if (std::find(allowed.begin(), allowed.end(), key) != allowed.end()) continue;
    std::string msg = "unknown key \"" + key + "\" in " + what;
    const auto hint = cj::closestMatch(key, allowed);
    if (!hint.empty())
      msg += " (did you mean \"" + hint + "\"?)";
    else {
      msg += " (allowed: ";
      for (std::size_t i = 0; i < allowed.size(); ++i) msg += (i ? ", " : "") + allowed[i];
      msg += ")";
    }
    d.add(pointer + "/" + cj::pointerToken(key), msg);
  }
}

core::units::UnitSystem parseUnits(const json& doc, cj::Diagnostics& d) {
  if (!doc.contains("units")) return core::units::UnitSystem::si();
  const json& u = doc["units"];
  if (!u.is_object()) {
    d.add("/units", "expected an object {\"system\": \"SI\" | \"reduced\", ...}, found " + found(u));
    return core::units::UnitSystem::si();
  }
  rejectUnknownKeys(u, {"system", "d0", "m0", "g"}, "/units", "units", d);
  if (!u.contains("system") || !u["system"].is_string()) {
    d.add("/units/system", "expected \"SI\" or \"reduced\", found " +
                               (u.contains("system") ? found(u["system"]) : std::string("nothing")));
    return core::units::UnitSystem::si();
  }
  const std::string system = u["system"].get<std::string>();
  using core::units::Dimension;
  if (system == "SI") {
    for (const char* k : {"d0", "m0", "g"}) {
      if (u.contains(k))
        d.add(std::string("/units/") + k, "only used with \"system\": \"reduced\"; remove it or switch the system");
    }
    return core::units::UnitSystem::si();
  }
  if (system != "reduced") {
    d.add("/units/system", "expected \"SI\" or \"reduced\", found \"" + system + "\"");
    return core::units::UnitSystem::si();
  }
  // Reduced units are defined by SI values of d0, m0 and g (Table 6.1's basis).
  double values[3] = {0, 0, 0};
  const char* keys[3] = {"d0", "m0", "g"};
  const Dimension dims[3] = {Dimension::lengthDim(), Dimension::massDim(), Dimension::acceleration()};
  bool ok = true;
  for (int i = 0; i < 3; ++i) {
    const std::string where = std::string("/units/") + keys[i];
    if (!u.contains(keys[i])) {
      d.add("/units", std::string("reduced units need \"") + keys[i] + "\" (an SI value or a string with a unit)");
      ok = false;
      continue;
    }
    auto r = core::units::parseQuantity(u[keys[i]], dims[i], core::units::UnitSystem::si());
    if (auto* err = std::get_if<std::string>(&r)) {
      d.add(where, *err);
      ok = false;
    } else if (std::get<double>(r) <= 0) {
      d.add(where, std::string("expected a positive ") + keys[i] + ", found " + u[keys[i]].dump());
      ok = false;
    } else {
      values[i] = std::get<double>(r);
    }
  }
  if (!ok) return core::units::UnitSystem::si();
  return core::units::UnitSystem::reduced(values[0], values[1], values[2]);
}

std::vector<std::string> parseFrom(const json& stage, const std::string& pointer, cj::Diagnostics& d) {
  std::vector<std::string> from;
  if (!stage.contains("from")) return from;
  const json& f = stage["from"];
  if (f.is_string()) {
    from.push_back(f.get<std::string>());
  } else if (f.is_array()) {
    for (std::size_t i = 0; i < f.size(); ++i) {
      if (f[i].is_string())
        from.push_back(f[i].get<std::string>());
      else
        d.add(pointer + "/from/" + std::to_string(i), "expected a stage name, found " + found(f[i]));
    }
  } else {
    d.add(pointer + "/from", "expected a stage name or a list of stage names, found " + found(f));
  }
  return from;
}

// Orders stages so each comes after everything in its `from`; reports cycles with their path.
std::vector<std::size_t> topologicalOrder(const std::vector<StageConfig>& stages, cj::Diagnostics& d) {
  std::map<std::string, std::size_t> index;
  for (std::size_t i = 0; i < stages.size(); ++i) index[stages[i].name] = i;
  enum class Mark { None, Active, Done };
  std::vector<Mark> mark(stages.size(), Mark::None);
  std::vector<std::size_t> order;
  std::vector<std::size_t> path;
  std::set<std::string> reported;
  std::function<void(std::size_t)> visit = [&](std::size_t i) {
    if (mark[i] == Mark::Done) return;
    if (mark[i] == Mark::Active) {
      auto start = std::find(path.begin(), path.end(), i);
      std::string cycle;
      for (auto it = start; it != path.end(); ++it) cycle += stages[*it].name + " -> ";
      cycle += stages[i].name;
      if (reported.insert(stages[i].name).second) {
        d.add("/stages/" + cj::pointerToken(stages[i].name) + "/from", "stages form a cycle: " + cycle);
      }
      return;
    }
    mark[i] = Mark::Active;
    path.push_back(i);
    for (const auto& up : stages[i].from) {
      auto it = index.find(up);
      if (it != index.end()) visit(it->second);
    }
    path.pop_back();
    mark[i] = Mark::Done;
    order.push_back(i);
  };
  for (std::size_t i = 0; i < stages.size(); ++i) visit(i);
  return order;
}

// Says where a problem found at one sweep point is, the point included when there is one.
std::string atSweepPoint(const std::string& where, const json& point) {
  return point.empty() ? where : where + " (sweep point " + point.dump() + ")";
}

// The grains of a stage instance's products (PlannedOutput::grains): its own plan's, or else the
// grains every instance of every stage in its `from` agrees on, found the same way; none when a
// stage on the way did not pass its own checks or the upstreams differ.
std::optional<stages::Grains> plannedGrains(const WorkflowConfig& cfg, const StageConfig& sc, const json& point,
                                            const std::set<std::string>& cleanStages, int depth = 0) {
  if (sc.type == nullptr || cleanStages.count(sc.name) == 0 || depth > static_cast<int>(cfg.stages.size()))
    return std::nullopt;
  if (const auto planned = sc.type->plannedOutput(withSweepPoint(sc.params, point)); planned && planned->grains)
    return planned->grains;
  std::optional<stages::Grains> agreed;
  for (const auto& name : sc.from) {
    const StageConfig* up = cfg.findStage(name);
    if (up == nullptr) return std::nullopt;
    for (const auto& upPoint : sweepPoints(up->sweep)) {
      const auto g = plannedGrains(cfg, *up, upPoint, cleanStages, depth + 1);
      if (!g || (agreed && (agreed->diameter != g->diameter || agreed->density != g->density))) return std::nullopt;
      agreed = g;
    }
  }
  return agreed;
}

// Rules that span stages: each stage's requests against what its upstream instances will
// produce (PlannedOutput), for every sweep point on both sides and every replica of an upstream
// point (a closure sample declares what tells it apart). Only stages whose own params, and whose
// upstreams' params, passed their checks take part: a planned output is computed from valid
// params only. A problem shared by several points is reported once.
void checkAgainstUpstreams(const WorkflowConfig& cfg, const std::set<std::string>& cleanStages, cj::Diagnostics& d) {
  for (const auto& sc : cfg.stages) {
    if (sc.type == nullptr || sc.from.empty() || cleanStages.count(sc.name) == 0) continue;
    std::vector<stages::UpstreamPlan> upstream;
    bool upstreamClean = true;
    for (const auto& name : sc.from) {
      const StageConfig* up = cfg.findStage(name);
      if (up == nullptr || up->type == nullptr || cleanStages.count(name) == 0) {
        upstreamClean = false;
        continue;
      }
      const auto points = sweepPoints(up->sweep);
      const auto written = sweepPointsAsWritten(up->sweep);
      for (std::size_t k = 0; k < points.size(); ++k) {
        const json swept = withSweepPoint(up->params, points[k]);
        for (const auto& replica : up->type->replicas(swept)) {
          json params = swept;
          params.merge_patch(replica.overlay);
          // A type that promises nothing hands on an empty plan: a stage that needs a product
          // refuses it by name instead of failing after the upstream ran.
          auto planned = up->type->plannedOutput(params).value_or(stages::PlannedOutput{});
          if (!planned.grains) planned.grains = plannedGrains(cfg, *up, points[k], cleanStages);
          upstream.push_back({name, points[k], written[k], std::move(planned)});
        }
      }
    }
    if (!upstreamClean || upstream.empty()) continue;
    const std::string ptr = "/stages/" + cj::pointerToken(sc.name) + "/params";
    std::set<std::string> seen;
    for (const auto& point : sweepPoints(sc.sweep)) {
      cj::Diagnostics local;
      sc.type->checkAgainstUpstream(withSweepPoint(sc.params, point), ptr, upstream, local);
      for (const auto& item : local.items()) {
        if (seen.insert(item.where + item.message).second)
          d.add(atSweepPoint(item.where, point),
                item.message + writtenNote(cfg.document, item.where, item.message, cfg.units));
      }
    }
  }
}

}  // namespace

WorkflowConfig parseWorkflow(const json& doc, const std::string& sourceName, const stages::StageRegistry& registry) {
  cj::Diagnostics d;
  WorkflowConfig cfg;
  cfg.document = doc;
  if (!doc.is_object()) {
    d.add("", "expected a workflow object {\"name\": ..., \"stages\": {...}}, found " + found(doc));
    throw cj::InputError(sourceName, d);
  }
  rejectUnknownKeys(doc, {"name", "units", "database", "stages"}, "", "the workflow", d);

  if (!doc.contains("name"))
    d.add("", "missing required key \"name\" (the workflow's name; results go to results/<name>/)");
  else if (!doc["name"].is_string() || !isSafeName(doc["name"].get<std::string>()))
    d.add("/name",
          "expected a name of letters, digits, '_', '.', '-' (it names a folder), found " + found(doc["name"]));
  else
    cfg.name = doc["name"].get<std::string>();

  cfg.units = parseUnits(doc, d);

  if (doc.contains("database")) {
    if (!doc["database"].is_string() || doc["database"].get<std::string>().empty())
      d.add("/database", "expected a file path, found " + found(doc["database"]));
    else
      cfg.database = doc["database"].get<std::string>();
  } else if (!cfg.name.empty()) {
    cfg.database = std::filesystem::path("results") / cfg.name / "grainbridge.sqlite";
  }

  if (!doc.contains("stages")) {
    d.add("", "missing required key \"stages\" (an object of named stages)");
  } else if (!doc["stages"].is_object() || doc["stages"].empty()) {
    d.add("/stages", "expected a non-empty object of named stages, found " + found(doc["stages"]));
  } else {
    std::set<std::string> cleanStages;  // stages with no problem of their own
    for (const auto& [name, stage] : doc["stages"].items()) {
      const std::string ptr = "/stages/" + cj::pointerToken(name);
      const std::size_t problemsBefore = d.size();
      StageConfig sc;
      sc.name = name;
      if (!isSafeName(name))
        d.add(ptr, "stage name \"" + name + "\" must be letters, digits, '_', '.', '-' (it names a folder)");
      if (!stage.is_object()) {
        d.add(ptr, "expected a stage object {\"type\": ..., \"params\": {...}}, found " + found(stage));
        continue;
      }
      rejectUnknownKeys(stage, {"type", "params", "from", "sweep", "ranks_per_instance"}, ptr, "a stage", d);
      if (!stage.contains("type") || !stage["type"].is_string()) {
        d.add(
            ptr + "/type", "expected a stage type (one of: " + [&] {
              std::string s;
              for (const auto& n : registry.names()) s += (s.empty() ? "" : ", ") + n;
              return s;
            }() + "), found " + (stage.contains("type") ? found(stage["type"]) : std::string("nothing")));
      } else {
        const auto typeName = stage["type"].get<std::string>();
        sc.type = registry.find(typeName);
        if (sc.type == nullptr) {
          std::string msg = "unknown stage type \"" + typeName + "\"";
          const auto hint = cj::closestMatch(typeName, registry.names());
          msg += hint.empty() ? " (`grainbridge stages` lists them)" : " (did you mean \"" + hint + "\"?)";
          d.add(ptr + "/type", msg);
        }
      }
      sc.from = parseFrom(stage, ptr, d);
      if (stage.contains("ranks_per_instance")) {
        const json& r = stage["ranks_per_instance"];
        if (!r.is_number_integer() || r.get<std::int64_t>() < 1 || r.get<std::int64_t>() > 1000000)
          d.add(ptr + "/ranks_per_instance", "expected a positive integer, found " + found(r));
        else
          sc.ranksPerInstance = static_cast<int>(r.get<std::int64_t>());
      }
      std::set<std::string> swept;
      if (stage.contains("sweep")) {
        const json& s = stage["sweep"];
        if (!s.is_object() || s.empty()) {
          d.add(ptr + "/sweep", "expected a non-empty object {<param>: [values...]}, found " + found(s));
        } else {
          for (const auto& [param, values] : s.items()) {
            const std::string sp = ptr + "/sweep/" + cj::pointerToken(param);
            swept.insert(param);
            if (!values.is_array() || values.empty()) {
              d.add(sp, "expected a non-empty list of values to sweep over, found " + found(values));
              continue;
            }
            if (stage.contains("params") && stage["params"].is_object() && stage["params"].contains(param)) {
              d.add(sp, "\"" + param + "\" is given both in params and in sweep; keep one");
            }
            if (sc.type == nullptr) continue;
            std::string why;
            const auto* spec = sc.type->params().findPath(param, why);
            if (spec == nullptr) {
              d.add(sp, "cannot sweep \"" + param + "\" of stage type " + sc.type->name() + ": " + why);
              continue;
            }
            SweepAxis axis{param, {}, {}};
            for (std::size_t i = 0; i < values.size(); ++i) {
              if (auto v =
                      sc.type->params().resolveValue(*spec, values[i], cfg.units, sp + "/" + std::to_string(i), d)) {
                axis.values.push_back(*v);
                axis.written.push_back(values[i]);
              }
            }
            sc.sweep.push_back(std::move(axis));
          }
        }
      }
      if (sc.type != nullptr) {
        const json params = stage.contains("params") ? stage["params"] : json::object();
        sc.params = sc.type->params().resolve(params, swept, cfg.units, ptr + "/params", d);
        // A swept path into nested parameters must name an element that exists.
        for (const auto& axis : sc.sweep) {
          const auto slash = axis.param.rfind('/');
          if (slash != std::string::npos && d.size() == problemsBefore &&
              !sc.params.contains(json::json_pointer("/" + axis.param.substr(0, slash)))) {
            d.add(ptr + "/sweep/" + cj::pointerToken(axis.param),
                  "\"" + axis.param.substr(0, slash) + "\" does not exist in this stage's params");
          }
        }
        // Cross-parameter checks for every sweep point; a problem shared by several points is
        // reported once.
        if (d.size() == problemsBefore) {  // only on parameters that are individually valid
          const std::vector<json> points = sweepPoints(sc.sweep);
          std::set<std::string> seen;
          for (const auto& point : points) {
            const json merged = withSweepPoint(sc.params, point);
            cj::Diagnostics local;
            sc.type->params().checkRules(merged, ptr + "/params", local);
            sc.type->checkParams(merged, ptr + "/params", local);
            if (sc.ranksPerInstance > 1 && !sc.type->runsOnSeveralRanks(merged)) {
              local.add(ptr + "/ranks_per_instance",
                        "stage type " + sc.type->name() + " runs an instance on one rank" +
                            (sc.type->name() == "dem" ? " unless its engine is lammps" : "") + "; found " +
                            std::to_string(sc.ranksPerInstance));
            }
            for (const auto& item : local.items()) {
              if (seen.insert(item.where + item.message).second)
                d.add(atSweepPoint(item.where, point),
                      item.message + writtenNote(cfg.document, item.where, item.message, cfg.units));
            }
          }
        }
        if (!sc.from.empty() && sc.type->inputMode() == stages::InputMode::None) {
          d.add(ptr + "/from", "stage type " + sc.type->name() + " takes no upstream stages");
        }
      }
      if (d.size() == problemsBefore) cleanStages.insert(name);
      cfg.stages.push_back(std::move(sc));
    }
    // `from` must name other stages of this workflow.
    std::vector<std::string> names;
    for (const auto& s : cfg.stages) names.push_back(s.name);
    for (const auto& s : cfg.stages) {
      for (std::size_t i = 0; i < s.from.size(); ++i) {
        const std::string where = "/stages/" + cj::pointerToken(s.name) + "/from" +
                                  (doc["stages"][s.name]["from"].is_array() ? "/" + std::to_string(i) : "");
        if (s.from[i] == s.name) {
          d.add(where, "stage \"" + s.name + "\" cannot take its own output (a cycle of one stage)");
        } else if (std::find(names.begin(), names.end(), s.from[i]) == names.end()) {
          std::string msg = "no stage named \"" + s.from[i] + "\" in this workflow";
          const auto hint = cj::closestMatch(s.from[i], names);
          if (!hint.empty()) msg += " (did you mean \"" + hint + "\"?)";
          d.add(where, msg);
        }
      }
    }
    checkAgainstUpstreams(cfg, cleanStages, d);
    const auto order = topologicalOrder(cfg.stages, d);
    std::vector<StageConfig> sorted;
    for (auto i : order) sorted.push_back(std::move(cfg.stages[i]));
    cfg.stages = std::move(sorted);
  }
  if (!d.empty()) throw cj::InputError(sourceName, d);
  return cfg;
}

WorkflowConfig loadWorkflow(const std::filesystem::path& path, const stages::StageRegistry& registry) {
  cj::Diagnostics d;
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) {
    d.add("", "config file does not exist");
    throw cj::InputError(path.string(), d);
  }
  if (std::filesystem::is_directory(path, ec)) {
    d.add("", "is a directory, not a config file");
    throw cj::InputError(path.string(), d);
  }
  auto doc = cj::parseFileStrict(path.string(), d);
  if (!doc) throw cj::InputError(path.string(), d);
  WorkflowConfig cfg = parseWorkflow(*doc, path.string(), registry);
  cfg.sourcePath = path;
  return cfg;
}

}  // namespace grainbridge::workflows::config
