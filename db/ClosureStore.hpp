#pragma once
// The closure database (DESIGN.md "Closures"): closure points, force and structure statistics
// and closure tables. Stages never write the database; they report rows in their manifest
// ("records": {table: [row, ...]}) and the executor inserts them here in the same transaction
// that marks the run done, so a closure value exists exactly when its run completed and its
// provenance (runs, run_inputs, artifacts) is there to follow. Like ProvenanceStore, it opens
// no transaction itself.
#include <cstdint>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "core/LoadedClosureTable.hpp"
#include "core/LoadedRheology.hpp"

namespace grainbridge::db {

class Database;

// A closed range on one numeric column; an absent bound is open.
struct ColumnRange {
  std::string column;
  std::optional<double> lo, hi;
  std::optional<std::string> text{};  // instead of a range: the column equals this text ("species=small")
};

struct ClosureQuery {
  std::string table = "closure_points";  // closure_points | force_statistics | structure_statistics
  std::string family;                    // "" = any
  std::vector<ColumnRange> ranges;
  std::optional<std::int64_t> runId;
  std::string workflow;  // "" = any; else only rows of that workflow's runs
};

class ClosureStore {
 public:
  explicit ClosureStore(Database& db);

  // The tables a stage may report rows for.
  static const std::vector<std::string>& recordTables();

  // Inserts a manifest's "records" object for run `runId`. Every row is an object whose keys
  // are columns of its table (run_id and id are set here). Throws grainbridge::Error naming
  // the table, row and column for an unknown table or column or a value of the wrong type.
  void insertRecords(std::int64_t runId, const nlohmann::json& records);

  // Matching rows as objects (column -> value) plus workflow, stage and run key, by id.
  // Throws Error naming an unknown column in a range.
  nlohmann::json query(const ClosureQuery& query);
  // The closure tables node by node, one row per node: table_id, run_id, name, quantity,
  // second_variable, solid_fraction, second (null for a 1-D table), value, uncertainty (its
  // standard error; null where the table has none), workflow, stage, run_key. `query`'s workflow,
  // run and ranges (over the numeric columns) filter them; its family does not apply.
  nlohmann::json tableNodes(const ClosureQuery& query);
  static const std::vector<std::string>& tableNodeColumns();

  // Table `name` of `quantity` as a continuum run receives it (core::LoadedClosureTable: the
  // table, the run that made it, its content sha256, which is what enters a consuming stage's
  // key, and its friction filter). From the run of `runKey` when given (a table made upstream in
  // the same workflow), else the newest (highest run id). Throws Error listing the tables there
  // are when none matches.
  core::LoadedClosureTable loadTable(const std::string& name, const std::string& quantity,
                                     const std::string& runKey = "");

  // The mu(I) rows (relation mu_of_I, every restitution) of the rheology `name`, as a continuum
  // run receives them: from the run of `runKey` when given, else from the newest run that made
  // rows of that name. Throws Error listing the rheologies there are when none matches.
  core::LoadedRheology loadRheology(const std::string& name, const std::string& runKey = "");

  // Column names of a table, from the schema itself (so no list here can drift from it).
  std::vector<std::string> columns(const std::string& table);

 private:
  void insertClosureTable(std::int64_t runId, const nlohmann::json& row, const std::string& where);

  Database& db_;
};

}  // namespace grainbridge::db
