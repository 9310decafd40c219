// `grainbridge db query` and `db export`: the closure database as a user reads it, filtered by
// family, state ranges and run, printed as a table, CSV or JSON; and everything in it written
// out for other tools. Values are SI; each row names the run that produced it, and
// `db show RUN` follows that run's provenance chain.
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "core/Files.hpp"
#include "core/text/NumberText.hpp"
#include "db/ClosureStore.hpp"
#include "db/ProvenanceStore.hpp"
#include "workflows/commands/Commands.hpp"
#include "workflows/commands/DatabaseSource.hpp"
#include "workflows/report/CsvField.hpp"

namespace grainbridge::workflows::commands {

using nlohmann::json;

namespace {

// "solid_fraction=0.1:0.3", "restitution=0.9" (that value, to 1e-9 relative), "shear_rate=:5".
db::ColumnRange parseRange(const std::string& text) {
  const auto eq = text.find('=');
  if (eq == std::string::npos || eq == 0) {
    throw UsageError("--where \"" + text + "\": expected COLUMN=LO:HI, COLUMN=VALUE, COLUMN=LO: or COLUMN=:HI");
  }
  db::ColumnRange r;
  r.column = text.substr(0, eq);
  const std::string value = text.substr(eq + 1);
  auto number = [&](const std::string& s) -> std::optional<double> {
    if (s.empty()) return std::nullopt;
    std::size_t used = 0;
    double v = 0;
    try {
      v = std::stod(s, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used != s.size()) throw UsageError("--where \"" + text + "\": \"" + s + "\" is not a number");
    return v;
  };
  const auto colon = value.find(':');
  if (colon == std::string::npos) {
    const auto v = number(value);
    if (!v) throw UsageError("--where \"" + text + "\": no value");
    const double tol = 1e-9 * std::max(1.0, std::abs(*v));
    r.lo = *v - tol;
    r.hi = *v + tol;
  } else {
    r.lo = number(value.substr(0, colon));
    r.hi = number(value.substr(colon + 1));
  }
  return r;
}

// A table is for people (six significant digits); CSV and JSON keep every digit.
std::string cell(const json& v) {
  if (v.is_null()) return "";
  return core::humanText(v);
}

// Columns to show: the requested ones (checked), else every column that is set in some row.
std::vector<std::string> shownColumns(const json& rows, const std::string& requested,
                                      const std::vector<std::string>& known) {
  std::vector<std::string> out;
  if (!requested.empty()) {
    std::istringstream in(requested);
    for (std::string c; std::getline(in, c, ',');) {
      if (std::find(known.begin(), known.end(), c) == known.end()) {
        std::string list;
        for (const auto& k : known) list += (list.empty() ? "" : ", ") + k;
        throw UsageError("--columns: no column \"" + c + "\" (columns: " + list + ")");
      }
      out.push_back(c);
    }
    return out;
  }
  for (const auto& k : known) {
    for (const auto& row : rows) {
      if (row.contains(k) && !row[k].is_null()) {
        out.push_back(k);
        break;
      }
    }
  }
  return out;
}

std::string formatRows(const json& rows, const std::vector<std::string>& columns, const std::string& format) {
  std::ostringstream out;
  if (format == "json") {
    json selected = json::array();
    for (const auto& row : rows) {
      json r = json::object();
      for (const auto& c : columns) r[c] = row.value(c, json());
      selected.push_back(std::move(r));
    }
    out << selected.dump(2) << "\n";
    return out.str();
  }
  if (format == "csv") {
    for (std::size_t c = 0; c < columns.size(); ++c) out << (c ? "," : "") << columns[c];
    out << "\n";
    for (const auto& row : rows) {
      for (std::size_t c = 0; c < columns.size(); ++c)
        out << (c ? "," : "") << report::csvValue(row.value(columns[c], json()));
      out << "\n";
    }
    return out.str();
  }
  std::vector<std::size_t> width(columns.size());
  for (std::size_t c = 0; c < columns.size(); ++c) {
    width[c] = columns[c].size();
    for (const auto& row : rows) width[c] = std::max(width[c], cell(row.value(columns[c], json())).size());
  }
  auto line = [&](auto&& text) {
    for (std::size_t c = 0; c < columns.size(); ++c) {
      const std::string s = text(c);
      out << (c ? "  " : "") << s << std::string(width[c] - s.size(), ' ');
    }
    out << "\n";
  };
  line([&](std::size_t c) { return columns[c]; });
  for (const auto& row : rows) line([&](std::size_t c) { return cell(row.value(columns[c], json())); });
  out << "(" << rows.size() << " row" << (rows.size() == 1 ? "" : "s") << ")\n";
  return out.str();
}

db::ClosureQuery queryOf(const CommandOptions& opt) {
  db::ClosureQuery q;
  q.table = opt.table;
  q.family = opt.family;
  q.workflow = opt.workflowFilter;
  if (opt.runId > 0) q.runId = opt.runId;
  for (const auto& w : opt.where) q.ranges.push_back(parseRange(w));
  return q;
}

}  // namespace

int commandDbQuery(const CommandOptions& opt) {
  auto database = openExisting(databaseOf(opt));
  db::ClosureStore store(database);
  json rows;
  std::vector<std::string> known;
  try {
    if (opt.table == "closure_tables") {
      // The tables node by node, each value with its standard error.
      rows = store.tableNodes(queryOf(opt));
      known = db::ClosureStore::tableNodeColumns();
      std::fputs(formatRows(rows, shownColumns(rows, opt.columns, known), opt.format).c_str(), stdout);
      return 0;
    }
    rows = store.query(queryOf(opt));
    known = store.columns(opt.table);
  } catch (const UsageError&) {
    throw;
  } catch (const Error& e) {
    throw UsageError(e.what());  // an unknown table or column is the user's to fix
  }
  known.insert(known.end(), {"workflow", "stage", "run_key"});
  std::fputs(formatRows(rows, shownColumns(rows, opt.columns, known), opt.format).c_str(), stdout);
  return 0;
}

int commandDbExport(const CommandOptions& opt) {
  auto database = openExisting(databaseOf(opt));
  db::ClosureStore store(database);
  const std::filesystem::path out = opt.output;
  if (out.empty()) throw UsageError("db export: say where, --output FILE.json or --output FOLDER");
  json everything = json::object();
  for (const auto& table : {"closure_points", "force_statistics", "structure_statistics", "rheology"}) {
    db::ClosureQuery q;
    q.table = table;
    q.workflow = opt.workflowFilter;
    everything[table] = store.query(q);
  }
  {
    // Closure tables with their grids parsed, so the export is plain JSON all the way down.
    auto st = database.prepare(
        "SELECT t.id, t.run_id, t.name, t.quantity, t.second_variable, t.solid_fractions_json, t.seconds_json, "
        "t.values_json, t.uncertainties_json, t.filters_json, r.workflow, r.key FROM closure_tables t "
        "JOIN runs r ON r.id = t.run_id WHERE ?1 = '' OR r.workflow = ?1 ORDER BY t.id");
    st.bind(1, opt.workflowFilter);
    everything["closure_tables"] = json::array();
    while (st.step()) {
      everything["closure_tables"].push_back({{"id", st.columnInt64(0)},
                                              {"run_id", st.columnInt64(1)},
                                              {"name", st.columnText(2)},
                                              {"quantity", st.columnText(3)},
                                              {"second_variable", st.columnText(4)},
                                              {"solid_fractions", json::parse(st.columnText(5))},
                                              {"seconds", json::parse(st.columnText(6))},
                                              {"values", json::parse(st.columnText(7))},
                                              {"uncertainties", json::parse(st.columnText(8))},
                                              {"filters", json::parse(st.columnText(9))},
                                              {"workflow", st.columnText(10)},
                                              {"run_key", st.columnText(11)}});
    }
  }
  {
    db::ProvenanceStore provenance(database);
    everything["runs"] = json::array();
    for (const auto& r : provenance.runs(opt.workflowFilter)) {
      everything["runs"].push_back({{"id", r.id},
                                    {"workflow", r.workflow},
                                    {"stage", r.stage},
                                    {"stage_type", r.stageType},
                                    {"impl_version", r.implVersion},
                                    {"key", r.key},
                                    {"status", r.status},
                                    {"params", json::parse(r.paramsJson)},
                                    {"upstream_keys", r.upstreamKeys},
                                    {"code_version", r.codeVersion},
                                    {"code_dirty", r.codeDirty},
                                    {"started_at", r.startedAt},
                                    {"ended_at", r.endedAt}});
    }
  }
  if (out.extension() == ".json") {
    core::writeFileAtomically(out, everything.dump(2) + "\n");
  } else {
    std::filesystem::create_directories(out);
    for (const auto& [table, rows] : everything.items()) {
      if (table == "closure_tables" || table == "runs") {
        core::writeFileAtomically(out / (table + ".json"), rows.dump(2) + "\n");
        continue;
      }
      std::vector<std::string> known = store.columns(table);
      known.insert(known.end(), {"workflow", "stage", "run_key"});
      core::writeFileAtomically(out / (table + ".csv"), formatRows(rows, known, "csv"));
    }
  }
  std::printf(
      "exported %zu closure points, %zu force statistics, %zu structure statistics, %zu closure tables, "
      "%zu rheology rows and %zu runs to %s\n",
      everything["closure_points"].size(), everything["force_statistics"].size(),
      everything["structure_statistics"].size(), everything["closure_tables"].size(), everything["rheology"].size(),
      everything["runs"].size(),
      out.string().c_str());
  return 0;
}

}  // namespace grainbridge::workflows::commands
