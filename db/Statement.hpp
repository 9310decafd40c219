#pragma once
// RAII prepared statement. Bind indices are 1-based and column indices 0-based, as in the
// SQLite C API, so SQL text and code read the same way. Failures throw grainbridge::Error
// (BusyError for SQLITE_BUSY) naming the database file and the SQL text; a bad index is a
// programmer error (GB_ASSERT).
#include <cstdint>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

struct sqlite3;
struct sqlite3_stmt;

namespace grainbridge::db {

class Statement {
 public:
  // Called by Database::prepare; `stmt` is owned from here on.
  Statement(sqlite3* connection, sqlite3_stmt* stmt, std::string sql, std::filesystem::path dbPath);
  ~Statement();
  Statement(Statement&& other) noexcept;
  Statement& operator=(Statement&& other) noexcept;
  Statement(const Statement&) = delete;
  Statement& operator=(const Statement&) = delete;

  Statement& bind(int index, std::int64_t value);
  // Without this, bind(i, 5) would be ambiguous between the int64 and double overloads.
  Statement& bind(int index, int value) { return bind(index, static_cast<std::int64_t>(value)); }
  Statement& bind(int index, double value);
  Statement& bind(int index, const std::string& value);
  Statement& bindNull(int index);
  // Binds NULL for an empty string: optional TEXT columns store NULL, not "".
  Statement& bindTextOrNull(int index, const std::string& value);

  // true = a row is available; false = done. Throws on failure.
  bool step();
  // Rewinds so the statement can run again; bindings are kept (SQLite semantics).
  void reset();
  void clearBindings();

  std::int64_t columnInt64(int index) const;
  double columnDouble(int index) const;
  std::string columnText(int index) const;  // "" for NULL
  bool columnIsNull(int index) const;
  int columnCount() const;
  std::string columnName(int index) const;
  // The value as JSON: null, an integer, a real or a string (blobs are not used here).
  nlohmann::json columnJson(int index) const;
  const std::string& sql() const { return sql_; }

 private:
  void checkBind(int rc, int index) const;
  void checkColumn(int index) const;

  sqlite3* connection_ = nullptr;
  sqlite3_stmt* stmt_ = nullptr;
  std::string sql_;
  std::filesystem::path dbPath_;
};

}  // namespace grainbridge::db
