#include "core/LoadedClosureTable.hpp"

#include <nlohmann/json.hpp>

#include "core/Error.hpp"
#include "core/Sha256.hpp"

namespace grainbridge::core {

using nlohmann::json;

namespace {

json contentJson(const ClosureTable& table) {
  // Key order is nlohmann's (sorted), so the hash does not depend on how a record was built.
  json j = {{"quantity", table.quantity()},
            {"second_variable", table.secondVariable()},
            {"solid_fractions", table.solidFractions()},
            {"seconds", table.seconds()},
            {"values", table.values()}};
  // Only with a third axis: a table without one keeps the hash it always had.
  if (table.threeDimensional()) {
    j["third_variable"] = table.thirdVariable();
    j["thirds"] = table.thirds();
  }
  return j;
}

}  // namespace

std::string contentSha256(const ClosureTable& table) { return sha256Hex(contentJson(table).dump()); }

void to_json(json& j, const LoadedClosureTable& t) {
  j = contentJson(t.table);
  j["name"] = t.name;
  j["run_key"] = t.runKey;
  j["sha256"] = t.sha256;
  j["filters"] = {{"friction", t.friction}};
  j["uncertainties"] = t.uncertainties;
  j["correlations"] = t.correlations;
}

LoadedClosureTable loadedClosureTableFromJson(const json& j) {
  try {
    return LoadedClosureTable{
        j.at("name").get<std::string>(),
        j.at("run_key").get<std::string>(),
        j.at("sha256").get<std::string>(),
        j.at("filters").value("friction", 0.0),
        ClosureTable(j.at("quantity").get<std::string>(), j.at("solid_fractions").get<std::vector<double>>(),
                     j.at("second_variable").get<std::string>(), j.at("seconds").get<std::vector<double>>(),
                     j.value("third_variable", std::string()), j.value("thirds", std::vector<double>{}),
                     j.at("values").get<std::vector<double>>()),
        j.value("uncertainties", std::vector<double>{}),
        j.value("correlations", std::map<std::string, std::vector<double>>{})};
  } catch (const json::exception& e) {
    throw Error(std::string("closure table record: ") + e.what());
  }
}

}  // namespace grainbridge::core
