#include "db/Statement.hpp"

#include <sqlite3.h>
#include <utility>

#include "core/Error.hpp"
#include "db/BusyError.hpp"

namespace grainbridge::db {

namespace {
// SQLITE_TRANSIENT is a C-style cast macro; spelled out here to stay -Wold-style-cast clean.
// It tells SQLite to copy the bound text, so the caller's string may die right after bind.
const sqlite3_destructor_type kTransient = reinterpret_cast<sqlite3_destructor_type>(static_cast<std::intptr_t>(-1));
}  // namespace

Statement::Statement(sqlite3* connection, sqlite3_stmt* stmt, std::string sql, std::filesystem::path dbPath)
    : connection_(connection), stmt_(stmt), sql_(std::move(sql)), dbPath_(std::move(dbPath)) {
  GB_ASSERT(connection_ != nullptr && stmt_ != nullptr, "Statement needs a connection and a prepared statement");
}

Statement::~Statement() {
  if (stmt_ != nullptr) sqlite3_finalize(stmt_);
}

Statement::Statement(Statement&& other) noexcept
    : connection_(std::exchange(other.connection_, nullptr)),
      stmt_(std::exchange(other.stmt_, nullptr)),
      sql_(std::move(other.sql_)),
      dbPath_(std::move(other.dbPath_)) {}

Statement& Statement::operator=(Statement&& other) noexcept {
  if (this != &other) {
    if (stmt_ != nullptr) sqlite3_finalize(stmt_);
    connection_ = std::exchange(other.connection_, nullptr);
    stmt_ = std::exchange(other.stmt_, nullptr);
    sql_ = std::move(other.sql_);
    dbPath_ = std::move(other.dbPath_);
  }
  return *this;
}

void Statement::checkBind(int rc, int index) const {
  if (rc == SQLITE_OK) return;
  // A wrong index or a bind on a running statement is a bug in our SQL or code, not input.
  GB_ASSERT(rc != SQLITE_RANGE && rc != SQLITE_MISUSE, "bad bind index " + std::to_string(index) + " for SQL: " + sql_);
  throw Error("database " + dbPath_.string() + ": cannot bind parameter " + std::to_string(index) + " of SQL \"" +
              sql_ + "\": " + sqlite3_errstr(rc));
}

void Statement::checkColumn(int index) const {
  GB_ASSERT(stmt_ != nullptr, "use of a moved-from Statement");
  GB_ASSERT(index >= 0 && index < sqlite3_column_count(stmt_),
            "column index " + std::to_string(index) + " out of range for SQL: " + sql_);
}

Statement& Statement::bind(int index, std::int64_t value) {
  checkBind(sqlite3_bind_int64(stmt_, index, value), index);
  return *this;
}

Statement& Statement::bind(int index, double value) {
  checkBind(sqlite3_bind_double(stmt_, index, value), index);
  return *this;
}

Statement& Statement::bind(int index, const std::string& value) {
  checkBind(sqlite3_bind_text64(stmt_, index, value.data(), value.size(), kTransient, SQLITE_UTF8), index);
  return *this;
}

Statement& Statement::bindNull(int index) {
  checkBind(sqlite3_bind_null(stmt_, index), index);
  return *this;
}

Statement& Statement::bindTextOrNull(int index, const std::string& value) {
  return value.empty() ? bindNull(index) : bind(index, value);
}

bool Statement::step() {
  GB_ASSERT(stmt_ != nullptr, "use of a moved-from Statement");
  const int rc = sqlite3_step(stmt_);
  if (rc == SQLITE_ROW) return true;
  if (rc == SQLITE_DONE) return false;
  const std::string message = "database " + dbPath_.string() + ": SQL \"" + sql_ +
                              "\" failed: " + sqlite3_errmsg(connection_) + " (" + sqlite3_errstr(rc) + ")";
  // Rewind now so the statement is reusable after the caller handles the error.
  sqlite3_reset(stmt_);
  if ((rc & 0xFF) == SQLITE_BUSY) throw BusyError(message);
  throw Error(message);
}

void Statement::reset() {
  GB_ASSERT(stmt_ != nullptr, "use of a moved-from Statement");
  // The return code repeats the last step's error, which step() has already reported.
  sqlite3_reset(stmt_);
}

void Statement::clearBindings() {
  GB_ASSERT(stmt_ != nullptr, "use of a moved-from Statement");
  sqlite3_clear_bindings(stmt_);
}

std::int64_t Statement::columnInt64(int index) const {
  checkColumn(index);
  return sqlite3_column_int64(stmt_, index);
}

double Statement::columnDouble(int index) const {
  checkColumn(index);
  return sqlite3_column_double(stmt_, index);
}

std::string Statement::columnText(int index) const {
  checkColumn(index);
  const unsigned char* text = sqlite3_column_text(stmt_, index);
  if (text == nullptr) return {};
  // column_bytes after column_text gives the UTF-8 length, embedded NULs included.
  const int bytes = sqlite3_column_bytes(stmt_, index);
  return std::string(reinterpret_cast<const char*>(text), static_cast<std::size_t>(bytes));
}

bool Statement::columnIsNull(int index) const {
  checkColumn(index);
  return sqlite3_column_type(stmt_, index) == SQLITE_NULL;
}

int Statement::columnCount() const {
  GB_ASSERT(stmt_ != nullptr, "use of a moved-from Statement");
  return sqlite3_column_count(stmt_);
}

std::string Statement::columnName(int index) const {
  checkColumn(index);
  return sqlite3_column_name(stmt_, index);
}

nlohmann::json Statement::columnJson(int index) const {
  checkColumn(index);
  switch (sqlite3_column_type(stmt_, index)) {
    case SQLITE_NULL:
      return nullptr;
    case SQLITE_INTEGER:
      return columnInt64(index);
    case SQLITE_FLOAT:
      return columnDouble(index);
    default:
      return columnText(index);
  }
}

}  // namespace grainbridge::db
