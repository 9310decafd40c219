#include "db/ClosureStore.hpp"

#include <algorithm>

#include "core/Error.hpp"
#include "core/Sha256.hpp"
#include "db/BusyError.hpp"
#include "db/Database.hpp"
#include "db/Statement.hpp"

namespace grainbridge::db {

using nlohmann::json;

namespace {

void bindJson(Statement& st, int index, const json& value, const std::string& where) {
  if (value.is_null()) {
    st.bindNull(index);
  } else if (value.is_number_integer() || value.is_boolean()) {
    st.bind(index, value.is_boolean() ? static_cast<std::int64_t>(value.get<bool>()) : value.get<std::int64_t>());
  } else if (value.is_number()) {
    st.bind(index, value.get<double>());
  } else if (value.is_string()) {
    st.bind(index, value.get<std::string>());
  } else if (value.is_object() || value.is_array()) {
    st.bind(index, value.dump());  // extra_json and the like
  } else {
    throw Error(where + ": unsupported value " + value.dump());
  }
}

std::string joined(const std::vector<std::string>& names) {
  std::string out;
  for (const auto& n : names) out += (out.empty() ? "" : ", ") + n;
  return out;
}

}  // namespace

ClosureStore::ClosureStore(Database& db) : db_(db) {}

const std::vector<std::string>& ClosureStore::recordTables() {
  static const std::vector<std::string> tables = {"closure_points", "force_statistics", "structure_statistics",
                                                  "closure_tables", "rheology"};
  return tables;
}

std::vector<std::string> ClosureStore::columns(const std::string& table) {
  const auto& known = recordTables();
  if (std::find(known.begin(), known.end(), table) == known.end()) {
    throw Error("closure database: no table \"" + table + "\" (tables: " + joined(known) + ")");
  }
  std::vector<std::string> out;
  auto st = db_.prepare("SELECT name FROM pragma_table_info(?1) ORDER BY cid");
  st.bind(1, table);
  while (st.step()) out.push_back(st.columnText(0));
  return out;
}

void ClosureStore::insertRecords(std::int64_t runId, const json& records) {
  if (records.is_null()) return;
  if (!records.is_object())
    throw Error("closure database: records must be an object of tables, found " + records.dump());
  for (const auto& [table, rows] : records.items()) {
    const auto cols = columns(table);
    for (std::size_t r = 0; r < rows.size(); ++r) {
      const json& row = rows[r];
      const std::string where = "records/" + table + "/" + std::to_string(r);
      if (!row.is_object()) throw Error("closure database: " + where + " is not an object");
      if (table == "closure_tables") {
        insertClosureTable(runId, row, where);
        continue;
      }
      std::vector<std::string> names = {"run_id"};
      for (const auto& [column, value] : row.items()) {
        if (column == "id" || column == "run_id" || std::find(cols.begin(), cols.end(), column) == cols.end()) {
          throw Error("closure database: " + where + ": no column \"" + column + "\" in " + table);
        }
        names.push_back(column);
      }
      std::string sql = "INSERT INTO " + table + "(" + joined(names) + ") VALUES(";
      for (std::size_t k = 0; k < names.size(); ++k) sql += (k ? ",?" : "?") + std::to_string(k + 1);
      sql += ")";
      auto st = db_.prepare(sql);
      st.bind(1, runId);
      int index = 2;
      for (const auto& [column, value] : row.items()) bindJson(st, index++, value, where + "/" + column);
      try {
        st.step();
      } catch (const BusyError&) {
        throw;  // the transaction's retry handles a locked database
      } catch (const Error& e) {
        // A CHECK or NOT NULL constraint: say which row broke it.
        throw Error("closure database: " + where + ": " + e.what());
      }
    }
  }
}

void ClosureStore::insertClosureTable(std::int64_t runId, const json& row, const std::string& where) {
  // Validate by building the table: a malformed grid fails here, not when an engine loads it.
  try {
    const auto second = row.value("seconds", json::array()).get<std::vector<double>>();
    core::ClosureTable check(
        row.at("quantity").get<std::string>(), row.at("solid_fractions").get<std::vector<double>>(),
        row.value("second_variable", std::string()), second, row.value("third_variable", std::string()),
        row.value("thirds", json::array()).get<std::vector<double>>(), row.at("values").get<std::vector<double>>());
    (void)check;
  } catch (const json::exception& e) {
    throw Error("closure database: " + where + ": " + e.what());
  }
  auto st = db_.prepare(
      "INSERT INTO closure_tables(run_id, name, quantity, second_variable, solid_fractions_json, seconds_json, "
      "values_json, uncertainties_json, filters_json, correlations_json, third_variable, thirds_json) "
      "VALUES(?1,?2,?3,?4,?5,?6,?7,?8,?9,?10,?11,?12)");
  st.bind(1, runId)
      .bind(2, row.at("name").get<std::string>())
      .bind(3, row.at("quantity").get<std::string>())
      .bind(4, row.value("second_variable", std::string()))
      .bind(5, row.at("solid_fractions").dump())
      .bind(6, row.value("seconds", json::array()).dump())
      .bind(7, row.at("values").dump())
      .bind(8, row.value("uncertainties", json::array()).dump())
      .bind(9, row.value("filters", json::object()).dump())
      .bind(10, row.value("correlations", json::object()).dump())
      .bind(11, row.value("third_variable", std::string()))
      .bind(12, row.value("thirds", json::array()).dump());
  st.step();
}

json ClosureStore::query(const ClosureQuery& q) {
  const auto cols = columns(q.table);
  std::string sql = "SELECT t.*, r.workflow AS workflow, r.stage AS stage, r.key AS run_key FROM " + q.table +
                    " t JOIN runs r ON r.id = t.run_id WHERE 1";
  std::vector<json> args;
  if (!q.family.empty()) {
    sql += " AND t.family = ?" + std::to_string(args.size() + 1);
    args.emplace_back(q.family);
  }
  if (!q.workflow.empty()) {
    sql += " AND r.workflow = ?" + std::to_string(args.size() + 1);
    args.emplace_back(q.workflow);
  }
  if (q.runId) {
    sql += " AND t.run_id = ?" + std::to_string(args.size() + 1);
    args.emplace_back(*q.runId);
  }
  for (const auto& range : q.ranges) {
    if (std::find(cols.begin(), cols.end(), range.column) == cols.end()) {
      throw Error("closure database: no column \"" + range.column + "\" in " + q.table + " (columns: " + joined(cols) +
                  ")");
    }
    // Column names come from the schema (checked above), values are bound.
    if (range.text) {
      // Text against a numeric column would match nothing: say so instead.
      auto type = db_.prepare("SELECT type FROM pragma_table_info(?1) WHERE name = ?2");
      type.bind(1, q.table).bind(2, range.column);
      if (type.step() && type.columnText(0) != "TEXT") {
        throw Error("closure database: \"" + *range.text + "\" is not a number, and " + q.table + "." + range.column +
                    " is a number column");
      }
      sql += " AND t." + range.column + " = ?" + std::to_string(args.size() + 1);
      args.emplace_back(*range.text);
    }
    if (range.lo) {
      sql += " AND t." + range.column + " >= ?" + std::to_string(args.size() + 1);
      args.emplace_back(*range.lo);
    }
    if (range.hi) {
      sql += " AND t." + range.column + " <= ?" + std::to_string(args.size() + 1);
      args.emplace_back(*range.hi);
    }
  }
  sql += " ORDER BY t.id";
  auto st = db_.prepare(sql);
  for (std::size_t k = 0; k < args.size(); ++k) bindJson(st, static_cast<int>(k + 1), args[k], "query");
  json out = json::array();
  while (st.step()) {
    json row = json::object();
    for (int c = 0; c < st.columnCount(); ++c) row[st.columnName(c)] = st.columnJson(c);
    out.push_back(std::move(row));
  }
  return out;
}

const std::vector<std::string>& ClosureStore::tableNodeColumns() {
  static const std::vector<std::string> columns = {
      "table_id", "run_id", "name",        "quantity", "second_variable", "solid_fraction", "second",
      "third_variable", "third", "value", "uncertainty", "workflow", "stage", "run_key"};
  return columns;
}

json ClosureStore::tableNodes(const ClosureQuery& query) {
  auto st = db_.prepare(
      "SELECT t.id, t.run_id, t.name, t.quantity, t.second_variable, t.solid_fractions_json, t.seconds_json, "
      "t.values_json, t.uncertainties_json, r.workflow, r.stage, r.key, t.third_variable, t.thirds_json "
      "FROM closure_tables t JOIN runs r ON r.id = t.run_id WHERE (?1 = '' OR r.workflow = ?1) AND (?2 = 0 OR t.run_id = ?2) "
      "ORDER BY t.id");
  st.bind(1, query.workflow).bind(2, query.runId.value_or(0));
  const auto& known = tableNodeColumns();
  for (const auto& range : query.ranges) {
    if (std::find(known.begin(), known.end(), range.column) == known.end()) {
      throw Error("closure database: no column \"" + range.column + "\" in closure table nodes (columns: " +
                  joined(known) + ")");
    }
  }
  json out = json::array();
  while (st.step()) {
    const auto fractions = json::parse(st.columnText(5)).get<std::vector<double>>();
    const auto seconds = json::parse(st.columnText(6)).get<std::vector<double>>();
    const auto values = json::parse(st.columnText(7)).get<std::vector<double>>();
    const auto errors = json::parse(st.columnText(8)).get<std::vector<double>>();
    const auto thirds = json::parse(st.columnText(13)).get<std::vector<double>>();
    // values[(iz * seconds + iy) * fractions + ix]
    const std::size_t perThird = fractions.size() * std::max<std::size_t>(1, seconds.size());
    for (std::size_t k = 0; k < values.size(); ++k) {
      json row = {{"table_id", st.columnInt64(0)},
                  {"run_id", st.columnInt64(1)},
                  {"name", st.columnText(2)},
                  {"quantity", st.columnText(3)},
                  {"second_variable", st.columnText(4)},
                  {"solid_fraction", fractions.at(k % fractions.size())},
                  {"second", seconds.empty() ? json() : json(seconds.at((k % perThird) / fractions.size()))},
                  {"third_variable", st.columnText(12)},
                  {"third", thirds.empty() ? json() : json(thirds.at(k / perThird))},
                  {"value", values[k]},
                  {"uncertainty", k < errors.size() ? json(errors[k]) : json()},
                  {"workflow", st.columnText(9)},
                  {"stage", st.columnText(10)},
                  {"run_key", st.columnText(11)}};
      const bool inside = std::all_of(query.ranges.begin(), query.ranges.end(), [&](const ColumnRange& r) {
        const json& v = row.at(r.column);
        if (!v.is_number()) return false;
        const double x = v.get<double>();
        return (!r.lo || x >= *r.lo) && (!r.hi || x <= *r.hi);
      });
      if (inside) out.push_back(std::move(row));
    }
  }
  return out;
}

core::LoadedClosureTable ClosureStore::loadTable(const std::string& name, const std::string& quantity,
                                                const std::string& runKey) {
  auto st = db_.prepare(
      "SELECT t.solid_fractions_json, t.second_variable, t.seconds_json, t.values_json, t.filters_json, r.key, "
      "t.uncertainties_json, t.correlations_json, t.third_variable, t.thirds_json "
      "FROM closure_tables t JOIN runs r ON r.id = t.run_id "
      "WHERE t.name = ?1 AND t.quantity = ?2 AND (?3 = '' OR r.key = ?3) ORDER BY t.run_id DESC, t.id DESC LIMIT 1");
  st.bind(1, name).bind(2, quantity).bind(3, runKey);
  if (!st.step()) {
    std::string known;
    auto all = db_.prepare("SELECT DISTINCT name || '/' || quantity FROM closure_tables ORDER BY 1");
    while (all.step()) known += (known.empty() ? "" : ", ") + all.columnText(0);
    throw Error("closure database " + db_.path().string() + ": no closure table \"" + name + "\" of quantity \"" +
                quantity + "\"" + (runKey.empty() ? "" : " from run " + runKey.substr(0, 12)) +
                " (tables: " + (known.empty() ? "none" : known) + ")");
  }
  core::ClosureTable table(quantity, json::parse(st.columnText(0)).get<std::vector<double>>(), st.columnText(1),
                           json::parse(st.columnText(2)).get<std::vector<double>>(), st.columnText(8),
                           json::parse(st.columnText(9)).get<std::vector<double>>(),
                           json::parse(st.columnText(3)).get<std::vector<double>>());
  std::string sha256 = core::contentSha256(table);
  return core::LoadedClosureTable{name,
                                  st.columnText(5),
                                  std::move(sha256),
                                  json::parse(st.columnText(4)).value("friction", 0.0),
                                  std::move(table),
                                  json::parse(st.columnText(6)).get<std::vector<double>>(),
                                  json::parse(st.columnText(7)).get<std::map<std::string, std::vector<double>>>()};
}

core::LoadedRheology ClosureStore::loadRheology(const std::string& name, const std::string& runKey) {
  auto newest = db_.prepare(
      "SELECT r.key FROM rheology h JOIN runs r ON r.id = h.run_id "
      "WHERE h.name = ?1 AND h.relation = 'mu_of_I' AND h.form = ?3 AND (?2 = '' OR r.key = ?2) "
      "ORDER BY h.run_id DESC LIMIT 1");
  newest.bind(1, name).bind(2, runKey).bind(3, std::string(core::kMuOfIJopForm));
  if (!newest.step()) {
    std::string known;
    auto all = db_.prepare("SELECT DISTINCT name FROM rheology WHERE relation = 'mu_of_I' ORDER BY 1");
    while (all.step()) known += (known.empty() ? "" : ", ") + all.columnText(0);
    throw Error("closure database " + db_.path().string() + ": no mu(I) rheology \"" + name + "\"" +
                (runKey.empty() ? "" : " from run " + runKey.substr(0, 12)) +
                " (rheologies: " + (known.empty() ? "none" : known) + ")");
  }
  core::LoadedRheology out;
  out.name = name;
  out.runKey = newest.columnText(0);
  auto st = db_.prepare(
      "SELECT h.restitution, h.diameter, h.density, h.inertial_numbers_json, h.values_json, h.mu_s, h.mu_2, "
      "h.inertial_number_0 FROM rheology h JOIN runs r ON r.id = h.run_id "
      "WHERE h.name = ?1 AND h.relation = 'mu_of_I' AND h.form = ?3 AND r.key = ?2 ORDER BY h.restitution, h.id");
  st.bind(1, name).bind(2, out.runKey).bind(3, std::string(core::kMuOfIJopForm));
  while (st.step()) {
    core::LoadedRheology::Row row;
    if (!st.columnIsNull(0)) row.restitution = st.columnDouble(0);
    out.diameter = st.columnDouble(1);
    out.density = st.columnDouble(2);
    row.inertialNumbers = json::parse(st.columnText(3)).get<std::vector<double>>();
    row.stressRatios = json::parse(st.columnText(4)).get<std::vector<double>>();
    if (!st.columnIsNull(5)) row.fit = core::LoadedRheology::Fit{st.columnDouble(5), st.columnDouble(6), st.columnDouble(7)};
    out.rows.push_back(std::move(row));
  }
  out.sha256 = core::contentSha256(out);
  return out;
}

}  // namespace grainbridge::db
