// `grainbridge db query` and `db export`: the closure database as a user reads it, filtered by
// family, state ranges and run, printed as a table, CSV or JSON; and everything in it written
// out for other tools. Values are SI; each row names the run that produced it, and
// `db show RUN` follows that run's provenance chain.
#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "core/Files.hpp"
#include "core/json/Diagnostics.hpp"
#include "core/text/NumberText.hpp"
#include "db/ClosureStore.hpp"
#include "db/ProvenanceStore.hpp"
#include "workflows/commands/Commands.hpp"
#include "workflows/commands/DatabaseSource.hpp"
#include "workflows/report/CsvField.hpp"

namespace grainbridge::workflows::commands {

using nlohmann::json;

namespace {

// How close a stored value must be to a value written in --where to match it, relative to the
// value written. A closure point stores the state measured in the run, which sits beside the round
// state the config asked for: the quickstart's phi 0.3 box (10.9390 mm, 500 grains) holds 0.300004,
// which the report labels "phi 0.3". 0.1 % keeps those and is far finer than the step between any
// two states of the shipped sweeps.
constexpr double kWhereRelativeTolerance = 1e-3;

double whereTolerance(double written) {
  return written == 0.0 ? 1e-12 : kWhereRelativeTolerance * std::abs(written);
}

// Whether a --where value is meant as a number: it starts as one does (a digit, a sign, a point).
// "0.3x" is then a mistyped number, refused, not text; "small" is text.
bool looksNumeric(const std::string& value) {
  const char c = value.front();
  return std::isdigit(static_cast<unsigned char>(c)) != 0 || c == '-' || c == '+' || c == '.';
}

// "solid_fraction=0.1:0.3", "restitution=0.9", "shear_rate=:5"; each bound widened by
// kWhereRelativeTolerance of itself, so `solid_fraction=0.3` and `0.1:0.3` take 0.300004.
// "species=small": a text column equal to the text.
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
  if (colon == std::string::npos && !value.empty() && !looksNumeric(value)) {
    r.text = value;  // a text column (species=small): equality
    return r;
  }
  if (colon == std::string::npos) {
    const auto v = number(value);
    if (!v) throw UsageError("--where \"" + text + "\": no value");
    r.lo = *v - whereTolerance(*v);
    r.hi = *v + whereTolerance(*v);
  } else {
    r.lo = number(value.substr(0, colon));
    r.hi = number(value.substr(colon + 1));
    if (r.lo) *r.lo -= whereTolerance(*r.lo);
    if (r.hi) *r.hi += whereTolerance(*r.hi);
  }
  return r;
}

// A table is for people (six significant digits); CSV and JSON keep every digit.
std::string cell(const json& v) {
  if (v.is_null()) return "";
  return core::humanText(v);
}

// A column named on the command line must exist: the error names the closest one and lists all.
void requireColumn(const std::string& option, const std::string& column, const std::vector<std::string>& known,
                   const std::string& table) {
  if (std::find(known.begin(), known.end(), column) != known.end()) return;
  std::string list;
  for (const auto& k : known) list += (list.empty() ? "" : ", ") + k;
  const auto hint = core::json::closestMatch(column, known);
  throw UsageError(option + ": no column \"" + column + "\" in " + table +
                   (hint.empty() ? "" : " (did you mean \"" + hint + "\"?)") + "; columns: " + list);
}

// A table for people leaves out extra_json (a JSON object per row, hundreds of characters wide)
// unless asked for by --columns; CSV and JSON keep it.
bool leaveOut(const std::string& column, const std::string& format) {
  return format == "table" && column == "extra_json";
}

// Columns to show: the requested ones (checked), else every column that is set in some row.
std::vector<std::string> shownColumns(const json& rows, const std::string& requested,
                                      const std::vector<std::string>& known, const std::string& table,
                                      const std::string& format) {
  std::vector<std::string> out;
  if (!requested.empty()) {
    std::istringstream in(requested);
    for (std::string c; std::getline(in, c, ',');) {
      requireColumn("--columns", c, known, table);
      out.push_back(c);
    }
    return out;
  }
  for (const auto& k : known) {
    if (leaveOut(k, format)) continue;
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

// Nothing matched the --where ranges: say what each ranged column holds without them, so a user
// who wrote 0.35 where the points are at 0.3 sees it.
std::string whereMissHint(db::ClosureStore& store, const db::ClosureQuery& query) {
  db::ClosureQuery unranged = query;
  unranged.ranges.clear();
  const json all = store.query(unranged);
  std::string out = "no row matches --where (values match to " + core::humanText(json(kWhereRelativeTolerance * 100)) +
                    " % of the value written)";
  if (all.empty()) return out + "; nothing is stored for this table and filter\n";
  for (const auto& range : query.ranges) {
    std::vector<double> values;
    for (const auto& row : all) {
      if (row.contains(range.column) && row[range.column].is_number()) values.push_back(row[range.column].get<double>());
    }
    std::sort(values.begin(), values.end());
    values.erase(std::unique(values.begin(), values.end()), values.end());
    out += "; " + range.column + " has ";
    if (values.empty()) {
      out += "no values";
      continue;
    }
    const std::size_t shown = std::min<std::size_t>(values.size(), 8);
    for (std::size_t i = 0; i < shown; ++i) out += (i ? " " : "") + core::humanText(json(values[i]));
    if (values.size() > shown) out += " ... (" + std::to_string(values.size()) + " values)";
  }
  return out + "\n";
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
      const auto columns = shownColumns(rows, opt.columns, known, opt.table, opt.format);
      std::fputs(formatRows(rows, columns, opt.format).c_str(), stdout);
      return 0;
    }
    known = store.columns(opt.table);
    const auto query = queryOf(opt);
    for (const auto& range : query.ranges) requireColumn("--where", range.column, known, opt.table);
    rows = store.query(query);
    if (rows.empty() && !query.ranges.empty()) std::fputs(whereMissHint(store, query).c_str(), stderr);
  } catch (const UsageError&) {
    throw;
  } catch (const Error& e) {
    throw UsageError(e.what());  // an unknown table is the user's to fix
  }
  known.insert(known.end(), {"workflow", "stage", "run_key"});
  const auto columns = shownColumns(rows, opt.columns, known, opt.table, opt.format);
  std::fputs(formatRows(rows, columns, opt.format).c_str(), stdout);
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
