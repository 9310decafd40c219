#include "core/LoadedRheology.hpp"

#include <cmath>
#include <nlohmann/json.hpp>

#include "core/Error.hpp"
#include "core/SameValue.hpp"
#include "core/Sha256.hpp"

namespace grainbridge::core {

using nlohmann::json;

namespace {

json contentJson(const LoadedRheology& r) {
  json rows = json::array();
  for (const auto& row : r.rows) {
    json j = {{"restitution", row.restitution ? json(*row.restitution) : json()},
              {"inertial_numbers", row.inertialNumbers},
              {"stress_ratios", row.stressRatios},
              {"fit", json()}};
    if (row.fit) {
      j["fit"] = {{"mu_s", row.fit->staticRatio},
                  {"mu_2", row.fit->limitRatio},
                  {"inertial_number_0", row.fit->inertialNumberScale}};
    }
    rows.push_back(std::move(j));
  }
  return {{"diameter", r.diameter}, {"density", r.density}, {"rows", std::move(rows)}};
}

}  // namespace

const LoadedRheology::Row* LoadedRheology::atRestitution(double e) const {
  for (const auto& row : rows) {
    if (row.restitution && sameValue(*row.restitution, e)) return &row;
  }
  return nullptr;
}

std::string contentSha256(const LoadedRheology& rheology) { return sha256Hex(contentJson(rheology).dump()); }

void to_json(json& j, const LoadedRheology& r) {
  j = contentJson(r);
  j["name"] = r.name;
  j["run_key"] = r.runKey;
  j["sha256"] = r.sha256;
}

LoadedRheology loadedRheologyFromJson(const json& j) {
  try {
    LoadedRheology r;
    r.name = j.at("name").get<std::string>();
    r.runKey = j.at("run_key").get<std::string>();
    r.sha256 = j.at("sha256").get<std::string>();
    r.diameter = j.at("diameter").get<double>();
    r.density = j.at("density").get<double>();
    for (const auto& row : j.at("rows")) {
      LoadedRheology::Row out;
      if (!row.at("restitution").is_null()) out.restitution = row.at("restitution").get<double>();
      out.inertialNumbers = row.at("inertial_numbers").get<std::vector<double>>();
      out.stressRatios = row.at("stress_ratios").get<std::vector<double>>();
      if (const auto& fit = row.at("fit"); !fit.is_null()) {
        out.fit = LoadedRheology::Fit{fit.at("mu_s").get<double>(), fit.at("mu_2").get<double>(),
                                      fit.at("inertial_number_0").get<double>()};
      }
      r.rows.push_back(std::move(out));
    }
    return r;
  } catch (const json::exception& e) {
    throw Error(std::string("rheology record: ") + e.what());
  }
}

}  // namespace grainbridge::core
